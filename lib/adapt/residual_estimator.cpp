// residual_indicators: the volume, jump, flux and contact terms of the scalar contact problems.
#include "adapt/residual_estimator.hpp"

#include <algorithm>
#include <cmath>

#include "adapt/residual_terms.hpp"
#include "assembly/cell_field.hpp"
#include "basis/quadrature.hpp"
#include "core/error.hpp"
#include "mesh/contact_boundary.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::adapt {
namespace {

double positive(double x) { return std::max(x, 0.0); }

// (h_T/p_T)² ‖f + Δu_h‖²_T.
double volume_term(const space::H1Space& space, const assembly::CellField& u, int c, const contact::PointFunction& f) {
  const auto at = cell_second_derivatives(space, u, c);
  double sum = 0.0;
  for (std::size_t q = 0; q < at.points.size(); ++q) {
    const double residual = (f ? f(at.points[q]) : 0.0) + at.hessians[q][0].trace();
    sum += at.weights[q] * residual * residual;
  }
  const double scale = cell_diameter(space.mesh(), c) / space.cell_degree(c);
  return scale * scale * sum;
}

// What a boundary edge adds to its cell: the flux mismatch on Γ_N and Γ_C, and on Γ_C the
// problem's contact terms (header).
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
    const double flux = trace.grad_x(q, 0) * normal.x() + trace.grad_y(q, 0) * normal.y();
    double mismatch = flux - (setup.traction ? setup.traction(x, normal) : 0.0);
    if (trace_edge >= 0) {
      const double lambda =
          multipliers.evaluate(solution.lambda_legendre, contact.arc_length_at_parameter(trace_edge, t));
      const double value = trace.value(q, 0);
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
  const ResidualTerms terms{.volume = [&](int c) { return volume_term(space, u, c, setup.f); },
                            .flux = [](int, const Eigen::MatrixXd& gradient,
                                       const mesh::Point& normal) { return Eigen::VectorXd(gradient * normal); },
                            .boundary =
                                [&](int e, int trace_edge) {
                                  return boundary_terms(setup, solution, space, u, contact, multipliers, e, trace_edge);
                                }};
  return sum_indicators(space, u, contact, terms);
}

}  // namespace hpcontact::adapt
