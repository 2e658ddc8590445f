// Finite element functions on a solid mesh evaluated in a cell (scalar, or the three components of
// a displacement), and their VTU: the cells cut into p_T³ linear hexahedra or tetrahedra through an
// equispaced lattice (exact at the lattice points).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>

#include "io/vtu_writer.hpp"
#include "space/solid_space.hpp"
#include "space/solid_vector_space.hpp"

namespace hpcontact::postprocess {

/// u_h(x(ξ)) for u_h = Σ_i coefficients(i) φ_i (zero on Γ_D), at the local point ξ of `cell`.
double solid_value(const space::SolidH1Space& space, const Eigen::VectorXd& coefficients, int cell,
                   const Eigen::Vector3d& xi);
/// The displacement u_h(x(ξ)) of coefficients on the vector space.
Eigen::Vector3d solid_displacement(const space::SolidVectorSpace& space, const Eigen::VectorXd& coefficients, int cell,
                                   const Eigen::Vector3d& xi);

/// A point field with `components` values at a cell's local point ξ.
struct SolidPointField {
  std::string name;
  int components = 1;
  std::function<Eigen::VectorXd(int cell, const Eigen::Vector3d& xi)> evaluate;
};

/// The field on every cell's lattice of (p_T + 1)³ points (hexahedra, VTK_HEXAHEDRON cells) or
/// (p_T + 1)(p_T + 2)(p_T + 3)/6 points (tetrahedra, p_T³ VTK_TETRA cells of Freudenthal's
/// subdivision), the cell degree p_T per VTK cell (no points shared between cells).
io::VtuGrid solid_vtu_grid(const space::SolidH1Space& space, const SolidPointField& field);

}  // namespace hpcontact::postprocess
