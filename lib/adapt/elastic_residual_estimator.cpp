// elastic_residual_indicators: the volume, jump, traction and contact terms of elastic contact.
#include "adapt/elastic_residual_estimator.hpp"

#include <algorithm>
#include <cmath>

#include "adapt/residual_terms.hpp"
#include "assembly/cell_field.hpp"
#include "assembly/coupling.hpp"
#include "basis/quadrature.hpp"
#include "core/error.hpp"
#include "mesh/contact_boundary.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::adapt {
namespace {

double positive(double x) { return std::max(x, 0.0); }

// σ(u) of a cell's material from ∇u (row k = ∇u_k), in the plane.
Eigen::Matrix2d stress(const assembly::Material& m, const Eigen::MatrixXd& gradient) {
  const Eigen::Matrix2d strain = 0.5 * (gradient + gradient.transpose());
  return m.lambda * strain.trace() * Eigen::Matrix2d::Identity() + 2.0 * m.mu * strain;
}

// (h_T/p_T)² ‖f + div σ(u_h)‖²_T / 2μ_T. With constant Lamé parameters on T,
// (div σ)_i = (λ + μ) ∂_i div u + μ Δu_i.
double volume_term(const space::H1Space& space, const assembly::CellField& u, int c, const assembly::Material& m,
                   const assembly::VectorFunction& f) {
  const auto at = cell_second_derivatives(space, u, c);
  double sum = 0.0;
  for (std::size_t q = 0; q < at.points.size(); ++q) {
    const auto& h = at.hessians[q];
    Eigen::Vector2d residual = f ? f(at.points[q]) : Eigen::Vector2d::Zero();
    for (int i = 0; i < 2; ++i) residual[i] += (m.lambda + m.mu) * (h[0](i, 0) + h[1](i, 1)) + m.mu * h[i].trace();
    sum += at.weights[q] * residual.squaredNorm();
  }
  const double scale = cell_diameter(space.mesh(), c) / space.cell_degree(c);
  return scale * scale * sum / (2.0 * m.mu);
}

// What a boundary edge adds to its cell (header). `trace_edge` ≥ 0 on Γ_C.
BoundaryTerms boundary_terms(const contact::ElasticContactSetup& setup, const contact::ElasticContactSolution& solution,
                             const assembly::CellField& u, const space::MultiplierSpace& multipliers,
                             const std::array<bool, space::kComponents>& free, int e, int trace_edge) {
  const auto& ops = *setup.operators;
  const auto& space = ops.space();
  const auto& mesh = space.mesh();
  const auto& contact = ops.contact();
  const int c = mesh.edge_cells(e)[0], local = mesh.local_edge_of(e, 0), p = space.cell_degree(c);
  const auto& material = ops.materials()[static_cast<std::size_t>(c)];
  const double stiffness = 2.0 * material.mu;
  const auto& rule = basis::gauss_legendre(p + 3);
  const auto trace = edge_trace(space, u, c, local, rule.points);
  const double h = mesh.edge_length(e);
  const bool friction = setup.problem == contact::ElasticContactProblem::tresca ||
                        setup.problem == contact::ElasticContactProblem::coulomb;
  BoundaryTerms terms;
  double gap_violation = 0.0, bound_violation = 0.0;
  for (std::size_t q = 0; q < rule.points.size(); ++q) {
    const int row = static_cast<int>(q);
    const double t = rule.points[q];
    const double weight = rule.weights[q] * edge_speed(mesh, e, mesh.edge_sign(c, local) * t);
    const mesh::Point x = trace.points.row(row).transpose(), normal = mesh.boundary_normal(e, t);
    Eigen::Vector2d mismatch = stress(material, trace.gradient(row)) * normal;
    if (setup.traction && mesh.edge_part(e) == mesh::BoundaryPart::neumann) mismatch -= setup.traction(x, normal);
    if (trace_edge >= 0) {
      const double s = contact.arc_length_at_parameter(trace_edge, t);
      const double pressure = multipliers.evaluate(solution.pressure, s);
      const double shear = multipliers.evaluate(solution.shear, s);
      const mesh::Point n = assembly::trace_direction(contact, s, assembly::TraceDirection::normal);
      const mesh::Point tangent = assembly::trace_direction(contact, s, assembly::TraceDirection::tangent);
      const Eigen::Vector2d displacement = trace.value.row(row).transpose();
      const double u_n = displacement.dot(n), u_t = displacement.dot(tangent), g = setup.gap(x);
      mismatch -= -pressure * n + shear * tangent;
      if (setup.problem == contact::ElasticContactProblem::tied) {
        gap_violation += weight * ((u_n - g) * (u_n - g) + u_t * u_t);
      } else {
        gap_violation += weight * positive(u_n - g) * positive(u_n - g);
        bound_violation += weight * positive(-pressure) * positive(-pressure);
        terms.contact += weight * positive(pressure) * positive(g - u_n);
      }
      if (friction) {
        const double bound = setup.problem == contact::ElasticContactProblem::tresca
                                 ? setup.threshold(x)
                                 : setup.friction_coefficient * positive(pressure);
        bound_violation += weight * std::pow(positive(std::abs(shear) - bound), 2);
        terms.contact += weight * positive(bound * std::abs(u_t) + shear * u_t);
      }
    }
    for (int k = 0; k < space::kComponents; ++k)
      if (free[k]) terms.flux += weight * mismatch[k] * mismatch[k];
  }
  terms.flux *= h / p / stiffness;
  terms.contact += stiffness * p / h * gap_violation + h / p * bound_violation / stiffness;
  return terms;
}

}  // namespace

ResidualIndicators elastic_residual_indicators(const contact::ElasticContactSetup& setup,
                                               const contact::ElasticContactSolution& solution,
                                               const std::array<std::vector<char>, space::kComponents>& fixed) {
  HPC_VERIFY(setup.operators, "elastic_residual_indicators without operators");
  const auto& ops = *setup.operators;
  const auto& space = ops.space();
  HPC_VERIFY(space.whole(), "the residual estimator runs on a whole (serial) space");
  const auto u = assembly::vector_field(ops.vector_space(), solution.u, solution.u_rows, solution.lift);
  const auto& contact = ops.contact();
  const space::MultiplierSpace multipliers(*setup.boundary_mesh, setup.segment_degrees);
  const auto& materials = ops.materials();
  const ResidualTerms terms{
      .volume =
          [&](int c) { return volume_term(space, u, c, materials[static_cast<std::size_t>(c)], setup.body_force); },
      // σ(u_h)n / √(2μ_T): the jump of the scaled traction is the term of the header.
      .flux =
          [&](int cell, const Eigen::MatrixXd& gradient, const mesh::Point& normal) {
            const auto& m = materials[static_cast<std::size_t>(cell)];
            return Eigen::VectorXd(stress(m, gradient) * normal / std::sqrt(2.0 * m.mu));
          },
      .boundary =
          [&](int e, int trace_edge) {
            std::array<bool, space::kComponents> free{};
            for (int k = 0; k < space::kComponents; ++k)
              free[k] = fixed[k].empty() || !fixed[k][static_cast<std::size_t>(e)];
            return boundary_terms(setup, solution, u, multipliers, free, e, trace_edge);
          }};
  return sum_indicators(space, u, contact, terms);
}

}  // namespace hpcontact::adapt
