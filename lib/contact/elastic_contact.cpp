// solve_elastic_contact: assemble, condense onto Γ_C, solve the multiplier QP (for Coulomb
// repeatedly, with the friction bound of the last pressure), recover u.
#include "contact/elastic_contact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "assembly/coupling.hpp"
#include "assembly/elastic_system.hpp"
#include "contact/multiplier_constraints.hpp"
#include "contact/multiplier_qp.hpp"
#include "core/error.hpp"
#include "core/timer.hpp"
#include "linalg/sparse_stack.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::contact {

std::string to_string(ElasticContactProblem problem) {
  switch (problem) {
    case ElasticContactProblem::frictionless:
      return "frictionless";
    case ElasticContactProblem::tresca:
      return "tresca";
    default:
      return "coulomb";
  }
}

namespace {

void check_data(const ElasticContactSetup& setup) {
  HPC_VERIFY(setup.operators && setup.boundary_mesh, "elastic contact setup without operators or T_{C,H}");
  if (!setup.gap) throw InputError("elastic contact: the gap g to the obstacle is missing");
  if (setup.problem == ElasticContactProblem::tresca && !setup.threshold)
    throw InputError("Tresca friction: the friction threshold s is missing");
  if (setup.problem == ElasticContactProblem::coulomb && !(setup.friction_coefficient >= 0.0))
    throw InputError(
        fmt::format("Coulomb friction: the friction coefficient F = {} must be >= 0", setup.friction_coefficient));
}

// The constraints of one part of λ: the sign of M_- (normal), or |λ_t| ≤ s of M_s (tangential,
// with s = 1 for Coulomb, whose bounds each fixed-point step sets).
MultiplierConstraints part_constraints(const ElasticContactSetup& setup, const space::MultiplierSpace& multipliers,
                                       bool normal) {
  ContactSetup part;
  part.boundary_mesh = setup.boundary_mesh;
  part.segment_degrees = setup.segment_degrees;
  part.constraint_points = setup.constraint_points;
  part.problem = normal ? ContactProblem::signorini : ContactProblem::friction_s;
  if (!normal)
    part.bound = setup.problem == ElasticContactProblem::tresca ? setup.threshold
                                                                : PointFunction([](const mesh::Point&) { return 1.0; });
  return build_multiplier_constraints(part, multipliers, setup.operators->contact());
}

// The condensed problem: B, its constraints and the obstacle offset, in the nodal basis.
struct CondensedProblem {
  linalg::Coupling coupling;
  MultiplierConstraints constraints;
  Eigen::VectorXd offset;
  int n_normal = 0;       ///< multiplier coefficients of the normal part
  int n_normal_rows = 0;  ///< constraint rows of the normal part
};

// B w: the rows of the coupling (−B_n; B_t) applied to the lift, with B of the extended space.
Eigen::VectorXd coupling_of_lift(const ElasticContactSetup& setup, const space::MultiplierSpace& multipliers,
                                 const linalg::Coupling& to_nodal, const assembly::DirichletLift& lift) {
  auto part = [&](assembly::TraceDirection direction) -> Eigen::VectorXd {
    return to_nodal * lift.times(assembly::assemble_directional_coupling(
                          *lift.extended_vector(), setup.operators->contact(), multipliers, direction));
  };
  Eigen::VectorXd out = -part(assembly::TraceDirection::normal);
  if (setup.problem == ElasticContactProblem::frictionless) return out;
  out.conservativeResize(2 * out.size());
  out.tail(out.size() / 2) = part(assembly::TraceDirection::tangent);
  return out;
}

CondensedProblem condensed_problem(const ElasticContactSetup& setup, const space::MultiplierSpace& multipliers,
                                   const assembly::DirichletLift* lift) {
  const auto& ops = *setup.operators;
  CondensedProblem out;
  auto normal = part_constraints(setup, multipliers, true);
  const linalg::Coupling to_nodal = normal.to_nodal.sparseView();
  // λ_n = σ_nn ≤ 0 pairs with −u·n, so that the gap row (ℓ_i, g − u·n) is ≥ 0 as in (9).
  out.coupling = -(to_nodal * ops.coupling(multipliers, assembly::TraceDirection::normal));
  out.offset = -(normal.to_nodal * assembly::assemble_multiplier_load(ops.contact(), multipliers, setup.gap));
  out.n_normal = multipliers.n_dofs();
  out.n_normal_rows = static_cast<int>(normal.matrix.rows());
  if (setup.problem == ElasticContactProblem::frictionless) {
    out.constraints = std::move(normal);
  } else {
    const auto tangential = part_constraints(setup, multipliers, false);
    out.coupling =
        linalg::stack_rows(out.coupling, to_nodal * ops.coupling(multipliers, assembly::TraceDirection::tangent));
    out.offset.conservativeResize(2 * out.n_normal);
    out.offset.tail(out.n_normal).setZero();
    out.constraints = stack_constraints(normal, tangential);
  }
  // The constraints act on u_0 + w: B u_0 against the offset − B w.
  if (lift) out.offset -= coupling_of_lift(setup, multipliers, to_nodal, *lift);
  return out;
}

// This rank's share of the load of u_0 (for factor.solve_local), and the energy's constant
// (assembly::DirichletLift).
assembly::DirichletLift::LiftedLoad problem_load_share(const ElasticContactSetup& setup,
                                                       const assembly::DirichletLift* lift,
                                                       const assembly::CondensedFactor& factor) {
  const auto& ops = *setup.operators;
  const std::set<mesh::BoundaryPart> neumann{mesh::BoundaryPart::neumann};
  if (!lift)
    return {assembly::assemble_elastic_load(ops.vector_space(), setup.body_force, neumann, setup.traction,
                                            factor.local_rows()),
            0.0};
  const assembly::LocalRows& rows = factor.local_rows();
  const assembly::LocalRows extended_rows = lift->extended_rows(rows);
  const Eigen::VectorXd load = assembly::assemble_elastic_load(*lift->extended_vector(), setup.body_force, neumann,
                                                               setup.traction, extended_rows);
  return lift->lifted_load(assembly::ElasticCellSystem(ops.vector_space(), ops.materials()), load, rows, extended_rows,
                           ops.distribution());
}

// Coulomb: the tangential bounds ±F p at the tangential constraint points, p = −σ_nn there (the
// normal and tangential parts share the multiplier space, so C_t maps normal coefficients too).
void set_coulomb_bounds(double coefficient, const CondensedProblem& problem, const Eigen::VectorXd& lambda,
                        MultiplierConstraints& constraints) {
  const Eigen::Index rows_t = constraints.matrix.rows() - problem.n_normal_rows;
  const Eigen::MatrixXd c_t = constraints.matrix.bottomRightCorner(rows_t, problem.n_normal);
  const Eigen::VectorXd bound = coefficient * (-(c_t * lambda.head(problem.n_normal))).cwiseMax(0.0);
  constraints.upper.tail(rows_t) = bound;
  constraints.lower.tail(rows_t) = -bound;
}

// The relative change max |Δλ| / max |λ| between fixed-point iterates.
double relative_change(const Eigen::VectorXd& next, const Eigen::VectorXd& previous) {
  const double scale = std::max(next.lpNorm<Eigen::Infinity>(), std::numeric_limits<double>::min());
  return (next - previous).lpNorm<Eigen::Infinity>() / scale;
}

// The multiplier: one QP, or for Coulomb the fixed point s_{k+1} = F p(λ_k) from s_0 = 0.
MultiplierQpSolution solve_multiplier(const ElasticContactSetup& setup, CondensedProblem& problem,
                                      const Eigen::MatrixXd& s, const Eigen::VectorXd& d,
                                      std::vector<double>& changes) {
  if (setup.problem != ElasticContactProblem::coulomb)
    return solve_multiplier_qp(s, d, problem.constraints, setup.qp, setup.interior_point);
  Eigen::VectorXd previous = Eigen::VectorXd::Zero(d.size());
  for (int k = 1; k <= setup.max_fixed_point_iterations; ++k) {
    set_coulomb_bounds(setup.friction_coefficient, problem, previous, problem.constraints);
    auto qp = solve_multiplier_qp(s, d, problem.constraints, setup.qp, setup.interior_point);
    changes.push_back(relative_change(qp.x, previous));
    previous = qp.x;
    if (changes.back() <= setup.fixed_point_tolerance) return qp;
  }
  throw NumericalError(fmt::format(
      "Coulomb friction (F = {}): the fixed point on the Tresca problem did not converge in {} iterations "
      "(relative changes of λ, first and last: {:.3e}, {:.3e}; tolerance {:.1e}); a smaller F, or a finer "
      "T_{{C,H}} where the pressure varies, may help",
      setup.friction_coefficient, changes.size(), changes.front(), changes.back(), setup.fixed_point_tolerance));
}

}  // namespace

ElasticContactSolution solve_elastic_contact(const ElasticContactSetup& setup) {
  check_data(setup);
  const auto& ops = *setup.operators;
  ElasticContactSolution out;

  // 1. The load, B (normal part, then tangential) and the constraints in the nodal basis.
  Stopwatch assembly_clock;
  const space::MultiplierSpace multipliers(*setup.boundary_mesh, setup.segment_degrees);
  if (setup.dirichlet[0] || setup.dirichlet[1])
    out.lift = std::make_shared<assembly::DirichletLift>(ops.vector_space(), setup.dirichlet, ops.lift_space());
  CondensedProblem problem = condensed_problem(setup, multipliers, out.lift.get());
  out.seconds.assembly = assembly_clock.seconds();

  // 2. Condensation onto the trace (ordered last in the factor): S = B A⁻¹ Bᵀ, d.
  Stopwatch factorization_clock;
  const assembly::CondensedFactor& factor = ops.stiffness_factor();
  out.seconds.factorization = factorization_clock.seconds();
  // Distributed, the vectors of the displacement space are held at each rank's own cells' dofs,
  // the load as the ranks' shares (this rank's own cells, on the lift's extended space with
  // Dirichlet data): none of the global length (u stays at the rank's dofs).
  Stopwatch load_clock;
  const auto [load_share, energy_offset] = problem_load_share(setup, out.lift.get(), factor);
  out.seconds.assembly += load_clock.seconds();
  Stopwatch condensation_clock;
  const Eigen::VectorXd u_free = factor.solve_local(load_share).col(0);
  const Eigen::MatrixXd s = factor.schur_complement(problem.coupling);
  const Eigen::VectorXd b_u_free = factor.multiply_local(problem.coupling, u_free).col(0);
  const Eigen::VectorXd d = b_u_free - problem.offset;
  out.seconds.condensation = condensation_clock.seconds();
  out.n_trace = factor.n_trailing();

  // 3. The multiplier.
  Stopwatch qp_clock;
  auto qp = solve_multiplier(setup, problem, s, d, out.fixed_point_changes);
  out.seconds.qp = qp_clock.seconds();
  if (ops.log()) ops.log()->record("contact QP (" + qp.report.method + ")", s.rows(), s.cols(), out.seconds.qp);

  // 4. Recovery: u = A⁻¹(F − Bᵀλ), the gap, the tractions, the energy.
  Stopwatch recovery_clock;
  out.lambda = std::move(qp.x);
  out.qp = std::move(qp.report);
  const Eigen::VectorXd u =
      factor.solve_local(Eigen::VectorXd(load_share - factor.transpose_share(problem.coupling, out.lambda).col(0)))
          .col(0);
  out.gap = factor.multiply_local(problem.coupling, u).col(0) - problem.offset;
  out.gap_scale = b_u_free.lpNorm<Eigen::Infinity>() + problem.offset.lpNorm<Eigen::Infinity>() +
                  (s * out.lambda).lpNorm<Eigen::Infinity>();
  const Eigen::VectorXd legendre = problem.constraints.to_nodal.transpose() * out.lambda;
  out.pressure = -legendre.head(problem.n_normal);
  out.shear = setup.problem == ElasticContactProblem::frictionless ? Eigen::VectorXd::Zero(problem.n_normal)
                                                                   : Eigen::VectorXd(-legendre.tail(problem.n_normal));
  out.energy = 0.5 * factor.quadratic_form_local(u) - factor.dot_local(load_share, u) + energy_offset;
  out.u = u;
  out.u_rows = factor.local_rows();
  out.n_dofs = factor.size();
  out.n_normal = problem.n_normal;
  out.constraint_matrix = std::move(problem.constraints.matrix);
  out.lower = std::move(problem.constraints.lower);
  out.upper = std::move(problem.constraints.upper);
  out.seconds.recovery = recovery_clock.seconds();
  return out;
}

}  // namespace hpcontact::contact
