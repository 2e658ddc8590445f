// tabulate_cell: tensor-product Lobatto shapes mapped by the bilinear cell map.
#include "assembly/cell_values.hpp"

#include <Eigen/LU>

#include "basis/lobatto.hpp"
#include "mesh/cell_map.hpp"

namespace hpcontact::assembly {

CellValues tabulate_cell(const space::H1Space& space, int cell, const std::vector<double>& xi,
                         const std::vector<double>& eta) {
  const int p = space.cell_degree(cell);
  const auto table_xi = basis::tabulate_lobatto(p, xi);
  const auto table_eta = basis::tabulate_lobatto(p, eta);
  const auto& shapes = space.cell_shapes(cell);
  const int n_xi = static_cast<int>(xi.size());
  const int n_points = n_xi * static_cast<int>(eta.size());
  const int n_shapes = static_cast<int>(shapes.size());
  const mesh::CellMap map(space.mesh(), cell);

  CellValues out{Eigen::MatrixXd(n_points, 2), Eigen::VectorXd(n_points), Eigen::MatrixXd(n_points, n_shapes),
                 Eigen::MatrixXd(n_points, n_shapes), Eigen::MatrixXd(n_points, n_shapes)};
  for (int b = 0; b < static_cast<int>(eta.size()); ++b) {
    for (int a = 0; a < n_xi; ++a) {
      const int q = a + n_xi * b;
      out.points.row(q) = map.map(xi[a], eta[b]).transpose();
      const Eigen::Matrix2d jacobian = map.jacobian(xi[a], eta[b]);
      out.jacobians(q) = jacobian.determinant();
      // ∇_x φ = DΨ^{-T} ∇_ξ φ
      const Eigen::Matrix2d inverse_transpose = jacobian.inverse().transpose();
      for (int s = 0; s < n_shapes; ++s) {
        const auto& shape = shapes[s];
        const double value_xi = table_xi.values(a, shape.i), value_eta = table_eta.values(b, shape.j);
        const double d_xi = table_xi.derivatives(a, shape.i) * value_eta * shape.sign;
        const double d_eta = value_xi * table_eta.derivatives(b, shape.j) * shape.sign;
        out.values(q, s) = value_xi * value_eta * shape.sign;
        out.grad_x(q, s) = inverse_transpose(0, 0) * d_xi + inverse_transpose(0, 1) * d_eta;
        out.grad_y(q, s) = inverse_transpose(1, 0) * d_xi + inverse_transpose(1, 1) * d_eta;
      }
    }
  }
  return out;
}

std::pair<std::vector<double>, std::vector<double>> edge_reference_points(int local_edge,
                                                                          const std::vector<double>& t) {
  const std::vector<double> minus{-1.0}, plus{1.0};
  switch (local_edge) {
    case 0:
      return {t, minus};
    case 1:
      return {plus, t};
    case 2:
      return {t, plus};
    default:
      return {minus, t};
  }
}

}  // namespace hpcontact::assembly
