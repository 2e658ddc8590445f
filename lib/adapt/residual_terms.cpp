// The shared pieces of the residual estimators: second derivatives, edge traces, flux jumps, the
// sum over T_h.
#include "adapt/residual_terms.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <unordered_map>

#include "assembly/cell_values.hpp"
#include "basis/quadrature.hpp"

namespace hpcontact::adapt {

double cell_diameter(const mesh::Mesh& mesh, int c) {
  double h = 0.0;
  for (int k = 0; k < mesh.cell_size(c); ++k) h = std::max(h, mesh.edge_length(mesh.cell_edge(c, k)));
  return h;
}

double edge_speed(const mesh::Mesh& mesh, int e, double t) {
  return (mesh.edge_point(e, t + kDifferenceStep) - mesh.edge_point(e, t - kDifferenceStep)).norm() /
         (2 * kDifferenceStep);
}

// The Hessian is D J⁻¹, D = ∂(∇_x u_h)/∂ξ and J = ∂x/∂ξ, both by central differences at each
// quadrature point (the 2δ of both cancel).
CellSecondDerivatives cell_second_derivatives(const space::H1Space& space, const assembly::CellField& u, int c) {
  const auto rule = assembly::cell_rule(space, c, 1);
  const int n = rule.points.size();
  assembly::ReferencePoints stencil;
  for (int q = 0; q < n; ++q) {
    const double xi = rule.points.xi[q], eta = rule.points.eta[q];
    for (const auto& [dx, dy] : {std::pair{0.0, 0.0},
                                 {kDifferenceStep, 0.0},
                                 {-kDifferenceStep, 0.0},
                                 {0.0, kDifferenceStep},
                                 {0.0, -kDifferenceStep}})
      stencil.xi.push_back(xi + dx), stencil.eta.push_back(eta + dy);
  }
  const auto values = assembly::tabulate_cell(space, c, stencil);
  const Eigen::MatrixXd a = u.coefficients(c);
  const Eigen::MatrixXd gx = values.grad_x * a, gy = values.grad_y * a;
  CellSecondDerivatives out;
  out.hessians.assign(n, std::vector<Eigen::Matrix2d>(u.components));
  for (int q = 0; q < n; ++q) {
    const int i = 5 * q;
    Eigen::Matrix2d j;
    for (int axis = 0; axis < 2; ++axis)
      j.col(axis) = (values.points.row(i + 1 + 2 * axis) - values.points.row(i + 2 + 2 * axis)).transpose();
    const Eigen::Matrix2d j_inverse = j.inverse();
    for (int k = 0; k < u.components; ++k) {
      Eigen::Matrix2d d;
      for (int axis = 0; axis < 2; ++axis) {
        const int plus = i + 1 + 2 * axis, minus = i + 2 + 2 * axis;
        d.col(axis) << gx(plus, k) - gx(minus, k), gy(plus, k) - gy(minus, k);
      }
      out.hessians[q][k] = d * j_inverse;
    }
    out.points.push_back(values.points.row(i).transpose());
    out.weights.push_back(rule.weights[q] * std::abs(values.jacobians[i]));
  }
  return out;
}

Eigen::MatrixXd EdgeTrace::gradient(int q) const {
  Eigen::MatrixXd g(value.cols(), 2);
  g.col(0) = grad_x.row(q).transpose();
  g.col(1) = grad_y.row(q).transpose();
  return g;
}

EdgeTrace edge_trace(const space::H1Space& space, const assembly::CellField& u, int c, int local,
                     const std::vector<double>& t) {
  const auto values =
      assembly::tabulate_cell(space, c, assembly::edge_reference_points(space.mesh().cell_type(c), local, t));
  const Eigen::MatrixXd a = u.coefficients(c);
  return {values.values * a, values.grad_x * a, values.grad_y * a, values.points};
}

double jump_share(const space::H1Space& space, const assembly::CellField& u, int e, const NormalFlux& flux) {
  const auto& mesh = space.mesh();
  const auto& cells = mesh.edge_cells(e);
  const int p = std::max(space.cell_degree(cells[0]), space.cell_degree(cells[1]));
  const auto& rule = basis::gauss_legendre(p + 2);
  std::array<EdgeTrace, 2> side;
  for (int k = 0; k < 2; ++k) {
    const int local = mesh.local_edge_of(e, k);
    std::vector<double> t = rule.points;  // the edge's own parameter, in the cell's local direction
    if (mesh.edge_sign(cells[k], local) < 0)
      for (double& x : t) x = -x;
    side[k] = edge_trace(space, u, cells[k], local, t);
  }
  double sum = 0.0;
  for (std::size_t q = 0; q < rule.points.size(); ++q) {
    const double t = rule.points[q];
    const mesh::Point tangent =
        (mesh.edge_point(e, t + kDifferenceStep) - mesh.edge_point(e, t - kDifferenceStep)).normalized();
    const mesh::Point normal(tangent.y(), -tangent.x());
    const int row = static_cast<int>(q);
    const Eigen::VectorXd jump =
        flux(cells[0], side[0].gradient(row), normal) - flux(cells[1], side[1].gradient(row), normal);
    sum += rule.weights[q] * edge_speed(mesh, e, t) * jump.squaredNorm();
  }
  return 0.5 * 0.5 * mesh.edge_length(e) / p * sum;
}

ResidualIndicators sum_indicators(const space::H1Space& space, const assembly::CellField& u,
                                  const mesh::ContactBoundary& contact, const ResidualTerms& terms) {
  const auto& mesh = space.mesh();
  std::unordered_map<int, int> trace_edge_of;  // mesh edge → index in contact.edges()
  for (std::size_t k = 0; k < contact.edges().size(); ++k) trace_edge_of[contact.edges()[k].edge] = static_cast<int>(k);
  ResidualIndicators out;
  out.cell.assign(mesh.n_cells(), 0.0);
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const double volume = terms.volume(c);
    out.cell[c] += volume, out.volume += volume;
  }
  for (int e = 0; e < mesh.n_edges(); ++e) {
    const auto& cells = mesh.edge_cells(e);
    if (!mesh.is_boundary_edge(e)) {
      const double share = jump_share(space, u, e, terms.flux);
      out.cell[cells[0]] += share, out.cell[cells[1]] += share, out.jumps += 2 * share;
      continue;
    }
    if (mesh.edge_part(e) == mesh::BoundaryPart::dirichlet) continue;
    const auto found = trace_edge_of.find(e);
    const auto boundary = terms.boundary(e, found == trace_edge_of.end() ? -1 : found->second);
    out.cell[cells[0]] += boundary.flux + boundary.contact;
    out.flux += boundary.flux, out.contact += boundary.contact;
  }
  return out;
}

}  // namespace hpcontact::adapt
