// Elastic contact on hexahedral meshes (frictionless, Tresca, Coulomb): the coupling, condensation,
// the QP (Coulomb: its fixed point), recovery.
#include "contact/solid_elastic_contact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <limits>
#include <memory>

#include "assembly/condensed_factor.hpp"
#include "assembly/solid_elastic_system.hpp"
#include "assembly/surface_coupling.hpp"
#include "contact/active_set_contact.hpp"
#include "contact/disc_qp.hpp"
#include "contact/multiplier_qp.hpp"
#include "contact/solid_trace_qp.hpp"
#include "core/error.hpp"
#include "core/timer.hpp"

namespace hpcontact::contact {
namespace {

/// Tresca's threshold s at the nodal points of T_{C,H}, each checked ≥ 0.
Eigen::VectorXd tresca_radius(const SolidElasticSetup& setup) {
  const auto& surface = setup.multipliers->mesh().surface();
  Eigen::VectorXd radius(setup.multipliers->n_dofs());
  for (Eigen::Index i = 0; i < radius.size(); ++i) {
    const mesh::SolidPoint x = surface.from_plane(setup.multipliers->nodal_point(static_cast<int>(i)));
    radius(i) = setup.threshold(x);
    if (!(radius(i) >= 0.0))
      throw InputError(fmt::format("Tresca's threshold s is {} at ({}, {}, {}) on Γ_C; it must be ≥ 0", radius(i), x(0),
                                   x(1), x(2)));
  }
  return radius;
}

/// Coulomb: the Tresca problems on S, d with radii F P_k at the nodal points, P_k the pressure of
/// the previous iterate (P_0 = 0), until max |Δλ| / max |λ| ≤ the tolerance. The report is the
/// last QP's, with the steps and products of all of them.
DiscQpSolution solve_coulomb_fixed_point(const SolidElasticSetup& setup, const SolidTraceOperator& s,
                                         const Eigen::VectorXd& d, std::vector<double>& changes) {
  const double coefficient = *setup.friction_coefficient;
  const Eigen::Index m = d.size() / 3;
  Eigen::VectorXd previous = Eigen::VectorXd::Zero(d.size());
  int steps = 0;
  long products = 0;
  for (int k = 1; k <= setup.max_fixed_point_iterations; ++k) {
    DiscQpSolution qp = solve_disc_trace_qp(s, d, coefficient * previous.head(m).cwiseMax(0.0));
    steps += qp.report.iterations;
    products += qp.report.products;
    const double scale = std::max(qp.x.lpNorm<Eigen::Infinity>(), std::numeric_limits<double>::min());
    changes.push_back((qp.x - previous).lpNorm<Eigen::Infinity>() / scale);
    previous = qp.x;
    if (changes.back() <= setup.fixed_point_tolerance) {
      qp.report.iterations = steps;
      qp.report.products = products;
      return qp;
    }
  }
  throw NumericalError(
      fmt::format("Coulomb friction (F = {}): the fixed point on the Tresca problem did not converge in {} iterations "
                  "(relative changes of λ, first and last: {:.3e}, {:.3e}; tolerance {:.1e}); a smaller F, or a finer "
                  "T_{{C,H}} where the pressure varies, may help",
                  coefficient, changes.size(), changes.front(), changes.back(), setup.fixed_point_tolerance));
}

/// P ≥ 0 at the m nodal points; C = I formed only for the dense path's interior-point fallback
/// (`identity_rows`).
MultiplierConstraints pressure_bounds(int m, bool identity_rows) {
  MultiplierConstraints out;
  if (identity_rows) out.to_nodal = out.matrix = Eigen::MatrixXd::Identity(m, m);
  out.lower = Eigen::VectorXd::Zero(m);
  out.upper = Eigen::VectorXd::Constant(m, std::numeric_limits<double>::infinity());
  return out;
}

/// solve.trace_operator = "saddle_point": frictionless contact on an iterative K.
void check_saddle_point_setup(const SolidElasticSetup& setup, bool friction) {
  if (friction)
    throw InputError(
        "solve.trace_operator = \"saddle_point\" solves frictionless contact only; Tresca and Coulomb friction "
        "take \"dense\", \"products\" or \"auto\"");
  const linalg::DistributedSolver k = setup.distribution.solver;
  if (k != linalg::DistributedSolver::gamg && k != linalg::DistributedSolver::bddc)
    throw InputError(
        fmt::format("solve.trace_operator = \"saddle_point\" needs an iterative K (the active set's steps "
                    "are its projected conjugate gradients): run with --distributed-solver gamg or bddc, "
                    "not {}",
                    to_string(k)));
}

}  // namespace

linalg::Coupling stacked_coupling(const space::SolidVectorSpace& space,
                                  const space::SurfaceMultiplierSpace& multipliers, int blocks) {
  const auto& surface = multipliers.mesh().surface();
  const int m = multipliers.n_dofs();
  const linalg::Coupling scalar_b = assembly::surface_coupling(space.scalar(), multipliers);
  std::vector<Eigen::Triplet<double>> entries;
  const std::array<Eigen::Vector3d, 3> directions{surface.normal(), surface.axis(0), surface.axis(1)};
  for (int k = 0; k < blocks; ++k) {
    const linalg::Coupling part = assembly::directional_coupling(space, scalar_b, directions[k]);
    for (int row = 0; row < part.outerSize(); ++row)
      for (linalg::Coupling::InnerIterator it(part, row); it; ++it)
        entries.emplace_back(k * m + row, static_cast<int>(it.col()), it.value());
  }
  linalg::Coupling b(blocks * m, space.n_dofs());
  b.setFromTriplets(entries.begin(), entries.end());
  return b;
}

Eigen::VectorXd solid_body_load(const SolidElasticSetup& setup) {
  const space::SolidVectorSpace& space = *setup.space;
  Eigen::VectorXd load = Eigen::VectorXd::Zero(space.n_dofs());
  for (int c = 0; c < 3; ++c) {
    if (!setup.body_force[c]) continue;
    const Eigen::VectorXd component = assembly::solid_load(space.scalar(), setup.body_force[c]);
    for (int d = 0; d < space.scalar().n_dofs(); ++d)
      if (const int dof = space.dof(d, c); dof >= 0) load(dof) = component(d);
  }
  return load;
}

SolidElasticSolution solve_solid_elastic_contact(const SolidElasticSetup& setup) {
  if (setup.space == nullptr || setup.multipliers == nullptr || !setup.gap)
    throw InputError("3-D elastic contact: the space, the multipliers or the gap g is missing");
  if (setup.friction_coefficient && (setup.threshold || !(*setup.friction_coefficient >= 0.0)))
    throw InputError(
        fmt::format("3-D Coulomb friction: the friction coefficient F = {} must be ≥ 0 and come "
                    "without Tresca's threshold s",
                    *setup.friction_coefficient));
  const space::SolidVectorSpace& space = *setup.space;
  SolidElasticSolution out;

  // 1. F, B_n, G.
  Stopwatch clock;
  const Eigen::VectorXd load = solid_body_load(setup);
  // (Coulomb: Tresca problems, whose discs the fixed point sizes)
  const bool tresca = setup.threshold || setup.friction_coefficient;
  const int m = setup.multipliers->n_dofs();
  const linalg::Coupling b = stacked_coupling(space, *setup.multipliers, tresca ? 3 : 1);
  Eigen::VectorXd g = Eigen::VectorXd::Zero(b.rows());
  g.head(m) = assembly::surface_multiplier_load(*setup.multipliers, setup.gap);
  const Eigen::VectorXd radius = setup.threshold ? tresca_radius(setup) : Eigen::VectorXd();
  const bool saddle_point = setup.trace_solve == SchurPath::saddle_point;
  if (saddle_point) check_saddle_point_setup(setup, tresca);
  const bool products = saddle_point || uses_products(setup.trace_solve, b.rows(), b.cols());
  const MultiplierConstraints constraints = pressure_bounds(m, !products);
  out.n_trace = static_cast<int>(linalg::nonzero_columns(b).size());
  out.seconds.assembly = clock.seconds();

  // 2. K by static condensation (the trace last on the dense path).
  clock = Stopwatch();
  const assembly::CondensedFactor factor(std::make_unique<assembly::SolidElasticCellSystem>(space, setup.materials),
                                         trailing_dofs(products, b), setup.distribution);
  out.seconds.factorization = clock.seconds();

  if (saddle_point) {
    // 3–4. No S: the active set on the saddle point, each step K's projected CG.
    clock = Stopwatch();
    const std::unique_ptr<linalg::ConstrainedSolver> solver = factor.constrained_solver(b);
    HPC_VERIFY(solver != nullptr, "an iterative K without constrained solves");
    ActiveSetContactSolution contact = solve_active_set_contact(*solver, b, load, g);
    out.u = std::move(contact.u);
    out.pressure = std::move(contact.pressure);
    out.traction_1 = out.traction_2 = Eigen::VectorXd::Zero(m);
    out.qp = std::move(contact.report);
    out.seconds.qp = clock.seconds();
    clock = Stopwatch();
    out.gap = g - b * out.u;
    out.energy = 0.5 * factor.quadratic_form(out.u) - load.dot(out.u);
    out.seconds.recovery = clock.seconds();
    return out;
  }

  // 3. S (dense or as products) and d.
  clock = Stopwatch();
  const SolidTraceOperator s = condensed_operator(factor, b, products);
  const Eigen::VectorXd d = b * factor.solve(load) - g;
  out.seconds.condensation = clock.seconds();

  // 4. The multipliers: min ½ λᵀ S λ − λᵀ d over P ≥ 0 (and the discs |(t₁, t₂)| ≤ s, for
  //    Coulomb s = F P by the fixed point).
  clock = Stopwatch();
  Eigen::VectorXd lambda;
  if (tresca) {
    DiscQpSolution qp = setup.friction_coefficient ? solve_coulomb_fixed_point(setup, s, d, out.fixed_point_changes)
                                                   : solve_disc_trace_qp(s, d, radius);
    lambda = std::move(qp.x);
    out.qp = std::move(qp.report);
  } else {
    MultiplierQpSolution qp = solve_bounded_trace_qp(s, d, constraints, setup.qp, setup.interior_point);
    lambda = std::move(qp.x);
    out.qp = std::move(qp.report);
  }
  out.pressure = lambda.head(m);
  out.traction_1 = tresca ? Eigen::VectorXd(lambda.segment(m, m)) : Eigen::VectorXd::Zero(m);
  out.traction_2 = tresca ? Eigen::VectorXd(lambda.tail(m)) : Eigen::VectorXd::Zero(m);
  out.seconds.qp = clock.seconds();

  // 5. u = K⁻¹(F − B_nᵀ P), the gap (ℓ_i, g − u·n), the energy.
  clock = Stopwatch();
  out.u = factor.solve(Eigen::VectorXd(load - b.transpose() * lambda));
  out.gap = (g - b * out.u).head(m);
  out.energy = 0.5 * factor.quadratic_form(out.u) - load.dot(out.u);
  out.seconds.recovery = clock.seconds();
  return out;
}

}  // namespace hpcontact::contact
