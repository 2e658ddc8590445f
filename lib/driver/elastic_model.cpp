// The elastic model: its operators, contact problems and results.
#include "driver/elastic_model.hpp"

#include "adapt/elastic_residual_estimator.hpp"
#include "adapt/legendre_decay.hpp"
#include "assembly/cell_field.hpp"
#include "core/timer.hpp"
#include "driver/elastic_scene.hpp"
#include "driver/exact_check.hpp"
#include "io/vtu_writer.hpp"
#include "postprocess/elastic_boundary_samples.hpp"
#include "postprocess/moment_half_width.hpp"
#include "scene/scene_mesh.hpp"

namespace hpcontact::driver {

std::vector<scene::Effect> elastic_problem_effects(const scene::Scene& scene) {
  std::vector<scene::Effect> effects;
  for (const auto problem : scene.elastic_effects()) effects.push_back(scene::effect_of(problem));
  return effects;
}

ContactResult elastic_result(const contact::ElasticContactSetup& setup, const contact::ElasticContactSolution& solution,
                             const postprocess::ElasticBoundarySamples& samples, double seconds) {
  ContactResult r;
  r.problem = contact::to_string(setup.problem);
  r.energy = solution.energy;
  r.n_dofs = solution.n_dofs;
  r.nmult = solution.lambda.size();
  r.n_trace = solution.n_trace;
  // Tied contact bonds all of Γ_C whatever the sign of the traction: its contact set is Γ_C.
  const bool tied = setup.problem == contact::ElasticContactProblem::tied;
  r.contact_set_length = tied ? setup.boundary_mesh->length() : samples.contact_set_length;
  if (!tied)
    r.moment_half_width = postprocess::moment_half_width(
        space::MultiplierSpace(*setup.boundary_mesh, setup.segment_degrees), solution.pressure);
  r.total_force = samples.total_force;
  r.tangential_force = samples.tangential_force;
  r.contact_force = {samples.contact_force.x(), samples.contact_force.y()};
  const auto& zones = setup.boundary_mesh->zones();
  for (std::size_t z = 0; z < zones.size(); ++z)
    r.zones.push_back({zones[z].end - zones[z].begin, zones[z].closed,
                       tied ? zones[z].end - zones[z].begin : samples.zone_contact_set_length[z],
                       samples.zone_total_force[z], samples.zone_tangential_force[z],
                       std::array{samples.zone_contact_force[z].x(), samples.zone_contact_force[z].y()}});
  r.solver = solution.qp;
  r.seconds = {solution.seconds.assembly, solution.seconds.factorization, solution.seconds.condensation,
               solution.seconds.qp,       solution.seconds.recovery,      seconds};
  if (!tied) r.bounds = MultiplierBounds{samples.bounds.relative, samples.bounds.at, samples.bounds.to_free_boundary};
  r.fixed_point_changes = solution.fixed_point_changes;
  if (setup.problem == contact::ElasticContactProblem::coulomb) r.friction_coefficient = setup.friction_coefficient;
  return r;
}

namespace {

class ElasticModel final : public Model {
 public:
  ElasticModel(const scene::Scene& scene, const SceneDiscretization& d, OperatorLog* log,
               const linalg::Distribution& distribution)
      : scene_(scene),
        d_(d),
        operators_(scene_elastic_operators(scene, d.mesh.get(), d.cell_degrees, log, distribution)) {}

  std::vector<scene::Effect> problems() const override { return elastic_problem_effects(scene_); }

  SolvedProblem solve(scene::Effect effect) const override {
    Stopwatch clock;
    const auto setup = elastic_setup_of(scene_, d_, *scene::elastic_problem_of(effect), *operators_);
    auto solution = std::make_shared<const contact::ElasticContactSolution>(contact::solve_elastic_contact(setup));
    const double seconds = clock.seconds();
    auto samples = postprocess::sample_elastic_boundary(setup, *solution);
    auto result = elastic_result(setup, *solution, samples, seconds);
    result.exact = exact_errors_of(
        {{&scene_, assembly::vector_field(operators_->vector_space(), solution->u, solution->u_rows, solution->lift),
          &operators_->mesh()}},
        setup, solution->pressure, operators_->distribution());
    // The displacement u0 + the Dirichlet lift, its stress and von Mises stress, on this rank's cells.
    auto grid = [this, solution] {
      return io::elastic_vtu_grid(
          assembly::vector_field(operators_->vector_space(), solution->u, solution->u_rows, solution->lift),
          operators_->materials());
    };
    SolvedProblem solved{std::move(result),
                         scene::to_string(effect),
                         std::move(samples.table),
                         solution->pressure,
                         {{"", io::elastic_vtu_fields(), std::move(grid)}},
                         std::nullopt};
    if (scene_.is_adaptive()) {
      const auto field =
          assembly::vector_field(operators_->vector_space(), solution->u, solution->u_rows, solution->lift);
      solved.indicators = AdaptIndicators{
          adapt::elastic_residual_indicators(setup, *solution, scene::scene_fixed_components(scene_, *d_.mesh)),
          adapt::legendre_decay(operators_->space(), field)};
    }
    return solved;
  }

  infsup::InfSupSetup infsup_setup() const override {
    return infsup_setup_of(scene_, d_.mesh.get(), d_.cell_degrees, *d_.boundary_mesh, d_.segment_degrees, *operators_);
  }
  const mesh::Mesh& operators_mesh() const override { return operators_->mesh(); }
  long long n_dofs() const override { return operators_->n_dofs(); }
  void release_factors() const override { operators_->release_factors(); }
  // The pressure's error in L²(Γ_C): the data determine it everywhere.
  std::function<double(double)> multiplier_error_weight(scene::Effect, const SceneDiscretization&) const override {
    return {};
  }
  std::optional<MaterialSummary> material() const override {
    return MaterialSummary{assembly::to_string(scene_.plane_model), scene_.young, scene_.poisson};
  }

 private:
  const scene::Scene& scene_;
  const SceneDiscretization& d_;
  const std::unique_ptr<operators::ElasticOperators> operators_;
};

}  // namespace

std::unique_ptr<Model> make_elastic_model(const scene::Scene& scene, const SceneDiscretization& d, OperatorLog* log,
                                          const linalg::Distribution& distribution) {
  return std::make_unique<ElasticModel>(scene, d, log, distribution);
}

}  // namespace hpcontact::driver
