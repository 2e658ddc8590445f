// Tabulation of the local shape functions of a cell (values and physical gradients) at points of
// its reference cell, and the reference point sets (quadrature, edges, grids) they are taken at;
// shared by assembly, evaluation and error norms.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "mesh/reference_cell.hpp"
#include "space/h1_space.hpp"

namespace hpcontact::assembly {

/// Points of a reference cell: point q is (xi[q], eta[q]).
struct ReferencePoints {
  std::vector<double> xi, eta;
  int size() const { return static_cast<int>(xi.size()); }
};

/// The tensor grid ξ_a × η_b, point index q = a + n_ξ·b.
ReferencePoints tensor_points(const std::vector<double>& xi, const std::vector<double>& eta);

/// The points with local edge parameters t on `local_edge` (mesh/reference_cell.hpp).
ReferencePoints edge_reference_points(mesh::CellType type, int local_edge, const std::vector<double>& t);

/// A quadrature rule on a reference cell: n × n tensor Gauss points on the square, the n²-point
/// collapsed rule on the triangle (basis/quadrature.hpp). Both exact to degree 2n − 2 at least.
struct CellQuadrature {
  ReferencePoints points;
  std::vector<double> weights;
};
CellQuadrature cell_quadrature(mesh::CellType type, int n);

/// Shapes of one cell at reference points. Every matrix has shape (n_points, n_shapes), column
/// s = space.cell_shapes(cell)[s]; the sign of each shape (edge orientation) is already applied.
struct CellValues {
  Eigen::MatrixXd points;     ///< (n_points, 2) physical coordinates Ψ_T(ξ_q, η_q)
  Eigen::VectorXd jacobians;  ///< (n_points) det DΨ_T
  Eigen::MatrixXd values;     ///< φ_s
  Eigen::MatrixXd grad_x;     ///< ∂φ_s/∂x
  Eigen::MatrixXd grad_y;     ///< ∂φ_s/∂y
};

CellValues tabulate_cell(const space::H1Space& space, int cell, const ReferencePoints& points);

/// Gauss points per direction used for the volume integrals of a cell of degree p: p + 2.
/// Mass (degree 2p+1 per variable with the bilinear Jacobian) needs p + 1; the extra point
/// covers the rational stiffness integrand of non-parallelogram cells and smooth data. A curved
/// (blended) cell's Jacobian carries its curves' degree: 6 more points keep the quadrature error
/// below the discretization error down to 1e-10 (measured on the annulus study).
inline int cell_quadrature_points(int degree, bool curved = false) { return degree + 2 + (curved ? 6 : 0); }

/// The volume rule of cell `cell`: cell_quadrature_points of its degree and curvature, plus
/// `extra` points per direction (smooth data, error norms).
CellQuadrature cell_rule(const space::H1Space& space, int cell, int extra = 0);

}  // namespace hpcontact::assembly
