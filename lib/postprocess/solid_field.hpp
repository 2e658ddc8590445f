// A finite element function on a hexahedral mesh evaluated in a cell, and its VTU: the cells cut
// into p_T³ linear hexahedra through an equispaced lattice (exact at the lattice points).
#pragma once

#include <Eigen/Core>

#include "io/vtu_writer.hpp"
#include "space/solid_space.hpp"

namespace hpcontact::postprocess {

/// u_h(x(ξ)) for u_h = Σ_i coefficients(i) φ_i (zero on Γ_D), at the local point ξ of `cell`.
double solid_value(const space::SolidH1Space& space, const Eigen::VectorXd& coefficients, int cell,
                   const Eigen::Vector3d& xi);

/// u_h as the point field "u" on every cell's lattice of (p_T + 1)³ points, VTK_HEXAHEDRON cells,
/// the cell degree p_T per VTK cell (no points shared between cells).
io::VtuGrid solid_vtu_grid(const space::SolidH1Space& space, const Eigen::VectorXd& coefficients);

}  // namespace hpcontact::postprocess
