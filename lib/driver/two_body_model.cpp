// The two-body model: both bodies' operators, the pair's contact problems and their outputs.
#include "driver/two_body_model.hpp"

#include "assembly/cell_field.hpp"
#include "contact/two_body_contact.hpp"
#include "core/error.hpp"
#include "core/timer.hpp"
#include "driver/elastic_model.hpp"
#include "driver/elastic_scene.hpp"
#include "driver/exact_check.hpp"
#include "io/vtu_writer.hpp"
#include "mesh/contact_pair_geometry.hpp"
#include "postprocess/elastic_boundary_samples.hpp"

namespace hpcontact::driver {
namespace {

class TwoBodyModel final : public Model {
 public:
  TwoBodyModel(const scene::Scene& scene, const SceneDiscretization& d, OperatorLog* log)
      : scene_(scene),
        d_(d),
        master_mesh_(build_scene_mesh_on_first_rank(scene.pair->master, {})),
        slave_(scene_elastic_operators(scene, d.mesh.get(), d.cell_degrees, log)),
        master_(scene_elastic_operators(scene.pair->master, master_mesh_.mesh.get(), master_mesh_.cell_degrees, log)),
        projection_(master_->contact()) {}

  std::vector<scene::Effect> problems() const override { return elastic_problem_effects(scene_); }

  SolvedProblem solve(scene::Effect effect) const override {
    Stopwatch clock;
    const auto problem = *scene::elastic_problem_of(effect);
    contact::TwoBodyContactSetup setup;
    setup.slave = elastic_setup_of(scene_, d_, problem, *slave_);
    setup.master = elastic_body_of(scene_.pair->master, *master_);
    auto solution = std::make_shared<const contact::TwoBodyContactSolution>(contact::solve_two_body_contact(setup));
    const double seconds = clock.seconds();
    auto samples = postprocess::sample_pair_boundary(setup, *solution, projection_);
    ContactResult result = elastic_result(setup.slave, solution->contact, samples, seconds);
    result.n_dofs += solution->master.n_dofs;
    result.pair = PairSummary{scene_.pair->name, scene_.body, scene_.pair->master.body};
    const auto& u_s = solution->contact;
    const auto& u_m = solution->master;
    result.exact = exact_errors_of(
        {{&scene_, assembly::vector_field(slave_->vector_space(), u_s.u, u_s.u_rows, u_s.lift), &slave_->mesh()},
         {&scene_.pair->master, assembly::vector_field(master_->vector_space(), u_m.u, u_m.u_rows, u_m.lift),
          &master_->mesh()}},
        setup.slave, u_s.pressure, {});
    // Each body's displacement u0 + its Dirichlet lift, its stress and von Mises stress, a file each.
    auto slave_grid = [this, solution] {
      const auto& u = solution->contact;
      return io::elastic_vtu_grid(assembly::vector_field(slave_->vector_space(), u.u, u.u_rows, u.lift),
                                  slave_->materials());
    };
    auto master_grid = [this, solution] {
      const auto& u = solution->master;
      return io::elastic_vtu_grid(assembly::vector_field(master_->vector_space(), u.u, u.u_rows, u.lift),
                                  master_->materials());
    };
    return {std::move(result),
            scene_.pair->name + "_" + scene::to_string(effect),
            std::move(samples.table),
            solution->contact.pressure,
            {{"_" + scene_.body, io::elastic_vtu_fields(), std::move(slave_grid)},
             {"_" + scene_.pair->master.body, io::elastic_vtu_fields(), std::move(master_grid)}}};
  }

  // b(μ, v) = ∫ μ (v_s − v_m∘Φ)·n_s on both bodies' displacements, μ in H^{-1/2} of the slave's Γ_C.
  infsup::InfSupSetup infsup_setup() const override {
    auto setup =
        infsup_setup_of(scene_, d_.mesh.get(), d_.cell_degrees, *d_.boundary_mesh, d_.segment_degrees, *slave_);
    setup.master = master_.get();
    setup.projection = &projection_;
    return setup;
  }
  const mesh::Mesh& operators_mesh() const override { return slave_->mesh(); }
  const mesh::MasterProjection* master_projection() const override { return &projection_; }
  long long n_dofs() const override { return slave_->n_dofs() + master_->n_dofs(); }
  void release_factors() const override {
    slave_->release_factors();
    master_->release_factors();
  }
  std::function<double(double)> multiplier_error_weight(scene::Effect, const SceneDiscretization&) const override {
    return {};
  }

 private:
  const scene::Scene& scene_;
  const SceneDiscretization& d_;
  /// The master's T_h and degrees only: T_{C,H} and the multiplier live on the slave's Γ_C.
  const SceneMesh master_mesh_;
  const std::unique_ptr<operators::ElasticOperators> slave_, master_;
  const mesh::MasterProjection projection_;  ///< onto the master's Γ_C
};

}  // namespace

std::unique_ptr<Model> make_two_body_model(const scene::Scene& scene, const SceneDiscretization& d, OperatorLog* log,
                                           const linalg::Distribution& distribution) {
  if (distribution.distributed())
    throw InputError(scene.file + ": a two-body scene runs serially for now; run it without mpirun");
  return std::make_unique<TwoBodyModel>(scene, d, log);
}

}  // namespace hpcontact::driver
