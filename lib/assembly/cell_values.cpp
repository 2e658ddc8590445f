// tabulate_cell: Lobatto tensor shapes on quadrilaterals, the triangle basis on triangles, mapped
// by the cell map; reference point sets.
#include "assembly/cell_values.hpp"

#include <Eigen/LU>

#include "basis/lobatto.hpp"
#include "basis/quadrature.hpp"
#include "basis/triangle_basis.hpp"
#include "mesh/cell_map.hpp"

namespace hpcontact::assembly {
namespace {

// Reference values and gradients (value, ∂/∂ξ, ∂/∂η) of every shape of the cell at point q.
void reference_shapes(std::span<const space::LocalShape> shapes, mesh::CellType type, int p, double xi, double eta,
                      Eigen::VectorXd& lobatto_xi, Eigen::VectorXd& lobatto_dxi, Eigen::VectorXd& lobatto_eta,
                      Eigen::VectorXd& lobatto_deta, std::vector<basis::ShapeValue>& out) {
  out.resize(shapes.size());
  if (type == mesh::CellType::quadrilateral) {
    basis::lobatto_values(p, xi, lobatto_xi, lobatto_dxi);
    basis::lobatto_values(p, eta, lobatto_eta, lobatto_deta);
    for (std::size_t s = 0; s < shapes.size(); ++s) {
      const int i = shapes[s].i, j = shapes[s].j;
      out[s] = {lobatto_xi(i) * lobatto_eta(j), lobatto_dxi(i) * lobatto_eta(j), lobatto_xi(i) * lobatto_deta(j)};
    }
    return;
  }
  const basis::TriangleShapes triangle(p, xi, eta);
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    const auto& shape = shapes[s];
    switch (shape.role) {
      case space::ShapeRole::vertex:
        out[s] = triangle.vertex(shape.entity);
        break;
      case space::ShapeRole::edge:
        out[s] = triangle.edge(shape.entity, shape.i);
        break;
      case space::ShapeRole::interior:
        out[s] = triangle.bubble(shape.i, shape.j);
        break;
    }
  }
}

}  // namespace

ReferencePoints tensor_points(const std::vector<double>& xi, const std::vector<double>& eta) {
  ReferencePoints out;
  for (double y : eta)
    for (double x : xi) {
      out.xi.push_back(x);
      out.eta.push_back(y);
    }
  return out;
}

ReferencePoints edge_reference_points(mesh::CellType type, int local_edge, const std::vector<double>& t) {
  ReferencePoints out;
  for (double parameter : t) {
    const Eigen::Vector2d point = mesh::local_edge_point(type, local_edge, parameter);
    out.xi.push_back(point.x());
    out.eta.push_back(point.y());
  }
  return out;
}

CellQuadrature cell_quadrature(mesh::CellType type, int n) {
  if (type == mesh::CellType::triangle) {
    const auto& rule = basis::collapsed_triangle_rule(n);
    return {{rule.xi, rule.eta}, rule.weights};
  }
  const auto& line = basis::gauss_legendre(n);
  CellQuadrature out{tensor_points(line.points, line.points), {}};
  for (std::size_t b = 0; b < line.points.size(); ++b)
    for (std::size_t a = 0; a < line.points.size(); ++a) out.weights.push_back(line.weights[a] * line.weights[b]);
  return out;
}

CellQuadrature cell_rule(const space::H1Space& space, int cell, int extra) {
  return cell_quadrature(
      space.mesh().cell_type(cell),
      cell_quadrature_points(space.cell_degree(cell), space.mesh().cell_geometry(cell) != nullptr) + extra);
}

CellValues tabulate_cell(const space::H1Space& space, int cell, const ReferencePoints& points) {
  const int p = space.cell_degree(cell);
  const auto& shapes = space.cell_shapes(cell);
  const int n_points = points.size();
  const int n_shapes = static_cast<int>(shapes.size());
  const mesh::CellMap map(space.mesh(), cell);
  Eigen::VectorXd lobatto_xi(p + 1), lobatto_dxi(p + 1), lobatto_eta(p + 1), lobatto_deta(p + 1);
  std::vector<basis::ShapeValue> reference;

  CellValues out{Eigen::MatrixXd(n_points, 2), Eigen::VectorXd(n_points), Eigen::MatrixXd(n_points, n_shapes),
                 Eigen::MatrixXd(n_points, n_shapes), Eigen::MatrixXd(n_points, n_shapes)};
  for (int q = 0; q < n_points; ++q) {
    const double xi = points.xi[q], eta = points.eta[q];
    out.points.row(q) = map.map(xi, eta).transpose();
    const Eigen::Matrix2d jacobian = map.jacobian(xi, eta);
    out.jacobians(q) = jacobian.determinant();
    // ∇_x φ = DΨ^{-T} ∇_ξ φ
    const Eigen::Matrix2d inverse_transpose = jacobian.inverse().transpose();
    reference_shapes(shapes, map.type(), p, xi, eta, lobatto_xi, lobatto_dxi, lobatto_eta, lobatto_deta, reference);
    for (int s = 0; s < n_shapes; ++s) {
      const double sign = shapes[s].sign;
      const double d_xi = reference[s].d_xi * sign, d_eta = reference[s].d_eta * sign;
      out.values(q, s) = reference[s].value * sign;
      out.grad_x(q, s) = inverse_transpose(0, 0) * d_xi + inverse_transpose(0, 1) * d_eta;
      out.grad_y(q, s) = inverse_transpose(1, 0) * d_xi + inverse_transpose(1, 1) * d_eta;
    }
  }
  return out;
}

}  // namespace hpcontact::assembly
