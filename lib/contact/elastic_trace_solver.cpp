// solve_on_trace: assemble every body's coupling rows and load, condense them onto the
// multiplier, solve the multiplier QP (for Coulomb repeatedly, with the friction bound of the last
// pressure), recover each body's u.
#include "contact/elastic_trace_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <set>

#include "assembly/elastic_system.hpp"
#include "contact/multiplier_constraints.hpp"
#include "contact/multiplier_qp.hpp"
#include "core/error.hpp"
#include "core/timer.hpp"
#include "linalg/sparse_stack.hpp"

namespace hpcontact::contact {

namespace {

// The constraints of one part of λ: the sign of M_- (normal), or |λ_t| ≤ s of M_s (tangential,
// with s = 1 for Coulomb, whose bounds each fixed-point step sets); none for tied contact.
MultiplierConstraints part_constraints(const ElasticContactSetup& setup, const space::MultiplierSpace& multipliers,
                                       bool normal) {
  ContactSetup part;
  part.boundary_mesh = setup.boundary_mesh;
  part.segment_degrees = setup.segment_degrees;
  part.family = setup.family;
  part.constraint_points = setup.constraint_points;
  part.problem = normal ? ContactProblem::signorini : ContactProblem::friction_s;
  const bool tied = setup.problem == ElasticContactProblem::tied;
  // Tied contact bounds nothing: the coefficients themselves (no constraint points) are free.
  if (tied) part.constraint_points.clear();
  if (!normal)
    part.bound = setup.problem == ElasticContactProblem::tresca ? setup.threshold
                                                                : PointFunction([](const mesh::Point&) { return 1.0; });
  MultiplierConstraints constraints = build_multiplier_constraints(part, multipliers, setup.operators->contact());
  if (tied) {
    constraints.lower.setConstant(-std::numeric_limits<double>::infinity());
    constraints.upper.setConstant(std::numeric_limits<double>::infinity());
  }
  return constraints;
}

// The condensed problem: each body's rows C_k, the constraints and the offset, in the nodal basis.
struct CondensedProblem {
  std::vector<linalg::Coupling> couplings;  ///< per body
  MultiplierConstraints constraints;
  Eigen::VectorXd offset;
  int n_normal = 0;       ///< multiplier coefficients of the normal part (in the family's basis)
  int n_normal_rows = 0;  ///< constraint rows of the normal part
};

// C = sign · (−B_n; B_t) of one body on `space` (B_n alone without friction), in the nodal basis:
// λ_n = σ_nn ≤ 0 pairs with −u·n, so that the gap row (ℓ_i, g − u·n) is ≥ 0 as in (9).
linalg::Coupling body_rows(const TraceBody& body, const space::VectorSpace& space,
                           const space::MultiplierSpace& multipliers, const linalg::Coupling& to_nodal, bool friction) {
  linalg::Coupling rows = -(to_nodal * body.coupling(space, multipliers, assembly::TraceDirection::normal));
  if (friction)
    rows = linalg::stack_rows(rows, to_nodal * body.coupling(space, multipliers, assembly::TraceDirection::tangent));
  return body.sign * rows;
}

CondensedProblem condensed_problem(const ElasticContactSetup& setup, const space::MultiplierSpace& multipliers,
                                   const std::function<double(double)>& gap_of_arc,
                                   const std::vector<TraceBody>& bodies,
                                   const std::vector<std::shared_ptr<const assembly::DirichletLift>>& lifts) {
  CondensedProblem out;
  const bool friction = setup.problem != ElasticContactProblem::frictionless;
  auto normal = part_constraints(setup, multipliers, true);
  const linalg::Coupling to_nodal = normal.to_nodal.sparseView();
  out.n_normal = static_cast<int>(normal.to_nodal.rows());
  out.n_normal_rows = static_cast<int>(normal.matrix.rows());
  out.offset =
      -(normal.to_nodal * assembly::assemble_multiplier_load(setup.operators->contact(), multipliers, gap_of_arc));
  if (friction) {
    out.offset.conservativeResize(2 * out.n_normal);
    out.offset.tail(out.n_normal).setZero();
    out.constraints = stack_constraints(normal, part_constraints(setup, multipliers, false));
  } else {
    out.constraints = std::move(normal);
  }
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    out.couplings.push_back(
        body_rows(bodies[k], bodies[k].body.operators->vector_space(), multipliers, to_nodal, friction));
    // The constraints act on u_0 + w: C u_0 against the offset − C w, with C of the extended space.
    if (lifts[k])
      out.offset -=
          lifts[k]->times(body_rows(bodies[k], *lifts[k]->extended_vector(), multipliers, to_nodal, friction));
  }
  return out;
}

// This rank's share of the load of u_0 (for factor.solve_local), and the energy's constant
// (assembly::DirichletLift).
assembly::DirichletLift::LiftedLoad load_share(const ElasticBody& body, const assembly::DirichletLift* lift,
                                               const assembly::CondensedFactor& factor) {
  const auto& ops = *body.operators;
  const std::set<mesh::BoundaryPart> neumann{mesh::BoundaryPart::neumann};
  if (!lift)
    return {assembly::assemble_elastic_load(ops.vector_space(), body.body_force, neumann, body.traction,
                                            factor.local_rows()),
            0.0};
  const assembly::LocalRows& rows = factor.local_rows();
  const assembly::LocalRows extended_rows = lift->extended_rows(rows);
  const Eigen::VectorXd load =
      assembly::assemble_elastic_load(*lift->extended_vector(), body.body_force, neumann, body.traction, extended_rows);
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

// What each body contributes to the condensed problem before the multiplier is known.
struct BodyCondensation {
  const assembly::CondensedFactor* factor = nullptr;
  assembly::DirichletLift::LiftedLoad load;
};

// The Dirichlet lift of each body with Dirichlet data (null for the others).
std::vector<std::shared_ptr<const assembly::DirichletLift>> body_lifts(const std::vector<TraceBody>& bodies) {
  std::vector<std::shared_ptr<const assembly::DirichletLift>> lifts;
  for (const auto& body : bodies) {
    const auto& ops = *body.body.operators;
    lifts.push_back(
        body.body.dirichlet[0] || body.body.dirichlet[1]
            ? std::make_shared<assembly::DirichletLift>(ops.vector_space(), body.body.dirichlet, ops.lift_space())
            : nullptr);
  }
  return lifts;
}

// Condensation onto the trace (ordered last in each factor): S = Σ C_k A_k⁻¹ C_kᵀ and Σ C_k A_k⁻¹ F_k
// into `s` and `b_u_free`. Distributed, the vectors of a displacement space are held at each rank's
// own cells' dofs, the load as the ranks' shares: none of the global length.
std::vector<BodyCondensation> condense_bodies(const std::vector<TraceBody>& bodies,
                                              const std::vector<std::shared_ptr<const assembly::DirichletLift>>& lifts,
                                              const CondensedProblem& problem, Eigen::MatrixXd& s,
                                              Eigen::VectorXd& b_u_free, ElasticContactSolution& contact) {
  const auto n_rows = static_cast<Eigen::Index>(problem.offset.size());
  s = Eigen::MatrixXd::Zero(n_rows, n_rows);
  b_u_free = Eigen::VectorXd::Zero(n_rows);
  std::vector<BodyCondensation> condensed(bodies.size());
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    Stopwatch factorization_clock;
    condensed[k].factor = &bodies[k].body.operators->stiffness_factor();
    contact.seconds.factorization += factorization_clock.seconds();
    const auto& factor = *condensed[k].factor;
    Stopwatch load_clock;
    condensed[k].load = load_share(bodies[k].body, lifts[k].get(), factor);
    contact.seconds.assembly += load_clock.seconds();
    Stopwatch condensation_clock;
    const Eigen::VectorXd u_free = factor.solve_local(condensed[k].load.load).col(0);
    s += factor.schur_complement(problem.couplings[k]);
    b_u_free += factor.multiply_local(problem.couplings[k], u_free).col(0);
    contact.seconds.condensation += condensation_clock.seconds();
    contact.n_trace += factor.n_trailing();
  }
  return condensed;
}

// Recovery of each body, u_k = A_k⁻¹(F_k − C_kᵀλ), with its energy; the gap Σ C_k u_k − offset.
std::vector<BodyDisplacement> recover_bodies(const std::vector<BodyCondensation>& condensed,
                                             const std::vector<std::shared_ptr<const assembly::DirichletLift>>& lifts,
                                             const CondensedProblem& problem, ElasticContactSolution& contact) {
  std::vector<BodyDisplacement> bodies;
  contact.gap = -problem.offset;
  for (std::size_t k = 0; k < condensed.size(); ++k) {
    const auto& factor = *condensed[k].factor;
    const Eigen::VectorXd& share = condensed[k].load.load;
    BodyDisplacement body;
    body.u =
        factor.solve_local(Eigen::VectorXd(share - factor.transpose_share(problem.couplings[k], contact.lambda).col(0)))
            .col(0);
    contact.gap += factor.multiply_local(problem.couplings[k], body.u).col(0);
    body.energy =
        0.5 * factor.quadratic_form_local(body.u) - factor.dot_local(share, body.u) + condensed[k].load.energy_offset;
    body.u_rows = factor.local_rows();
    body.n_dofs = factor.size();
    body.lift = lifts[k];
    contact.energy += body.energy;
    bodies.push_back(std::move(body));
  }
  return bodies;
}

}  // namespace

TraceBody body_on_own_traces(const ElasticContactSetup& setup) {
  const auto& ops = *setup.operators;
  TraceBody body{{&ops, setup.body_force, setup.traction, setup.dirichlet}, 1.0, {}};
  body.coupling = [&ops](const space::VectorSpace& space, const space::MultiplierSpace& multipliers,
                         assembly::TraceDirection direction) {
    // The body's own space: the operators keep its coupling for the next problem.
    if (&space == &ops.vector_space()) return ops.coupling(multipliers, direction);
    return assembly::assemble_directional_coupling(space, ops.contact(), multipliers, direction);
  };
  return body;
}

TraceSolve solve_on_trace(const ElasticContactSetup& setup, const std::function<double(double)>& gap_of_arc,
                          const std::vector<TraceBody>& bodies) {
  HPC_VERIFY(setup.operators && setup.boundary_mesh && !bodies.empty(), "trace solve without operators or bodies");
  if (setup.problem == ElasticContactProblem::tresca && !setup.threshold)
    throw InputError("Tresca friction: the friction threshold s is missing");
  if (setup.problem == ElasticContactProblem::coulomb && !(setup.friction_coefficient >= 0.0))
    throw InputError(
        fmt::format("Coulomb friction: the friction coefficient F = {} must be >= 0", setup.friction_coefficient));
  TraceSolve out;
  auto& contact = out.contact;

  // 1. The lifts, each body's C_k, the constraints and the offset in the nodal basis.
  Stopwatch assembly_clock;
  const space::MultiplierSpace multipliers(*setup.boundary_mesh, setup.segment_degrees);
  const auto lifts = body_lifts(bodies);
  CondensedProblem problem = condensed_problem(setup, multipliers, gap_of_arc, bodies, lifts);
  contact.seconds.assembly = assembly_clock.seconds();

  // 2. Condensation onto the trace: S, d.
  Eigen::MatrixXd s;
  Eigen::VectorXd b_u_free;
  const auto condensed = condense_bodies(bodies, lifts, problem, s, b_u_free, contact);
  const Eigen::VectorXd d = b_u_free - problem.offset;

  // 3. The multiplier.
  Stopwatch qp_clock;
  auto qp = solve_multiplier(setup, problem, s, d, contact.fixed_point_changes);
  contact.seconds.qp = qp_clock.seconds();
  if (auto* log = setup.operators->log())
    log->record("contact QP (" + qp.report.method + ")", s.rows(), s.cols(), contact.seconds.qp);

  // 4. Recovery: each u_k, the gap, the tractions, the energy.
  Stopwatch recovery_clock;
  contact.lambda = std::move(qp.x);
  contact.qp = std::move(qp.report);
  out.bodies = recover_bodies(condensed, lifts, problem, contact);
  contact.gap_scale = b_u_free.lpNorm<Eigen::Infinity>() + problem.offset.lpNorm<Eigen::Infinity>() +
                      (s * contact.lambda).lpNorm<Eigen::Infinity>();
  const Eigen::VectorXd legendre = problem.constraints.to_nodal.transpose() * contact.lambda;
  const int n_legendre = multipliers.n_dofs();
  contact.pressure = -legendre.head(n_legendre);
  contact.shear = setup.problem == ElasticContactProblem::frictionless ? Eigen::VectorXd::Zero(n_legendre)
                                                                       : Eigen::VectorXd(-legendre.tail(n_legendre));
  contact.u = out.bodies.front().u;
  contact.u_rows = out.bodies.front().u_rows;
  contact.n_dofs = out.bodies.front().n_dofs;
  contact.lift = out.bodies.front().lift;
  contact.n_normal = problem.n_normal;
  contact.constraint_matrix = std::move(problem.constraints.matrix);
  contact.lower = std::move(problem.constraints.lower);
  contact.upper = std::move(problem.constraints.upper);
  contact.seconds.recovery = recovery_clock.seconds();
  return out;
}

}  // namespace hpcontact::contact
