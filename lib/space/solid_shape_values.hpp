// The values of a solid cell's local shapes at one reference point, for either kind of cell: what
// point values of functions and the couplings on Γ_C evaluate.
#pragma once

#include <Eigen/Core>

#include "basis/tetrahedron_basis.hpp"
#include "space/solid_space.hpp"

namespace hpcontact::space {

/// The mode of basis::TetrahedronShapes that a local shape of a tetrahedron names.
const basis::SolidShapeValue& tetrahedron_mode(const basis::TetrahedronShapes& all, const SolidShape& shape);

/// The unsigned local shapes of `cell` at the reference point ξ (hexahedron [-1, 1]³ or the
/// reference tetrahedron), shape (space.shape_count(cell)), in SolidH1Space::cell_shapes order.
Eigen::VectorXd local_shape_values(const SolidH1Space& space, int cell, const Eigen::Vector3d& xi);

}  // namespace hpcontact::space
