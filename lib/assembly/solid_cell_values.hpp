// The local shapes of a cell of S^p(T_h) tabulated at a Gauss rule mapped to the cell (tensor on
// hexahedra, collapsed on tetrahedra): values, physical gradients, quadrature weights times |det J|
// and the mapped points, what element matrices, loads and error integrals on solid meshes are made of.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "space/solid_space.hpp"

namespace hpcontact::assembly {

/// Shapes are the cell's unsigned local shapes in the order of SolidH1Space::cell_shapes; points
/// are the n³ tensor Gauss points (first axis fastest) or the n³ points of
/// basis::collapsed_tetrahedron_rule.
struct SolidCellValues {
  Eigen::MatrixXd values;                    ///< shape (n_shapes, n_points)
  std::array<Eigen::MatrixXd, 3> gradients;  ///< ∂/∂x_d of each shape, each shape (n_shapes, n_points)
  Eigen::VectorXd weights;                   ///< shape (n_points): w_q |det J(ξ_q)|
  std::vector<mesh::SolidPoint> points;      ///< the mapped points x(ξ_q)
};

/// @param points_per_axis n ≥ 1 Gauss points per axis (exact to degree 2n − 1 on affine hexahedra,
/// 2n − 3 on tetrahedra).
SolidCellValues solid_cell_values(const space::SolidH1Space& space, int cell, int points_per_axis);

/// The rule the solid assembly uses on a cell of degree p: p + 2 points per axis (exact for the
/// mass and stiffness of affine cells, with a margin for trilinear maps; on tetrahedra exact to
/// degree 2p + 1).
inline int solid_points_per_axis(int degree) { return degree + 2; }

}  // namespace hpcontact::assembly
