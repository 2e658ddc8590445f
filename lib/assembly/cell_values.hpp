// Tabulation of the local shape functions of a cell (values and physical gradients) at the points
// of a tensor grid on the reference square, shared by assembly, evaluation and error norms.
#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "space/h1_space.hpp"

namespace hpcontact::assembly {

/// Shapes of one cell at the tensor grid ξ_a × η_b (point index q = a + n_ξ·b).
/// Every matrix has shape (n_points, n_shapes), column s = space.cell_shapes(cell)[s];
/// the sign of each shape (edge orientation) is already applied.
struct CellValues {
  Eigen::MatrixXd points;     ///< (n_points, 2) physical coordinates Ψ_T(ξ_a, η_b)
  Eigen::VectorXd jacobians;  ///< (n_points) det DΨ_T
  Eigen::MatrixXd values;     ///< φ_s
  Eigen::MatrixXd grad_x;     ///< ∂φ_s/∂x
  Eigen::MatrixXd grad_y;     ///< ∂φ_s/∂y
};

CellValues tabulate_cell(const space::H1Space& space, int cell, const std::vector<double>& xi,
                         const std::vector<double>& eta);

/// Reference grid (ξ list, η list) of the points with local edge parameters t on `local_edge`
/// (see QuadMesh for the local edge numbering and directions).
std::pair<std::vector<double>, std::vector<double>> edge_reference_points(int local_edge, const std::vector<double>& t);

/// Gauss points per direction used for the volume integrals of a cell of degree p: p + 2.
/// Mass (degree 2p+1 per variable with the bilinear Jacobian) needs p + 1; the extra point
/// covers the rational stiffness integrand of non-parallelogram cells and smooth data. A curved
/// (blended) cell's Jacobian carries its curves' degree: 6 more points keep the quadrature error
/// below the discretization error down to 1e-10 (measured on the annulus study).
inline int cell_quadrature_points(int degree, bool curved = false) { return degree + 2 + (curved ? 6 : 0); }

}  // namespace hpcontact::assembly
