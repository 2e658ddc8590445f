// Scalar contact problems on hexahedral meshes: condensation onto Γ_C, the multiplier QP, recovery.
#include "contact/solid_contact.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "assembly/condensed_factor.hpp"
#include "assembly/solid_cell_system.hpp"
#include "assembly/surface_coupling.hpp"
#include "basis/quadrature.hpp"
#include "contact/multiplier_qp.hpp"
#include "contact/solid_trace_qp.hpp"
#include "core/error.hpp"
#include "core/timer.hpp"

namespace hpcontact::contact {

namespace {

/// The bounds of λ at its nodal points: λ ≤ 0 (9); |λ| ≤ 1 on the cells meeting supp s, λ = 0 on
/// the others (13); |λ| ≤ s (15). C = I is formed only for the dense path's interior-point fallback
/// (`identity_rows`): on the products path it would be the dense m × m matrix the path avoids.
MultiplierConstraints nodal_bounds(const SolidContactSetup& setup, bool identity_rows) {
  const space::SurfaceMultiplierSpace& multipliers = *setup.multipliers;
  const int m = multipliers.n_dofs();
  constexpr double infinity = std::numeric_limits<double>::infinity();
  MultiplierConstraints out;
  if (identity_rows) {
    out.to_nodal = Eigen::MatrixXd::Identity(m, m);
    out.matrix = Eigen::MatrixXd::Identity(m, m);
  }
  out.lower = Eigen::VectorXd::Constant(m, -infinity);
  out.upper = Eigen::VectorXd::Zero(m);
  if (setup.problem == ContactProblem::signorini) return out;
  std::vector<char> in_support;
  if (setup.problem == ContactProblem::friction)
    for (int c = 0; c < multipliers.mesh().n_cells(); ++c)
      in_support.push_back(assembly::cell_meets_support(multipliers.mesh(), c, setup.bound) ? 1 : 0);
  for (int i = 0; i < m; ++i) {
    double bound = 1.0;
    if (setup.problem == ContactProblem::friction) bound = in_support[i / multipliers.per_cell()] ? 1.0 : 0.0;
    if (setup.problem == ContactProblem::friction_s) {
      const mesh::SolidPoint x = multipliers.mesh().surface().from_plane(multipliers.nodal_point(i));
      bound = setup.bound(x);
      if (!(bound >= 0.0))
        throw InputError(
            fmt::format("the friction bound s is {} at ({}, {}, {}) on Γ_C; it must be ≥ 0", bound, x(0), x(1), x(2)));
    }
    out.lower(i) = -bound;
    out.upper(i) = bound;
  }
  return out;
}

}  // namespace

SolidContactSolution solve_solid_contact(const SolidContactSetup& setup) {
  if (setup.space == nullptr || setup.multipliers == nullptr || !setup.f)
    throw InputError("3-D contact problem: the space, the multipliers or the load f is missing");
  if (setup.problem == ContactProblem::signorini && !setup.obstacle)
    throw InputError("Signorini problem: the obstacle g is missing");
  if (setup.problem != ContactProblem::signorini && !setup.bound)
    throw InputError("friction problem: the bound s is missing");
  const space::SolidH1Space& space = *setup.space;
  SolidContactSolution out;

  // 1. Assemble F, B (weighted by s for (13)) and G; the bounds of λ.
  Stopwatch clock;
  const Eigen::VectorXd load = assembly::solid_load(space, setup.f);
  const linalg::Coupling b = assembly::surface_coupling(
      space, *setup.multipliers, setup.problem == ContactProblem::friction ? setup.bound : assembly::SolidFunction());
  const Eigen::VectorXd g = setup.problem == ContactProblem::signorini
                                ? assembly::surface_multiplier_load(*setup.multipliers, setup.obstacle)
                                : Eigen::VectorXd::Zero(setup.multipliers->n_dofs());
  if (setup.trace_solve == SchurPath::saddle_point)
    throw InputError(
        "solve.trace_operator = \"saddle_point\" solves elastic frictionless contact only; the scalar 3-D problems "
        "take \"dense\", \"products\" or \"auto\"");
  const bool products = uses_products(setup.trace_solve, b.rows(), b.cols());
  const MultiplierConstraints constraints = nodal_bounds(setup, !products);
  out.n_trace = static_cast<int>(linalg::nonzero_columns(b).size());
  out.seconds.assembly = clock.seconds();

  // 2. Factorize K by static condensation (the trace dofs last on the dense path).
  clock = Stopwatch();
  const assembly::CondensedFactor factor(std::make_unique<assembly::SolidScalarCellSystem>(space, 1.0, 0.0),
                                         trailing_dofs(products, b), setup.distribution);
  out.seconds.factorization = clock.seconds();

  // 3. S = B K⁻¹ Bᵀ (from the trailing block, or as products), d = B K⁻¹ F − G.
  clock = Stopwatch();
  const SolidTraceOperator s = condensed_operator(factor, b, products);
  const Eigen::VectorXd u_free = factor.solve(load);
  const Eigen::VectorXd d = b * u_free - g;
  out.seconds.condensation = clock.seconds();

  // 4. The multiplier QP.
  clock = Stopwatch();
  MultiplierQpSolution qp = solve_bounded_trace_qp(s, d, constraints, setup.qp, setup.interior_point);
  out.lambda = std::move(qp.x);
  out.qp = std::move(qp.report);
  out.lower = constraints.lower;
  out.upper = constraints.upper;
  out.seconds.qp = clock.seconds();

  // 5. u = K⁻¹(F − Bᵀλ), the gap and the energy.
  clock = Stopwatch();
  const Eigen::VectorXd reduced = load - Eigen::VectorXd(b.transpose() * out.lambda);
  out.u = factor.solve(reduced);
  out.gap = b * out.u - g;
  out.energy = 0.5 * factor.quadratic_form(out.u) - load.dot(out.u);
  out.seconds.recovery = clock.seconds();
  return out;
}

}  // namespace hpcontact::contact
