// The scalar model: its operators, contact problems and results.
#include "driver/scalar_model.hpp"

#include <algorithm>

#include "adapt/legendre_decay.hpp"
#include "adapt/residual_estimator.hpp"
#include "assembly/cell_field.hpp"
#include "core/timer.hpp"
#include "io/vtu_writer.hpp"
#include "operators/primal_operators.hpp"
#include "postprocess/boundary_samples.hpp"
#include "postprocess/moment_half_width.hpp"

namespace hpcontact::driver {
namespace {

ContactResult scalar_result(const std::string& name, const contact::ContactSolution& solution,
                            const postprocess::BoundarySamples& samples, const mesh::BoundaryMesh& boundary_mesh,
                            double seconds) {
  ContactResult r;
  r.problem = name;
  r.energy = solution.energy;
  r.n_dofs = solution.n_dofs;
  r.nmult = solution.lambda.size();
  r.n_trace = solution.n_trace;
  r.contact_set_length = samples.contact_set_length;
  const auto& zones = boundary_mesh.zones();
  for (std::size_t z = 0; z < zones.size(); ++z)
    r.zones.push_back({zones[z].end - zones[z].begin, zones[z].closed, samples.zone_contact_set_length[z], {}, {}, {}});
  // (a standard or dual family constrains its coefficients: no points per segment)
  const auto& q = solution.constraint_points;
  if (!q.empty())
    r.constraint_points =
        ConstraintPointCount{*std::min_element(q.begin(), q.end()), *std::max_element(q.begin(), q.end()),
                             static_cast<long long>(solution.constraint_s.size())};
  r.bounds = MultiplierBounds{samples.bounds.relative, samples.bounds.at, samples.bounds.to_free_boundary};
  r.solver = solution.qp;
  r.seconds = {solution.seconds.assembly, solution.seconds.factorization, solution.seconds.condensation,
               solution.seconds.qp,       solution.seconds.recovery,      seconds};
  return r;
}

class ScalarModel final : public Model {
 public:
  ScalarModel(const scene::Scene& scene, const SceneDiscretization& d, OperatorLog* log,
              const linalg::Distribution& distribution)
      : scene_(scene), d_(d), primal_(d.mesh.get(), d.cell_degrees, log, distribution) {}

  std::vector<scene::Effect> problems() const override {
    std::vector<scene::Effect> effects;
    for (const auto problem : scene_.contact_effects()) effects.push_back(scene::effect_of(problem));
    return effects;
  }

  SolvedProblem solve(scene::Effect effect) const override {
    Stopwatch clock;
    const auto setup = contact_setup_of(scene_, d_, *scene::contact_problem_of(effect), primal_);
    auto solution = std::make_shared<const contact::ContactSolution>(contact::solve_contact(setup));
    const double seconds = clock.seconds();
    auto samples = postprocess::sample_boundary(setup, *solution);
    // u = u0 + the Dirichlet lift on Ω, on this rank's cells.
    auto grid = [this, solution] {
      return io::solution_vtu_grid(
          assembly::scalar_field(primal_.space(), solution->u, solution->u_rows, solution->lift));
    };
    auto result = scalar_result(scene::to_string(effect), *solution, samples, *d_.boundary_mesh, seconds);
    if (setup.problem == contact::ContactProblem::signorini)  // λ ≤ 0 where in contact
      result.moment_half_width = postprocess::moment_half_width(*d_.multipliers, -solution->lambda_legendre);
    SolvedProblem solved{std::move(result),
                         scene::to_string(effect),
                         std::move(samples.table),
                         solution->lambda_legendre,
                         {{"", io::solution_vtu_fields(), std::move(grid)}},
                         std::nullopt};
    if (scene_.is_adaptive()) {
      const auto field = assembly::scalar_field(primal_.space(), solution->u, solution->u_rows, solution->lift);
      solved.indicators = AdaptIndicators{adapt::residual_indicators(setup, *solution, primal_.space()),
                                          adapt::legendre_decay(primal_.space(), field)};
    }
    return solved;
  }

  infsup::InfSupSetup infsup_setup() const override {
    return infsup_setup_of(scene_, d_.mesh.get(), d_.cell_degrees, *d_.boundary_mesh, d_.segment_degrees, primal_);
  }
  const mesh::Mesh& operators_mesh() const override { return primal_.mesh(); }
  long long n_dofs() const override { return primal_.space().n_dofs(); }
  void release_factors() const override { primal_.release_factors(); }
  std::function<double(double)> multiplier_error_weight(scene::Effect effect,
                                                        const SceneDiscretization& finest) const override {
    return driver::multiplier_error_weight(scene_, finest, *scene::contact_problem_of(effect));
  }

 private:
  const scene::Scene& scene_;
  const SceneDiscretization& d_;
  const operators::PrimalOperators primal_;
};

}  // namespace

std::unique_ptr<Model> make_scalar_model(const scene::Scene& scene, const SceneDiscretization& d, OperatorLog* log,
                                         const linalg::Distribution& distribution) {
  return std::make_unique<ScalarModel>(scene, d, log, distribution);
}

}  // namespace hpcontact::driver
