// solve_contact: assemble, condense onto Γ_C in a nodal multiplier basis, solve the box QP,
// recover u.
#include "contact/contact_problem.hpp"

#include <fmt/format.h>

#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

#include "assembly/coupling.hpp"
#include "assembly/poisson_assembly.hpp"
#include "basis/lobatto.hpp"
#include "basis/quadrature.hpp"
#include "core/error.hpp"
#include "core/timer.hpp"
#include "core/operator_log.hpp"
#include "mesh/contact_boundary.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::contact {

std::vector<double> constraint_points(int q) {
  HPC_VERIFY(q >= 1, "at least one constraint point");
  if (q == 1) return {0.0};
  std::vector<double> points(q);
  for (int k = 0; k < q; ++k) points[k] = -std::cos(std::numbers::pi * k / (q - 1));
  return points;
}

int segment_constraint_points(ContactProblem problem, int pc, std::optional<int> requested) {
  // For M_- and M_1 with p_C ≤ 1 the sign and box conditions at the nodal points are exact.
  if (problem != ContactProblem::friction_s && pc <= 1) return pc + 1;
  const int q = requested.value_or(pc + 1);
  if (q < pc + 1)
    throw InputError(fmt::format("{} constraint points per segment are fewer than p_C + 1 = {} "
                                 "(Remark 3 needs at least p_C + 1)", q, pc + 1));
  return q;
}

ContactSolution solve_contact(const ContactSetup& setup) {
  HPC_VERIFY(setup.mesh && setup.boundary_mesh, "contact setup without meshes");
  const bool signorini = setup.problem == ContactProblem::signorini;
  if (!setup.f) throw InputError("contact problem: the volume load f is missing");
  if (signorini && !setup.obstacle) throw InputError("Signorini problem: the obstacle g is missing");
  if (!signorini && !setup.bound) throw InputError("friction problem: the friction bound s is missing");

  Stopwatch assembly_clock;
  std::unique_ptr<operators::PrimalOperators> own_primal;
  const operators::PrimalOperators& primal =
      operators::shared_or_own(setup.primal, *setup.mesh, setup.cell_degrees, own_primal);
  OperatorLog* log = primal.log();
  const auto& space = primal.space();
  const auto& contact = primal.contact();
  const space::MultiplierSpace multipliers(*setup.boundary_mesh, setup.segment_degrees);
  auto assemble_load = [&] {
    Eigen::VectorXd load = assembly::assemble_volume_load(space, setup.f);
    if (setup.traction)
      load += assembly::assemble_boundary_load(
          space, {mesh::BoundaryPart::neumann, mesh::BoundaryPart::contact}, setup.traction);
    return load;
  };
  // F is shared with the other problems on `primal` when the setup names its data (load_key).
  Eigen::VectorXd own_load;
  if (setup.load_key.empty()) {
    Stopwatch load_clock;
    own_load = assemble_load();
    if (log) log->record("F", own_load.size(), 1, load_clock.seconds());
  }
  const Eigen::VectorXd& load =
      setup.load_key.empty() ? own_load : primal.derived_vector("F", setup.load_key, assemble_load);
  const bool weighted = setup.problem == ContactProblem::friction;
  const std::string coupling_name = weighted ? "B^s" : "B";
  const Eigen::SparseMatrix<double>& coupling_legendre =
      primal.coupling(multipliers, weighted ? setup.bound : assembly::BoundaryFunction{}, coupling_name);

  // Legendre → Lagrange at the nodal points, segment by segment: c_nodal = V c_legendre with
  // V_ik = P_k(τ_i), so the nodal basis functions are ℓ = V⁻ᵀ P and B_nodal = V⁻ᵀ B_legendre.
  const int n = multipliers.n_dofs();
  Eigen::MatrixXd to_nodal = Eigen::MatrixXd::Zero(n, n);  // block diagonal V⁻ᵀ
  ContactSolution out;
  // Constraint rows of each segment: C_k (q × (p_C + 1)) and the bounds at its points.
  struct SegmentConstraints {
    Eigen::MatrixXd rows;
    std::vector<double> s, lower, upper;
  };
  std::vector<SegmentConstraints> segments(multipliers.n_segments());
  int n_rows = 0;
  bool bounds_only = true;
  for (int k = 0; k < multipliers.n_segments(); ++k) {
    const int pc = multipliers.segment_degree(k), first = multipliers.first_dof(k);
    const auto nodes = constraint_points(pc + 1);
    Eigen::MatrixXd v(pc + 1, pc + 1);
    for (int i = 0; i <= pc; ++i) v.row(i) = basis::legendre_values(pc, nodes[i]).transpose();
    const Eigen::MatrixXd v_inverse = v.inverse();
    to_nodal.block(first, first, pc + 1, pc + 1) = v_inverse.transpose();
    const int q = segment_constraint_points(setup.problem, pc, setup.constraint_points);
    out.constraint_points.push_back(q);
    auto& rows = segments[k];
    const auto tau = constraint_points(q);
    rows.rows.resize(q, pc + 1);
    // ℓ_i(τ_j) = Σ_m P_m(τ_j) (V⁻¹)_mi.
    for (int j = 0; j < q; ++j) rows.rows.row(j) = basis::legendre_values(pc, tau[j]).transpose() * v_inverse;
    if (q == pc + 1) rows.rows.setIdentity();  // the nodal points: exactly the identity
    else bounds_only = false;
    const double a = setup.boundary_mesh->segment_begin(k), b = setup.boundary_mesh->segment_end(k);
    // (13) keeps λ = 0 only on segments outside supp s (a closed set: s vanishing at single
    // points, like (1-x)² at x = 1, does not remove them).
    bool meets_support = false;
    if (setup.problem == ContactProblem::friction)
      for (double t : basis::gauss_legendre(12).points)
        meets_support = meets_support || setup.bound(contact.point_at(a + 0.5 * (b - a) * (t + 1.0))) > 0.0;
    for (int j = 0; j < q; ++j) {
      const double s = a + 0.5 * (b - a) * (tau[j] + 1.0);
      rows.s.push_back(s);
      if (signorini) {
        rows.lower.push_back(-std::numeric_limits<double>::infinity());
        rows.upper.push_back(0.0);
        continue;
      }
      const double bound = setup.bound(contact.point_at(s));
      if (!(bound >= 0.0))
        throw InputError(fmt::format("friction bound s = {} at x = {}: s must be >= 0 (and finite)", bound,
                                     contact.point_at(s).x()));
      // (13): |λ| ≤ 1 on supp s, λ = 0 off it; (15): |λ| ≤ s.
      const double limit = setup.problem == ContactProblem::friction ? (meets_support ? 1.0 : 0.0) : bound;
      rows.lower.push_back(-limit);
      rows.upper.push_back(limit);
    }
    n_rows += q;
  }
  out.constraint_matrix = Eigen::MatrixXd::Zero(n_rows, n);
  out.lower.resize(n_rows);
  out.upper.resize(n_rows);
  for (int k = 0, row = 0; k < multipliers.n_segments(); ++k) {
    const auto& rows = segments[k];
    const auto q = rows.rows.rows();
    out.constraint_matrix.block(row, multipliers.first_dof(k), q, rows.rows.cols()) = rows.rows;
    for (Eigen::Index j = 0; j < q; ++j, ++row) {
      out.lower(row) = rows.lower[j];
      out.upper(row) = rows.upper[j];
      out.constraint_s.push_back(rows.s[j]);
    }
  }
  const Eigen::SparseMatrix<double> to_nodal_sparse = to_nodal.sparseView();
  const Eigen::SparseMatrix<double> coupling = (to_nodal_sparse * coupling_legendre).pruned();
  Eigen::VectorXd gap_offset = Eigen::VectorXd::Zero(n);
  if (signorini) {
    Stopwatch obstacle_clock;
    gap_offset = to_nodal * assembly::assemble_multiplier_load(contact, multipliers, setup.obstacle);
    if (log) log->record("g", n, 1, obstacle_clock.seconds());
  }

  // Condensation onto the Γ_C trace: the trace dofs ordered last in the factorization, so that
  // S = B K⁻¹ Bᵀ is dense algebra on the trailing block of the factor (condensed_factor.hpp, sparse_cholesky.hpp).
  out.seconds.assembly = assembly_clock.seconds();
  Stopwatch factorization_clock;
  const assembly::CondensedFactor& k_factor = primal.stiffness_factor();
  out.seconds.factorization = factorization_clock.seconds();
  Stopwatch condensation_clock;
  const Eigen::VectorXd u_free = k_factor.solve(load);
  // S depends on the coupling alone (the nodal basis follows from the multiplier space's
  // layout, which the coupling's key holds): problems sharing B share S.
  const Eigen::MatrixXd& s =
      primal.derived_matrix("S", operators::PrimalOperators::coupling_key(multipliers, coupling_name),
                            [&] { return Eigen::MatrixXd(k_factor.schur_complement(coupling)); });
  const Eigen::VectorXd d = coupling * u_free - gap_offset;
  out.seconds.condensation = condensation_clock.seconds();
  out.n_trace = k_factor.n_trailing();

  Stopwatch qp_clock;
  // Bounds on the coefficients: the active-set method, which ends in a few steps with an exact
  // active set. Should it stall (strongly singular S, e.g. a multiplier mesh much finer than the
  // trace space), the interior-point method takes over on the same problem (C = I).
  bool use_interior_point = !bounds_only;
  std::string fallback_reason;
  if (bounds_only) {
    try {
      auto result = solve_box_qp(s, d, out.lower, out.upper, setup.qp);
      out.lambda = result.x;
      out.qp = {result.method, result.converged, result.kkt_residual, result.newton_steps,
                result.proximal_steps, std::move(result.log), ""};
    } catch (const NumericalError& error) {
      use_interior_point = true;
      fallback_reason = error.what();
    }
  }
  if (use_interior_point) {
    try {
      auto result = solve_inequality_qp(s, d, out.constraint_matrix, out.lower, out.upper, setup.interior_point);
      out.lambda = result.x;
      out.constraint_multiplier = result.y;
      out.qp = {"interior-point", result.converged, result.kkt_residual, result.iterations, 0,
                std::move(result.log), fallback_reason};
    } catch (const NumericalError& error) {
      throw NumericalError(fallback_reason.empty() ? std::string(error.what())
                                                   : fallback_reason + "; then " + error.what());
    }
  }
  out.seconds.qp = qp_clock.seconds();
  if (log) log->record("contact QP (" + out.qp.method + ")", s.rows(), s.cols(), out.seconds.qp);
  Stopwatch recovery_clock;
  out.lambda_legendre = to_nodal.transpose() * out.lambda;  // V⁻¹ c_nodal
  const Eigen::VectorXd reduced_load = load - coupling.transpose() * out.lambda;
  out.u = k_factor.solve(reduced_load);
  out.gap = coupling * out.u - gap_offset;
  if (!use_interior_point) out.constraint_multiplier = out.gap;  // C = I: stationarity y = d − S λ = gap
  out.gap_scale = (coupling * u_free).lpNorm<Eigen::Infinity>() + gap_offset.lpNorm<Eigen::Infinity>() +
                  (s * out.lambda).lpNorm<Eigen::Infinity>();
  // uᵀ K u from the factor's eliminated blocks: K itself is never assembled.
  out.energy = 0.5 * k_factor.quadratic_form(out.u) - load.dot(out.u);
  out.seconds.recovery = recovery_clock.seconds();
  return out;
}

}  // namespace hpcontact::contact
