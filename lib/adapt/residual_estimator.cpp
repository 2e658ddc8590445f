// residual_indicators: the volume, jump, flux and contact terms of the scalar contact problems.
#include "adapt/residual_estimator.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "assembly/cell_field.hpp"
#include "assembly/cell_values.hpp"
#include "basis/quadrature.hpp"
#include "core/error.hpp"
#include "mesh/contact_boundary.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::adapt {
namespace {

constexpr double kStep = 1e-5;  // of the central differences (header)

double positive(double x) { return std::max(x, 0.0); }

double cell_diameter(const mesh::Mesh& mesh, int c) {
  double h = 0.0;
  for (int k = 0; k < mesh.cell_size(c); ++k) h = std::max(h, mesh.edge_length(mesh.cell_edge(c, k)));
  return h;
}

// (h_T/p_T)² ‖f + Δu_h‖²_T, with Δu_h = tr(D J⁻¹), D = ∂(∇_x u_h)/∂ξ and J = ∂x/∂ξ both by
// central differences at each quadrature point.
double volume_term(const space::H1Space& space, const assembly::CellField& u, int c, const contact::PointFunction& f) {
  const auto rule = assembly::cell_rule(space, c, 1);
  const int n = rule.points.size();
  assembly::ReferencePoints stencil;
  for (int q = 0; q < n; ++q) {
    const double xi = rule.points.xi[q], eta = rule.points.eta[q];
    for (const auto& [dx, dy] : {std::pair{0.0, 0.0}, {kStep, 0.0}, {-kStep, 0.0}, {0.0, kStep}, {0.0, -kStep}})
      stencil.xi.push_back(xi + dx), stencil.eta.push_back(eta + dy);
  }
  const auto values = assembly::tabulate_cell(space, c, stencil);
  const Eigen::VectorXd a = u.coefficients(c).col(0);
  const Eigen::VectorXd gx = values.grad_x * a, gy = values.grad_y * a;
  double sum = 0.0;
  for (int q = 0; q < n; ++q) {
    const int i = 5 * q;
    Eigen::Matrix2d d, j;
    for (int axis = 0; axis < 2; ++axis) {
      const int plus = i + 1 + 2 * axis, minus = i + 2 + 2 * axis;
      d.col(axis) << gx[plus] - gx[minus], gy[plus] - gy[minus];
      j.col(axis) = (values.points.row(plus) - values.points.row(minus)).transpose();
    }
    const Eigen::Matrix2d hessian = d * j.inverse();  // (the 2δ of both cancel)
    const mesh::Point x = values.points.row(i).transpose();
    const double residual = (f ? f(x) : 0.0) + hessian.trace();
    sum += rule.weights[q] * std::abs(values.jacobians[i]) * residual * residual;
  }
  const double scale = cell_diameter(space.mesh(), c) / space.cell_degree(c);
  return scale * scale * sum;
}

// u_h and ∂u_h/∂x, ∂u_h/∂y on local edge `local` of cell c at local parameters t.
struct EdgeTrace {
  Eigen::VectorXd value, grad_x, grad_y;
  Eigen::MatrixXd points;
};
EdgeTrace edge_trace(const space::H1Space& space, const assembly::CellField& u, int c, int local,
                     const std::vector<double>& t) {
  const auto values =
      assembly::tabulate_cell(space, c, assembly::edge_reference_points(space.mesh().cell_type(c), local, t));
  const Eigen::VectorXd a = u.coefficients(c).col(0);
  return {values.values * a, values.grad_x * a, values.grad_y * a, values.points};
}

// |dx/dt| of edge e at its parameter t (either direction: the speed is the same).
double edge_speed(const mesh::Mesh& mesh, int e, double t) {
  return (mesh.edge_point(e, t + kStep) - mesh.edge_point(e, t - kStep)).norm() / (2 * kStep);
}

// ½ (h_E/p_E) ‖[∂_n u_h]‖²_E, the share of each of the edge's two cells.
double jump_share(const space::H1Space& space, const assembly::CellField& u, int e) {
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
    const double t = rule.points[q], speed = edge_speed(mesh, e, t);
    const mesh::Point tangent = (mesh.edge_point(e, t + kStep) - mesh.edge_point(e, t - kStep)).normalized();
    const mesh::Point normal(tangent.y(), -tangent.x());
    const double jump =
        (side[0].grad_x[q] - side[1].grad_x[q]) * normal.x() + (side[0].grad_y[q] - side[1].grad_y[q]) * normal.y();
    sum += rule.weights[q] * speed * jump * jump;
  }
  return 0.5 * 0.5 * mesh.edge_length(e) / p * sum;
}

// What a boundary edge adds to its cell: the flux mismatch on Γ_N and Γ_C, and on Γ_C the
// problem's contact terms (header).
struct BoundaryTerms {
  double flux = 0.0, contact = 0.0;
};
BoundaryTerms boundary_terms(const contact::ContactSetup& setup, const contact::ContactSolution& solution,
                             const space::H1Space& space, const assembly::CellField& u,
                             const mesh::ContactBoundary& contact, const space::MultiplierSpace& multipliers, int e,
                             int trace_edge) {
  const auto& mesh = space.mesh();
  const int c = mesh.edge_cells(e)[0], local = mesh.local_edge_of(e, 0), p = space.cell_degree(c);
  const auto& rule = basis::gauss_legendre(p + 3);
  const auto trace = edge_trace(space, u, c, local, rule.points);
  const double h = mesh.edge_length(e);
  BoundaryTerms terms;
  double gap_violation = 0.0, bound_violation = 0.0;
  for (std::size_t q = 0; q < rule.points.size(); ++q) {
    const double t = rule.points[q];
    const double weight = rule.weights[q] * edge_speed(mesh, e, mesh.edge_sign(c, local) * t);
    const mesh::Point x = trace.points.row(q).transpose(), normal = mesh.boundary_normal(e, t);
    const double flux = trace.grad_x[q] * normal.x() + trace.grad_y[q] * normal.y();
    double mismatch = flux - (setup.traction ? setup.traction(x, normal) : 0.0);
    if (trace_edge >= 0) {
      const double lambda =
          multipliers.evaluate(solution.lambda_legendre, contact.arc_length_at_parameter(trace_edge, t));
      const double value = trace.value[q];
      switch (setup.problem) {
        case contact::ContactProblem::signorini: {
          const double gap = value - setup.obstacle(x);
          mismatch += lambda;
          gap_violation += weight * positive(-gap) * positive(-gap);
          bound_violation += weight * positive(lambda) * positive(lambda);
          terms.contact += weight * positive(-lambda) * positive(gap);
          break;
        }
        case contact::ContactProblem::friction_s: {
          const double s = setup.bound(x);
          mismatch += lambda;
          bound_violation += weight * std::pow(positive(std::abs(lambda) - s), 2);
          terms.contact += weight * positive(s * std::abs(value) - lambda * value);
          break;
        }
        case contact::ContactProblem::friction: {
          const double s = setup.bound(x);
          mismatch += s * lambda;
          bound_violation += weight * std::pow(s * positive(std::abs(lambda) - 1.0), 2);
          terms.contact += weight * s * positive(std::abs(value) - lambda * value);
          break;
        }
      }
    }
    terms.flux += weight * mismatch * mismatch;
  }
  terms.flux *= h / p;
  terms.contact += p / h * gap_violation + h / p * bound_violation;
  return terms;
}

}  // namespace

ResidualIndicators residual_indicators(const contact::ContactSetup& setup, const contact::ContactSolution& solution,
                                       const space::H1Space& space) {
  HPC_VERIFY(space.whole(), "the residual estimator runs on a whole (serial) space");
  const auto& mesh = space.mesh();
  const auto u = assembly::scalar_field(space, solution.u, solution.u_rows, solution.lift);
  const mesh::ContactBoundary contact(mesh);
  const space::MultiplierSpace multipliers(*setup.boundary_mesh, setup.segment_degrees);
  std::unordered_map<int, int> trace_edge_of;  // mesh edge → index in contact.edges()
  for (std::size_t k = 0; k < contact.edges().size(); ++k) trace_edge_of[contact.edges()[k].edge] = static_cast<int>(k);

  ResidualIndicators out;
  out.cell.assign(mesh.n_cells(), 0.0);
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const double volume = volume_term(space, u, c, setup.f);
    out.cell[c] += volume, out.volume += volume;
  }
  for (int e = 0; e < mesh.n_edges(); ++e) {
    const auto& cells = mesh.edge_cells(e);
    if (!mesh.is_boundary_edge(e)) {
      const double share = jump_share(space, u, e);
      out.cell[cells[0]] += share, out.cell[cells[1]] += share, out.jumps += 2 * share;
      continue;
    }
    const auto part = mesh.edge_part(e);
    if (part == mesh::BoundaryPart::dirichlet) continue;
    const auto found = trace_edge_of.find(e);
    const auto terms = boundary_terms(setup, solution, space, u, contact, multipliers, e,
                                      found == trace_edge_of.end() ? -1 : found->second);
    out.cell[cells[0]] += terms.flux + terms.contact;
    out.flux += terms.flux, out.contact += terms.contact;
  }
  return out;
}

}  // namespace hpcontact::adapt
