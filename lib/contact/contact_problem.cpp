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
#include "contact/multiplier_constraints.hpp"
#include "contact/multiplier_qp.hpp"
#include "core/error.hpp"
#include "core/operator_log.hpp"
#include "core/timer.hpp"
#include "mesh/contact_boundary.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::contact {

std::vector<double> constraint_points(int q) { return basis::chebyshev_lobatto_points(q); }

int segment_constraint_points(ContactProblem problem, int pc, std::optional<int> requested) {
  // For M_- and M_1 with p_C ≤ 1 the sign and box conditions at the nodal points are exact.
  if (problem != ContactProblem::friction_s && pc <= 1) return pc + 1;
  const int q = requested.value_or(pc + 1);
  if (q < pc + 1)
    throw InputError(
        fmt::format("{} constraint points per segment are fewer than p_C + 1 = {} "
                    "(Remark 3 needs at least p_C + 1)",
                    q, pc + 1));
  return q;
}

std::optional<int> requested_constraint_points(const std::vector<int>& per_zone,
                                               const mesh::BoundaryMesh& boundary_mesh, int segment) {
  if (per_zone.empty()) return std::nullopt;
  if (per_zone.size() == 1) return per_zone.front();
  const auto zones = boundary_mesh.zones().size();
  if (per_zone.size() != zones)
    throw InputError(
        fmt::format("{} constraint point counts given for the {} zones of T_C,H: give one, or one per zone",
                    per_zone.size(), zones));
  return per_zone[static_cast<std::size_t>(boundary_mesh.zone_of_segment(segment))];
}

namespace {

void check_data(const ContactSetup& setup) {
  HPC_VERIFY((setup.mesh || setup.primal) && setup.boundary_mesh, "contact setup without meshes");
  if (!setup.f) throw InputError("contact problem: the volume load f is missing");
  if (setup.problem == ContactProblem::signorini && !setup.obstacle)
    throw InputError("Signorini problem: the obstacle g is missing");
  if (setup.problem != ContactProblem::signorini && !setup.bound)
    throw InputError("friction problem: the friction bound s is missing");
}

// F on `space` as `target` asks (whole, or this rank's share), shared with the other problems on
// `primal` when the setup names its data (load_key), else assembled into `own`.
const Eigen::VectorXd& load_vector(const ContactSetup& setup, const operators::PrimalOperators& primal,
                                   const space::H1Space& space, const assembly::LocalRows& target,
                                   Eigen::VectorXd& own) {
  auto assemble = [&] {
    Eigen::VectorXd load = assembly::assemble_volume_load(space, setup.f, target);
    if (setup.traction)
      load += assembly::assemble_boundary_load(space, {mesh::BoundaryPart::neumann, mesh::BoundaryPart::contact},
                                               setup.traction, target);
    return load;
  };
  if (!setup.load_key.empty() && &space == &primal.space()) return primal.derived_vector("F", setup.load_key, assemble);
  Stopwatch clock;
  own = assemble();
  if (primal.log()) primal.log()->record("F", own.size(), 1, clock.seconds());
  return own;
}

// This rank's share of the load of u (for k_factor.solve_local), and the energy's constant: F
// assembled over the rank's own cells; with Dirichlet data u = u_0 + w, over the same cells on the
// extended space (Γ_D kept), then moved to u_0's unknowns (assembly::DirichletLift).
assembly::DirichletLift::LiftedLoad problem_load_share(const ContactSetup& setup,
                                                       const operators::PrimalOperators& primal,
                                                       const assembly::DirichletLift* lift,
                                                       const assembly::CondensedFactor& k_factor) {
  Eigen::VectorXd own;
  if (!lift) return {load_vector(setup, primal, primal.space(), k_factor.local_rows(), own), 0.0};
  const assembly::LocalRows& rows = k_factor.local_rows();
  const assembly::LocalRows extended_rows = lift->extended_rows(rows);
  const Eigen::VectorXd& extended = load_vector(setup, primal, lift->extended_scalar(), extended_rows, own);
  return lift->lifted_load(assembly::ScalarCellSystem(primal.space(), 1.0, 0.0), extended, rows, extended_rows,
                           primal.distribution());
}

// The problem's coupling and constraints: B (B^s for (13)) in the nodal multiplier basis (the
// family's basis for a standard or dual family) and the
// offset of the gap it measures, (ℓ_i, g) for (9), less B w with Dirichlet data u = u_0 + w.
struct NodalCoupling {
  std::string name;                 ///< "B" or "B^s" (S is shared between problems by it and the weight)
  assembly::CouplingWeight weight;  ///< s for B^s
  MultiplierConstraints constraints;
  linalg::Coupling matrix;
  Eigen::VectorXd gap_offset;
};

NodalCoupling assemble_nodal_coupling(const ContactSetup& setup, const operators::PrimalOperators& primal,
                                      const space::MultiplierSpace& multipliers, const assembly::DirichletLift* lift) {
  const bool weighted = setup.problem == ContactProblem::friction;
  NodalCoupling out;
  out.weight = weighted ? setup.bound : assembly::CouplingWeight{};
  out.name = weighted ? "B^s" : "B";
  const linalg::Coupling& coupling_legendre = primal.coupling(multipliers, out.weight, out.name);
  out.constraints = build_multiplier_constraints(setup, multipliers, primal.contact());
  const linalg::Coupling to_nodal = out.constraints.to_nodal.sparseView();
  out.matrix = linalg::squeezed<linalg::Coupling>((to_nodal * coupling_legendre).pruned());
  out.gap_offset = Eigen::VectorXd::Zero(out.constraints.to_nodal.rows());
  if (setup.problem == ContactProblem::signorini) {
    Stopwatch obstacle_clock;
    out.gap_offset =
        out.constraints.to_nodal * assembly::assemble_multiplier_load(primal.contact(), multipliers, setup.obstacle);
    if (primal.log()) primal.log()->record("g", multipliers.n_dofs(), 1, obstacle_clock.seconds());
  }
  // The constraints act on u_0 + w: B u_0 against (ℓ_i, g) − B w.
  if (lift)
    out.gap_offset -= to_nodal * lift->times(assembly::assemble_coupling(lift->extended_scalar(), primal.contact(),
                                                                         multipliers, out.weight.function()));
  return out;
}

// The condensed problem min ½ λᵀSλ − dᵀλ: S = B K⁻¹ Bᵀ, d = B u_free − gap_offset with u_free =
// K⁻¹ F, and the load that u is recovered from.
struct CondensedProblem {
  assembly::DirichletLift::LiftedLoad load;  ///< this rank's share of F (of u_0's), the energy's constant
  const Eigen::MatrixXd& s;
  Eigen::VectorXd b_u_free, d;
};

// Condensation onto the Γ_C trace: the trace dofs ordered last in the factorization, so that
// S = B K⁻¹ Bᵀ is dense algebra on the trailing block of the factor. S depends on the coupling
// alone (its key holds the multiplier space's layout and family): problems sharing B share S. Distributed,
// the vectors of S^p(T_h) are held at each rank's own cells' dofs, the load as the ranks' shares:
// none of the global length, with Dirichlet data too (u stays at the rank's own cells' dofs,
// where the outputs read it).
CondensedProblem condense_onto_trace(const ContactSetup& setup, const operators::PrimalOperators& primal,
                                     const space::MultiplierSpace& multipliers, const NodalCoupling& coupling,
                                     ContactSolution& out) {
  Stopwatch factorization_clock;
  const assembly::CondensedFactor& k_factor = primal.stiffness_factor();
  out.seconds.factorization = factorization_clock.seconds();
  Stopwatch load_clock;
  assembly::DirichletLift::LiftedLoad load = problem_load_share(setup, primal, out.lift.get(), k_factor);
  out.seconds.assembly += load_clock.seconds();
  Stopwatch condensation_clock;
  const Eigen::VectorXd u_free = k_factor.solve_local(load.load).col(0);
  const Eigen::MatrixXd& s =
      primal.derived_matrix("S",
                            operators::PrimalOperators::coupling_key(
                                multipliers, coupling.name + " " + space::to_string(setup.family), coupling.weight),
                            [&] { return Eigen::MatrixXd(k_factor.schur_complement(coupling.matrix)); });
  Eigen::VectorXd b_u_free = k_factor.multiply_local(coupling.matrix, u_free).col(0);
  Eigen::VectorXd d = b_u_free - coupling.gap_offset;
  out.seconds.condensation = condensation_clock.seconds();
  out.n_trace = k_factor.n_trailing();
  return {std::move(load), s, std::move(b_u_free), std::move(d)};
}

// The multiplier λ of the condensed problem under the constraints (and their multipliers).
void solve_for_multiplier(const ContactSetup& setup, const CondensedProblem& problem,
                          const MultiplierConstraints& constraints, OperatorLog* log, ContactSolution& out) {
  Stopwatch qp_clock;
  auto qp = solve_multiplier_qp(problem.s, problem.d, constraints, setup.qp, setup.interior_point);
  out.lambda = std::move(qp.x);
  out.constraint_multiplier = std::move(qp.y);
  out.qp = std::move(qp.report);
  out.seconds.qp = qp_clock.seconds();
  if (log) log->record("contact QP (" + out.qp.method + ")", problem.s.rows(), problem.s.cols(), out.seconds.qp);
}

// Recovery: u = K⁻¹(F − Bᵀλ), the gap, the energy from the factor's blocks (K itself is never
// assembled).
void recover_displacement(const assembly::CondensedFactor& k_factor, const CondensedProblem& problem,
                          const NodalCoupling& coupling, ContactSolution& out) {
  Stopwatch recovery_clock;
  out.lambda_legendre = coupling.constraints.to_nodal.transpose() * out.lambda;  // V⁻¹ c_nodal
  const Eigen::VectorXd& load_share = problem.load.load;
  const Eigen::VectorXd reduced_share = load_share - k_factor.transpose_share(coupling.matrix, out.lambda).col(0);
  const Eigen::VectorXd u = k_factor.solve_local(reduced_share).col(0);
  out.gap = k_factor.multiply_local(coupling.matrix, u).col(0) - coupling.gap_offset;
  // C = I: stationarity y = d − S λ = gap.
  if (out.qp.method != "interior-point") out.constraint_multiplier = out.gap;
  out.gap_scale = problem.b_u_free.lpNorm<Eigen::Infinity>() + coupling.gap_offset.lpNorm<Eigen::Infinity>() +
                  (problem.s * out.lambda).lpNorm<Eigen::Infinity>();
  out.energy = 0.5 * k_factor.quadratic_form_local(u) - k_factor.dot_local(load_share, u) + problem.load.energy_offset;
  out.u = u;
  out.u_rows = k_factor.local_rows();
  out.n_dofs = k_factor.size();
  out.seconds.recovery = recovery_clock.seconds();
}

}  // namespace

ContactSolution solve_contact(const ContactSetup& setup) {
  check_data(setup);
  ContactSolution out;
  // 1. Operators: F, the coupling B (B^s for (13)) in the nodal multiplier basis, the constraints
  //    and, for (9), the obstacle term (ℓ_i, g).
  Stopwatch assembly_clock;
  std::unique_ptr<operators::PrimalOperators> own_primal;
  const operators::PrimalOperators& primal =
      operators::shared_or_own(setup.primal, setup.mesh, setup.cell_degrees, own_primal);
  const space::MultiplierSpace multipliers(*setup.boundary_mesh, setup.segment_degrees);
  if (setup.dirichlet)
    out.lift = std::make_shared<assembly::DirichletLift>(primal.space(), setup.dirichlet, primal.lift_space());
  NodalCoupling coupling = assemble_nodal_coupling(setup, primal, multipliers, out.lift.get());
  out.seconds.assembly = assembly_clock.seconds();
  // 2. Condensation onto the Γ_C trace, 3. the multiplier, 4. u recovered.
  const CondensedProblem problem = condense_onto_trace(setup, primal, multipliers, coupling, out);
  solve_for_multiplier(setup, problem, coupling.constraints, primal.log(), out);
  recover_displacement(primal.stiffness_factor(), problem, coupling, out);
  out.constraint_matrix = std::move(coupling.constraints.matrix);
  out.lower = std::move(coupling.constraints.lower);
  out.upper = std::move(coupling.constraints.upper);
  out.constraint_s = std::move(coupling.constraints.s);
  out.constraint_points = std::move(coupling.constraints.points_per_segment);
  return out;
}

}  // namespace hpcontact::contact
