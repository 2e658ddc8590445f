// The elastic effects of a scene and their outputs.
#include "driver/elastic_run.hpp"

#include <fmt/format.h>

#include "assembly/cell_field.hpp"
#include "contact/multiplier_distance.hpp"
#include "core/error.hpp"
#include "core/expression.hpp"
#include "core/operator_log.hpp"
#include "core/petsc_session.hpp"
#include "core/rank_agreement.hpp"
#include "core/timer.hpp"
#include "driver/run_outputs.hpp"
#include "io/atomic_file.hpp"
#include "io/vtp_writer.hpp"
#include "io/vtu_writer.hpp"
#include "mesh/cell_map.hpp"
#include "postprocess/elastic_boundary_samples.hpp"
#include "scene/scene_mesh.hpp"

namespace hpcontact::driver {

std::vector<assembly::Material> scene_materials(const scene::Scene& scene, const mesh::Mesh& mesh) {
  const Expression young(scene.young, scene.where("material.E") + ": key 'material.E'");
  const Expression poisson(scene.poisson, scene.where("material.nu") + ": key 'material.nu'");
  std::vector<assembly::Material> materials(mesh.n_cells());
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const mesh::Point x = mesh::CellMap(mesh, c).map(0.0, 0.0);
    const double e = young(x.x(), x.y()), nu = poisson(x.x(), x.y());
    const auto at = fmt::format(" at the cell centre (x, y) = ({:g}, {:g})", x.x(), x.y());
    if (!(e > 0.0) || !std::isfinite(e))
      throw_bad_input(scene.where("material.E"), "material.E", fmt::format("\"{}\" = {}{}", scene.young, e, at),
                      "a finite number > 0");
    if (!(nu > -1.0 && nu < 0.5))
      throw_bad_input(scene.where("material.nu"), "material.nu", fmt::format("\"{}\" = {}{}", scene.poisson, nu, at),
                      "a number in (-1, 0.5)");
    materials[c] = assembly::lame_parameters(e, nu, scene.plane_model);
  }
  return materials;
}

std::unique_ptr<operators::ElasticOperators> scene_elastic_operators(const scene::Scene& scene, const mesh::Mesh* mesh,
                                                                     const std::vector<int>& cell_degrees,
                                                                     OperatorLog* log,
                                                                     linalg::Distribution distribution) {
  // Evaluated where the mesh is (distributed: on the first rank at least); a bad material there
  // fails every rank alike.
  std::vector<assembly::Material> materials;
  std::array<std::vector<char>, space::kComponents> fixed;
  const auto evaluate = [&] {
    if (!mesh) return;
    materials = scene_materials(scene, *mesh);
    fixed = scene::scene_fixed_components(scene, *mesh);
  };
  if (distribution.distributed())
    run_on_all_ranks_agreeing(evaluate, distribution.ranks);
  else
    evaluate();
  return std::make_unique<operators::ElasticOperators>(mesh, cell_degrees, std::move(materials), log, fixed,
                                                       distribution);
}

namespace {

// Dirichlet data of a component need edges that fix it (Γ_D, or its rollers) to act on.
void check_dirichlet_data(const scene::Scene& scene, const operators::ElasticOperators& operators) {
  const auto& space = operators.vector_space();
  const std::array<std::pair<const char*, const std::string*>, 2> data{
      {{"boundary.u_D_x", &scene.dirichlet_x}, {"boundary.u_D_y", &scene.dirichlet_y}}};
  for (int c = 0; c < space::kComponents; ++c) {
    if (data[c].second->empty() || operators.whole_mesh().has_dirichlet()) continue;
    bool fixed = false;
    for (int d = 0; d < space.scalar().n_dofs() && !fixed; ++d) fixed = space.dof(d, c) < 0;
    if (!fixed)
      throw_bad_input(scene.where(data[c].first), data[c].first, *data[c].second,
                      fmt::format("absent: no edge fixes u_{} (neither Γ_D, boundary.dirichlet, nor a roller, "
                                  "boundary.fixed_{})",
                                  c == 0 ? 'x' : 'y', c == 0 ? 'x' : 'y'));
  }
}

}  // namespace

contact::ElasticContactSetup elastic_setup_of(const scene::Scene& scene, const SceneDiscretization& d,
                                              contact::ElasticContactProblem problem,
                                              const operators::ElasticOperators& operators) {
  contact::ElasticContactSetup setup;
  setup.operators = &operators;
  setup.boundary_mesh = d.boundary_mesh.get();
  setup.segment_degrees = d.segment_degrees;
  setup.problem = problem;
  // The tangential multiplier's box (friction) is where Remark 3 asks the most points.
  setup.constraint_points = checked_constraint_points(scene, d,
                                                      problem == contact::ElasticContactProblem::frictionless
                                                          ? contact::ContactProblem::signorini
                                                          : contact::ContactProblem::friction_s);
  const auto fx = scene_function(scene, "data.f_x", scene.body_force_x);
  const auto fy = scene_function(scene, "data.f_y", scene.body_force_y);
  setup.body_force = [fx, fy](const mesh::Point& x) { return Eigen::Vector2d(fx(x), fy(x)); };
  const auto tx = scene_function(scene, "data.t_x", scene.traction_x);
  const auto ty = scene_function(scene, "data.t_y", scene.traction_y);
  setup.traction = [tx, ty](const mesh::Point& x, const mesh::Point&) { return Eigen::Vector2d(tx(x), ty(x)); };
  setup.dirichlet = {scene_function(scene, "boundary.u_D_x", scene.dirichlet_x),
                     scene_function(scene, "boundary.u_D_y", scene.dirichlet_y)};
  check_dirichlet_data(scene, operators);
  setup.gap = scene_function(scene, "data.g", scene.obstacle);
  if (problem == contact::ElasticContactProblem::tresca) {
    const auto bound = scene_function(scene, "data.s", scene.friction_bound);
    setup.threshold = [bound, file = scene.where("data.s"), text = scene.friction_bound](const mesh::Point& x) {
      const double value = bound(x);
      if (value < 0)
        throw_bad_input(file, "data.s", fmt::format("\"{}\" = {} at (x, y) = ({}, {})", text, value, x.x(), x.y()),
                        "Tresca's threshold must be >= 0 on Γ_C");
      return value;
    };
  }
  setup.friction_coefficient = scene.friction_coefficient;
  return setup;
}

namespace {

struct ElasticEffect {
  std::string name;
  contact::ElasticContactSetup setup;
  contact::ElasticContactSolution solution;
  postprocess::ElasticBoundarySamples samples;
  double seconds = 0.0;
};

// Every elastic contact problem of the scene on one discretization, sharing `operators`.
std::vector<ElasticEffect> solve_elastic_effects(const scene::Scene& scene, const SceneDiscretization& d,
                                                 const operators::ElasticOperators& operators,
                                                 const SceneRunOptions& options, const std::string& where) {
  std::vector<ElasticEffect> effects;
  for (const auto problem : scene.elastic_effects()) {
    const std::string name = contact::to_string(problem);
    if (options.progress) options.progress("solving " + name + where);
    Stopwatch clock;
    auto setup = elastic_setup_of(scene, d, problem, operators);
    auto solution = contact::solve_elastic_contact(setup);
    const double seconds = clock.seconds();
    auto samples = postprocess::sample_elastic_boundary(setup, solution);
    effects.push_back({name, std::move(setup), std::move(solution), std::move(samples), seconds});
  }
  return effects;
}

// solution_<effect>(_level<k>): the displacement u0 + the Dirichlet lift and its von Mises stress,
// on this rank's cells; its text built when written (effect and operators must live until then).
SolutionFile elastic_solution_file(const std::string& name, const ElasticEffect& effect,
                                   const operators::ElasticOperators& operators) {
  return {name, io::elastic_vtu_fields(), [&effect, &operators] {
            const auto& solution = effect.solution;
            return io::elastic_vtu_text(
                assembly::vector_field(operators.vector_space(), solution.u, solution.u_rows, solution.lift),
                operators.materials());
          }};
}

// The convergence effect: the scene's elastic problems on `convergence_refinements` uniform
// refinements beyond its own mesh, each level with its own operators; errors of the energy and
// of the pressure (L²(Γ_C)) against the finest level. With output "vtu" every level's
// displacement goes into `level_solutions`, with one PVD per problem into `files`. Each level's
// operators go into `log`, its factors freed once its problems are solved (its files need only its
// space).
io::CsvTable elastic_convergence(const scene::Scene& scene, const SceneDiscretization& base_mesh,
                                 const operators::ElasticOperators& base_operators,
                                 const std::vector<ElasticEffect>& base, const SceneRunOptions& options,
                                 OperatorLog& log, std::vector<SolutionFile>& level_solutions,
                                 std::vector<OutputText>& files) {
  struct Level {
    std::unique_ptr<SceneDiscretization> own;
    const SceneDiscretization* d;
    std::unique_ptr<OperatorLog> log;  ///< (before `operators`, which refer to it)
    std::unique_ptr<operators::ElasticOperators> operators;
    std::vector<ElasticEffect> effects;
  };
  std::vector<Level> levels;
  levels.push_back({nullptr, &base_mesh, nullptr, nullptr, {}});
  for (int k = 1; k <= scene.convergence_refinements; ++k) {
    scene::Scene refined = scene;
    refined.refinements += k;
    Level level{discretize_scene(refined, options.distribution), nullptr, std::make_unique<OperatorLog>(), nullptr, {}};
    level.d = level.own.get();
    level.operators = scene_elastic_operators(refined, level.own->mesh.get(), level.d->cell_degrees, level.log.get(),
                                              options.distribution);
    release_whole_mesh(*level.own, level.operators->mesh());
    level.effects =
        solve_elastic_effects(refined, *level.d, *level.operators, options, fmt::format(" (convergence level {})", k));
    level.operators->release_factors();  // (records their iterations)
    append_level_log(*level.log, k, log);
    levels.push_back(std::move(level));
  }
  io::CsvTable table(refinement_columns());
  const Level& finest = levels.back();
  // (every rank builds its piece when distributed)
  const bool writes_files = scene.wants_output(scene::Output::vtu) && options.write_files;
  for (std::size_t e = 0; e < base.size(); ++e)
    for (std::size_t k = 0; k < levels.size(); ++k) {
      const auto& d = *levels[k].d;
      const auto& effect = k == 0 ? base[e] : levels[k].effects[e];
      const auto& reference = finest.effects.empty() ? base[e].solution : finest.effects[e].solution;
      table.add_row(
          {effect.name, static_cast<long long>(k), d.largest_cell_degree, largest_degree(d.segment_degrees),
           static_cast<long long>(d.contact->edges().size()), static_cast<long long>(d.boundary_mesh->n_segments()),
           static_cast<long long>(effect.solution.n_dofs), static_cast<long long>(effect.solution.lambda.size()),
           effect.solution.energy, std::abs(effect.solution.energy - reference.energy),
           contact::multiplier_l2_distance(*d.multipliers, effect.solution.pressure, *finest.d->multipliers,
                                           reference.pressure),
           effect.seconds, scene.p.label(), scene.pc.label()});
      if (writes_files)
        run_on_all_ranks_agreeing([&] {
          level_solutions.push_back(
              built_now(elastic_solution_file(level_file_name(effect.name, static_cast<int>(k)), effect,
                                              k == 0 ? base_operators : *levels[k].operators)));
        });
    }
  if (writes_files)
    for (const auto& effect : base)
      files.push_back(level_collection(effect.name, scene.convergence_refinements, options.distribution.distributed()));
  return table;
}

nlohmann::json effect_summary(const ElasticEffect& effect) {
  const auto& solution = effect.solution;
  nlohmann::json j{{"energy", solution.energy},
                   {"nmult", solution.lambda.size()},
                   {"contact_set_length", effect.samples.contact_set_length},
                   {"total_force", effect.samples.total_force},
                   {"n_trace", solution.n_trace},
                   {"solver",
                    {{"method", solution.qp.method},
                     {"converged", solution.qp.converged},
                     {"kkt_residual", solution.qp.kkt_residual},
                     {"iterations", solution.qp.iterations}}},
                   {"seconds",
                    {{"assembly", solution.seconds.assembly},
                     {"factorization", solution.seconds.factorization},
                     {"condensation", solution.seconds.condensation},
                     {"contact_qp", solution.seconds.qp},
                     {"recovery", solution.seconds.recovery},
                     {"total", effect.seconds}}}};
  if (!solution.fixed_point_changes.empty())
    j["fixed_point"] = {{"iterations", solution.fixed_point_changes.size()}, {"changes", solution.fixed_point_changes}};
  if (effect.setup.problem == contact::ElasticContactProblem::coulomb)
    j["friction_coefficient"] = effect.setup.friction_coefficient;
  const auto& zones = effect.setup.boundary_mesh->zones();
  j["zones"] = nlohmann::json::array();
  for (std::size_t z = 0; z < zones.size(); ++z)
    j["zones"].push_back({{"length", zones[z].end - zones[z].begin},
                          {"closed", zones[z].closed},
                          {"contact_set_length", effect.samples.zone_contact_set_length[z]},
                          {"total_force", effect.samples.zone_total_force[z]}});
  return j;
}

struct ExtraTables {
  const std::optional<io::CsvTable>& mode;         ///< mode.csv (effect infsup, output mode)
  const std::optional<io::CsvTable>& convergence;  ///< convergence.csv (effect convergence)
  const std::vector<OutputText>& level_files;      ///< the convergence levels' PVD files
};

// Every file but the solutions' ParaView files, into the staging folder `out` (rank 0).
void write_tables(const scene::Scene& scene, const std::vector<ElasticEffect>& effects, const ExtraTables& extra,
                  const nlohmann::json& summary, const std::filesystem::path& out) {
  for (const auto& effect : effects) write_sample_files(scene, out, effect.name, effect.samples.table);
  if (extra.mode) extra.mode->write(out / "mode.csv");
  if (extra.convergence) extra.convergence->write(out / "convergence.csv");
  for (const auto& file : extra.level_files) io::write_file_atomically(out / file.name, file.text);
  if (scene.wants_output(scene::Output::summary))
    io::write_file_atomically(out / "summary.json", summary.dump(2) + "\n");
}

}  // namespace

nlohmann::json run_elastic_scene(const scene::Scene& scene, const SceneRunOptions& options) {
  Stopwatch clock;
  // 1. Meshes, degrees and materials; the operators are built on first use and shared.
  const auto d = discretize_scene(scene, options.distribution);
  OperatorLog log;
  const auto owned = scene_elastic_operators(scene, d->mesh.get(), d->cell_degrees, &log, options.distribution);
  const operators::ElasticOperators& operators = *owned;
  // (distributed, the operators now hold the rank's part)
  if (!reads_whole_mesh_after_operators(scene)) release_whole_mesh(*d, operators.mesh());
  // 2. The contact problems.
  const std::vector<ElasticEffect> effects = solve_elastic_effects(scene, *d, operators, options, "");
  // 3. Convergence under uniform refinement, then the inf-sup constant of the elastic pairing.
  std::optional<io::CsvTable> convergence;
  std::vector<SolutionFile> solutions;
  std::vector<OutputText> level_files;
  if (scene.has_effect(scene::Effect::convergence))
    convergence = elastic_convergence(scene, *d, operators, effects, options, log, solutions, level_files);
  std::optional<io::CsvTable> mode;
  nlohmann::json infsup;
  if (scene.has_effect(scene::Effect::infsup)) {
    if (options.progress) options.progress("inf-sup constant");
    infsup = infsup_effect(
        scene, *d,
        infsup_setup_of(scene, d->mesh.get(), d->cell_degrees, *d->boundary_mesh, d->segment_degrees, operators), mode);
    release_whole_mesh(*d, operators.mesh());
  }
  // 4. The summary, then every file at once (the factorizations freed first, as in run_scene).
  operators.release_factors();
  nlohmann::json summary{
      {"scene", scene.file},
      {"p", scene.p.label()},
      {"pC", scene.pc.label()},
      {"material", {{"model", assembly::to_string(scene.plane_model)}, {"E", scene.young}, {"nu", scene.poisson}}},
      {"edges_on_contact", d->contact->edges().size()},
      {"m", d->boundary_mesh->n_segments()},
      {"ndofs", operators.n_dofs()},
      {"nmult", d->multipliers->n_dofs()}};
  for (const auto effect : scene.effects) summary["effects"].push_back(scene::to_string(effect));
  summary["operators"] = operators_summary(log);
  for (const auto& effect : effects) summary[effect.name] = effect_summary(effect);
  if (!infsup.is_null()) summary["infsup"] = infsup;
  if (convergence)
    summary["convergence"] = {{"refinements", scene.convergence_refinements}, {"file", "convergence.csv"}};
  summary["seconds_total"] = clock.seconds();
  summary["ranks"] = mpi_rank_and_size().second;
  summary["distributed_solver"] = linalg::to_string(options.distribution.solver);
  std::vector<std::pair<std::string, const io::CsvTable*>> boundary;
  if (scene.wants_output(scene::Output::boundary))
    for (const auto& effect : effects) boundary.emplace_back(effect.name, &effect.samples.table);
  hand_over_tables(options, boundary, mode, convergence);
  // The outputs as one set (rank 0 writes all but the pieces of the solutions' ParaView files; a
  // failure to write ends every rank the same way).
  if (!options.write_files) return summary;
  if (scene.wants_output(scene::Output::vtu))
    for (const auto& effect : effects)
      solutions.push_back(elastic_solution_file("solution_" + effect.name, effect, operators));
  write_run_outputs(options.out, options.distribution, solutions, [&](const std::filesystem::path& out) {
    write_tables(scene, effects, {mode, convergence, level_files}, summary, out);
  });
  return summary;
}

}  // namespace hpcontact::driver
