// Frictionless elastic contact on hexahedral meshes: the normal coupling, condensation, QP, recovery.
#include "contact/solid_elastic_contact.hpp"

#include <limits>

#include "assembly/condensed_factor.hpp"
#include "assembly/solid_elastic_system.hpp"
#include "assembly/surface_coupling.hpp"
#include "contact/multiplier_qp.hpp"
#include "core/error.hpp"
#include "core/timer.hpp"

namespace hpcontact::contact {

SolidElasticSolution solve_solid_frictionless(const SolidElasticSetup& setup) {
  if (setup.space == nullptr || setup.multipliers == nullptr || !setup.gap)
    throw InputError("3-D elastic contact: the space, the multipliers or the gap g is missing");
  const space::SolidVectorSpace& space = *setup.space;
  const space::SolidH1Space& scalar = space.scalar();
  SolidElasticSolution out;

  // 1. F, B_n, G.
  Stopwatch clock;
  Eigen::VectorXd load = Eigen::VectorXd::Zero(space.n_dofs());
  for (int c = 0; c < 3; ++c) {
    if (!setup.body_force[c]) continue;
    const Eigen::VectorXd component = assembly::solid_load(scalar, setup.body_force[c]);
    for (int d = 0; d < scalar.n_dofs(); ++d)
      if (const int dof = space.dof(d, c); dof >= 0) load(dof) = component(d);
  }
  const Eigen::Vector3d normal = setup.multipliers->mesh().surface().normal();
  const linalg::Coupling b =
      assembly::directional_coupling(space, assembly::surface_coupling(scalar, *setup.multipliers), normal);
  const Eigen::VectorXd g = assembly::surface_multiplier_load(*setup.multipliers, setup.gap);
  const int m = setup.multipliers->n_dofs();
  MultiplierConstraints constraints;
  constraints.to_nodal = Eigen::MatrixXd::Identity(m, m);
  constraints.matrix = Eigen::MatrixXd::Identity(m, m);
  constraints.lower = Eigen::VectorXd::Zero(m);
  constraints.upper = Eigen::VectorXd::Constant(m, std::numeric_limits<double>::infinity());
  const std::vector<int> trace = linalg::nonzero_columns(b);
  out.n_trace = static_cast<int>(trace.size());
  out.seconds.assembly = clock.seconds();

  // 2. K by static condensation, the trace last.
  clock = Stopwatch();
  const assembly::CondensedFactor factor(std::make_unique<assembly::SolidElasticCellSystem>(space, setup.materials),
                                         trace);
  out.seconds.factorization = clock.seconds();

  // 3. S and d.
  clock = Stopwatch();
  const Eigen::MatrixXd s = factor.schur_complement(b);
  const Eigen::VectorXd d = b * factor.solve(load) - g;
  out.seconds.condensation = clock.seconds();

  // 4. The pressure: min ½ Pᵀ S P − Pᵀ d over P ≥ 0.
  clock = Stopwatch();
  MultiplierQpSolution qp = solve_multiplier_qp(s, d, constraints, setup.qp, setup.interior_point);
  out.pressure = std::move(qp.x);
  out.qp = std::move(qp.report);
  out.seconds.qp = clock.seconds();

  // 5. u = K⁻¹(F − B_nᵀ P), the gap (ℓ_i, g − u·n), the energy.
  clock = Stopwatch();
  out.u = factor.solve(Eigen::VectorXd(load - b.transpose() * out.pressure));
  out.gap = g - b * out.u;
  out.energy = 0.5 * factor.quadratic_form(out.u) - load.dot(out.u);
  out.seconds.recovery = clock.seconds();
  return out;
}

}  // namespace hpcontact::contact
