// The effects of a scene and their outputs.
#include "driver/scene_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "assembly/cell_field.hpp"
#include "contact/multiplier_distance.hpp"
#include "core/error.hpp"
#include "core/operator_log.hpp"
#include "core/petsc_session.hpp"
#include "core/rank_agreement.hpp"
#include "core/timer.hpp"
#include "driver/elastic_run.hpp"
#include "driver/free_boundary_fit.hpp"
#include "driver/run_outputs.hpp"
#include "infsup/infsup_analysis.hpp"
#include "io/atomic_file.hpp"
#include "io/csv_writer.hpp"
#include "io/vtk_xml_document.hpp"
#include "io/vtp_writer.hpp"
#include "io/vtu_writer.hpp"
#include "postprocess/boundary_samples.hpp"
#include "postprocess/mode_samples.hpp"

namespace hpcontact::driver {
namespace {

struct ContactEffect {
  std::string problem;  ///< the effect's name, e.g. "friction_s"
  contact::ContactProblem kind;
  contact::ContactSetup setup;
  contact::ContactSolution solution;
  postprocess::BoundarySamples samples;
  double seconds = 0.0;
};

nlohmann::json contact_summary(const ContactEffect& effect) {
  const auto& solution = effect.solution;
  nlohmann::json j;
  j["energy"] = solution.energy;
  j["nmult"] = solution.lambda.size();
  j["contact_set_length"] = effect.samples.contact_set_length;
  j["zones"] = nlohmann::json::array();
  const auto& zones = effect.setup.boundary_mesh->zones();
  for (std::size_t z = 0; z < zones.size(); ++z)
    j["zones"].push_back({{"length", zones[z].end - zones[z].begin},
                          {"closed", zones[z].closed},
                          {"contact_set_length", effect.samples.zone_contact_set_length[z]}});
  const auto& q = solution.constraint_points;
  j["constraint_points_per_segment"] = {{"min", *std::min_element(q.begin(), q.end())},
                                        {"max", *std::max_element(q.begin(), q.end())},
                                        {"total", solution.constraint_s.size()}};
  j["solver"] = {{"method", solution.qp.method},
                 {"converged", solution.qp.converged},
                 {"kkt_residual", solution.qp.kkt_residual},
                 {"iterations", solution.qp.iterations},
                 {"proximal_steps", solution.qp.proximal_steps}};
  if (!solution.qp.fallback_reason.empty()) j["solver"]["fallback_reason"] = solution.qp.fallback_reason;
  for (const auto& step : solution.qp.log)
    j["solver"]["log"].push_back({{"iteration", step.iteration},
                                  {"active_set_changes", step.active_set_changes},
                                  {"kkt_residual", step.kkt_residual}});
  j["n_trace"] = solution.n_trace;
  j["seconds"] = {{"assembly", solution.seconds.assembly},         {"factorization", solution.seconds.factorization},
                  {"condensation", solution.seconds.condensation}, {"contact_qp", solution.seconds.qp},
                  {"recovery", solution.seconds.recovery},         {"total", effect.seconds}};
  return j;
}

// Every contact problem of the scene on one discretization, sharing `primal`.
std::vector<ContactEffect> solve_contact_effects(const scene::Scene& scene, const SceneDiscretization& d,
                                                 const operators::PrimalOperators& primal,
                                                 const SceneRunOptions& options, const std::string& where) {
  std::vector<ContactEffect> effects;
  for (const auto problem : scene.contact_effects()) {
    const std::string name = scene::to_string(scene::effect_of(problem));
    if (options.progress) options.progress("solving " + name + where);
    Stopwatch clock;
    auto setup = contact_setup_of(scene, d, problem, primal);
    auto solution = contact::solve_contact(setup);
    const double seconds = clock.seconds();
    auto samples = postprocess::sample_boundary(setup, solution);
    effects.push_back({name, problem, std::move(setup), std::move(solution), std::move(samples), seconds});
  }
  return effects;
}

// solution_<problem>(_level<k>): u = u0 + the Dirichlet lift on Ω, on this rank's cells; its text
// built when written (effect and primal must live until then).
SolutionFile solution_file(const std::string& name, const ContactEffect& effect,
                           const operators::PrimalOperators& primal) {
  return {name, io::solution_vtu_fields(), [&effect, &primal] {
            const auto& solution = effect.solution;
            return io::solution_vtu_text(
                assembly::scalar_field(primal.space(), solution.u, solution.u_rows, solution.lift));
          }};
}

// Whether the run writes the convergence levels' VTU files: output "vtu" and files wanted (every
// rank builds its piece when distributed).
bool writes_level_files(const scene::Scene& scene, const SceneRunOptions& options) {
  return scene.wants_output(scene::Output::vtu) && options.write_files;
}

// With output "vtu": every level's u as solution_<problem>_level<k> and one PVD per problem
// (the level as ParaView's time), so the refinement sequence plays as an animation.
void add_level_solutions(const scene::Scene& scene, const std::vector<ContactEffect>& effects,
                         const operators::PrimalOperators& primal, const SceneRunOptions& options, int level,
                         std::vector<SolutionFile>& files) {
  if (!writes_level_files(scene, options)) return;
  run_on_all_ranks_agreeing([&] {
    for (const auto& effect : effects)
      files.push_back(built_now(solution_file(level_file_name(effect.problem, level), effect, primal)));
  });
}

// The convergence effect: the scene's contact problems on `convergence_refinements` uniform
// refinements beyond its own mesh, each level with its own operators shared by its problems; the
// finest level is the reference for the errors of the others.
void add_convergence_rows(const scene::Scene& scene, const std::vector<ContactEffect>& base,
                          const SceneDiscretization& base_mesh, const operators::PrimalOperators& base_primal,
                          const SceneRunOptions& options, OperatorLog& log, io::CsvTable& table,
                          std::vector<SolutionFile>& level_solutions, std::vector<OutputText>& files) {
  struct Level {
    const SceneDiscretization* discretization;
    const std::vector<ContactEffect>* effects;
  };
  std::vector<Level> levels{{&base_mesh, &base}};
  std::vector<std::unique_ptr<SceneDiscretization>> refined_meshes;
  std::vector<std::unique_ptr<std::vector<ContactEffect>>> refined_effects;
  add_level_solutions(scene, base, base_primal, options, 0, level_solutions);
  for (int k = 1; k <= scene.convergence_refinements; ++k) {
    scene::Scene refined = scene;
    refined.refinements += k;
    auto d = discretize_scene(refined, options.distribution);
    OperatorLog level_log;
    const operators::PrimalOperators primal(d->mesh.get(), d->cell_degrees, &level_log, options.distribution);
    release_whole_mesh(*d, primal.mesh());
    refined_effects.push_back(std::make_unique<std::vector<ContactEffect>>(
        solve_contact_effects(refined, *d, primal, options, fmt::format(" (convergence level {})", k))));
    add_level_solutions(scene, *refined_effects.back(), primal, options, k, level_solutions);
    primal.release_factors();  // (records their iterations)
    append_level_log(level_log, k, log);
    levels.push_back({d.get(), refined_effects.back().get()});
    refined_meshes.push_back(std::move(d));
  }
  const Level& finest = levels.back();
  for (std::size_t e = 0; e < finest.effects->size(); ++e)
    for (std::size_t k = 0; k < levels.size(); ++k) {
      const auto& d = *levels[k].discretization;
      const auto& effect = (*levels[k].effects)[e];
      const auto& reference = (*finest.effects)[e].solution;
      table.add_row(
          {effect.problem, static_cast<long long>(k), d.largest_cell_degree, largest_degree(d.segment_degrees),
           static_cast<long long>(d.contact->edges().size()), static_cast<long long>(d.boundary_mesh->n_segments()),
           static_cast<long long>(effect.solution.n_dofs), static_cast<long long>(effect.solution.lambda.size()),
           effect.solution.energy, std::abs(effect.solution.energy - reference.energy),
           contact::multiplier_l2_distance(*d.multipliers, effect.solution.lambda_legendre,
                                           *finest.discretization->multipliers, reference.lambda_legendre,
                                           multiplier_error_weight(scene, *finest.discretization, effect.kind)),
           effect.seconds, scene.p.label(), scene.pc.label()});
    }
  if (writes_level_files(scene, options))
    for (const auto& effect : base)
      files.push_back(
          level_collection(effect.problem, scene.convergence_refinements, options.distribution.distributed()));
}

// The scene with its mesh graded towards the free boundary of its contact problems; what the fit
// found goes into `free_boundary` for summary.json.
scene::Scene fitted_scene(const scene::Scene& scene, const linalg::Distribution& distribution,
                          const std::function<void(const std::string&)>& say, nlohmann::json& free_boundary) {
  say("fitting the mesh to the free boundary");
  Stopwatch clock;
  const auto fit = distribution.distributed()
                       ? fit_free_boundary_once(scene, scene.contact_effects(), distribution.ranks)
                       : fit_free_boundary(scene, scene.contact_effects());
  free_boundary = {
      {"points", nlohmann::json::array()}, {"rounds", fit.solves}, {"moved", fit.moved}, {"seconds", clock.seconds()}};
  for (const auto& point : fit.points) free_boundary["points"].push_back({point.x(), point.y()});
  return fit.scene;
}

// What summary.json says of the run as a whole: the scene, its discretization, the operators built.
void add_run_summary(const scene::Scene& scene, const SceneDiscretization& d, const operators::PrimalOperators& primal,
                     const OperatorLog& log, nlohmann::json& summary) {
  summary["scene"] = scene.file;
  for (const auto effect : scene.effects) summary["effects"].push_back(scene::to_string(effect));
  summary["p"] = scene.p.label();
  summary["pC"] = scene.pc.label();
  summary["edges_on_contact"] = d.contact->edges().size();
  summary["m"] = d.boundary_mesh->n_segments();
  summary["ndofs"] = primal.space().n_dofs();
  summary["nmult"] = d.multipliers->n_dofs();
  summary["operators"] = operators_summary(log);
}

}  // namespace

nlohmann::json infsup_effect(const scene::Scene& scene, const SceneDiscretization& d, const infsup::InfSupSetup& setup,
                             std::optional<io::CsvTable>& mode) {
  const auto alpha = infsup::analyse_infsup(setup, infsup::EigenBackend::slepc);
  if (scene.wants_output(scene::Output::mode)) mode = postprocess::sample_mode(*d.contact, *d.multipliers, alpha.mode);
  nlohmann::json j{{"alpha", alpha.alpha},
                   {"alpha_error", alpha.alpha_error},
                   {"alpha_converged", alpha.alpha_converged},
                   {"reference_level", alpha.reference_level},
                   {"lambda_unique", !alpha.singular},
                   {"problem", infsup::to_string(scene.problem)},
                   {"norm", infsup::to_string(scene.norm)},
                   {"lambda_min", alpha.lambda_min},
                   {"lambda_max", alpha.lambda_max},
                   {"Pi", alpha.pi},
                   {"eigensolver", alpha.method},
                   {"residual", alpha.residual},
                   {"seconds", alpha.seconds}};
  if (setup.elastic) j["primal_norm"] = operators::to_string(setup.primal_norm);
  if (!alpha.zone_alpha.empty()) j["zone_alpha"] = alpha.zone_alpha;
  return j;
}

nlohmann::json operators_summary(const OperatorLog& log) {
  nlohmann::json operators = nlohmann::json::array();
  for (const auto& record : log.records()) {
    operators.push_back(
        {{"name", record.name}, {"rows", record.rows}, {"cols", record.cols}, {"seconds", record.seconds}});
    if (record.solves > 0)
      operators.back()["iterations"] = {
          {"solves", record.solves}, {"total", record.iterations}, {"most", record.most_iterations}};
  }
  return operators;
}

long long largest_degree(const std::vector<int>& degrees) { return *std::max_element(degrees.begin(), degrees.end()); }

void write_sample_files(const scene::Scene& scene, const std::filesystem::path& folder, const std::string& name,
                        const io::CsvTable& samples) {
  if (scene.wants_output(scene::Output::boundary)) samples.write(folder / ("boundary_" + name + ".csv"));
  if (scene.wants_output(scene::Output::vtu))
    io::write_file_atomically(folder / ("contact_" + name + ".vtp"), io::polyline_vtp_text(samples));
}

std::string level_file_name(const std::string& problem, int level) {
  return fmt::format("solution_{}_level{}", problem, level);
}

OutputText level_collection(const std::string& problem, int finest, bool distributed) {
  std::vector<io::PvdEntry> entries;
  for (int k = 0; k <= finest; ++k)
    entries.push_back({static_cast<double>(k), solution_file_name(level_file_name(problem, k), distributed)});
  return {"solution_" + problem + ".pvd", io::pvd_text(entries)};
}

void append_level_log(const OperatorLog& level_log, int level, OperatorLog& log) {
  for (auto record : level_log.records()) {
    record.name = fmt::format("{} (convergence level {})", record.name, level);
    log.append(std::move(record));
  }
}

std::vector<std::string> refinement_columns() {
  return {"problem",      "level",        "p",       "pC",     "n",      "m", "ndofs", "nmult", "energy",
          "error_energy", "error_lambda", "seconds", "p_rule", "pC_rule"};
}

void hand_over_tables(const SceneRunOptions& options,
                      const std::vector<std::pair<std::string, const io::CsvTable*>>& boundary,
                      const std::optional<io::CsvTable>& mode, const std::optional<io::CsvTable>& convergence) {
  if (!options.tables) return;
  for (const auto& [problem, table] : boundary) options.tables->insert_or_assign("boundary_" + problem, *table);
  if (mode) options.tables->insert_or_assign("mode", *mode);
  if (convergence) options.tables->insert_or_assign("convergence", *convergence);
}

nlohmann::json run_scene(const scene::Scene& given_scene, const SceneRunOptions& options) {
  if (given_scene.is_elastic()) return run_elastic_scene(given_scene, options);
  Stopwatch clock;
  auto say = [&](const std::string& line) {
    if (options.progress) options.progress(line);
  };
  // 0. Optionally, the mesh graded towards the free boundary of every contact problem of the
  //    scene; the effects then run on that mesh.
  nlohmann::json free_boundary;
  const scene::Scene scene =
      given_scene.fit_free_boundary ? fitted_scene(given_scene, options.distribution, say, free_boundary) : given_scene;
  // 1. Meshes and degrees; the operators of S^p(T_h) are built on first use and shared.
  const auto d = discretize_scene(scene, options.distribution);
  OperatorLog log;
  const operators::PrimalOperators primal(d->mesh.get(), d->cell_degrees, &log, options.distribution);
  // (distributed, the operators now hold the rank's part)
  if (!reads_whole_mesh_after_operators(scene)) release_whole_mesh(*d, primal.mesh());

  // 2. The contact problems.
  const std::vector<ContactEffect> contacts = solve_contact_effects(scene, *d, primal, options, "");

  // 3. The inf-sup constant of the pairing: whether λ is unique.
  nlohmann::json summary;
  std::optional<io::CsvTable> mode;
  if (scene.has_effect(scene::Effect::infsup)) {
    say("inf-sup constant");
    summary["infsup"] = infsup_effect(
        scene, *d,
        infsup_setup_of(scene, d->mesh.get(), d->cell_degrees, *d->boundary_mesh, d->segment_degrees, primal), mode);
    release_whole_mesh(*d, primal.mesh());
  }

  // 4. Convergence under uniform refinement of every contact problem of the scene.
  std::optional<io::CsvTable> convergence;
  std::vector<SolutionFile> solutions;
  std::vector<OutputText> level_files;
  if (scene.has_effect(scene::Effect::convergence)) {
    convergence.emplace(refinement_columns());
    add_convergence_rows(scene, contacts, *d, primal, options, log, *convergence, solutions, level_files);
  }

  // 5. The summary, then every file at once (the factorizations freed first: the solutions'
  //    ParaView text is built beside them otherwise).
  primal.release_factors();
  add_run_summary(scene, *d, primal, log, summary);
  if (!free_boundary.is_null()) summary["free_boundary"] = free_boundary;
  for (const auto& effect : contacts) summary[effect.problem] = contact_summary(effect);
  if (convergence)
    summary["convergence"] = {{"refinements", scene.convergence_refinements}, {"file", "convergence.csv"}};
  summary["seconds_total"] = clock.seconds();
  summary["ranks"] = mpi_rank_and_size().second;
  summary["distributed_solver"] = linalg::to_string(options.distribution.solver);
  std::vector<std::pair<std::string, const io::CsvTable*>> boundary;
  if (scene.wants_output(scene::Output::boundary))
    for (const auto& effect : contacts) boundary.emplace_back(effect.problem, &effect.samples.table);
  hand_over_tables(options, boundary, mode, convergence);
  // 5. The outputs as one set (rank 0 writes all but the pieces of the solutions' ParaView files;
  //    a failure to write ends every rank the same way).
  if (!options.write_files) return summary;
  if (scene.wants_output(scene::Output::vtu))
    for (const auto& effect : contacts)
      solutions.push_back(solution_file("solution_" + effect.problem, effect, primal));
  write_run_outputs(options.out, options.distribution, solutions, [&](const std::filesystem::path& out) {
    for (const auto& effect : contacts) write_sample_files(scene, out, effect.problem, effect.samples.table);
    for (const auto& file : level_files) io::write_file_atomically(out / file.name, file.text);
    if (mode) mode->write(out / "mode.csv");
    if (convergence) convergence->write(out / "convergence.csv");
    if (scene.wants_output(scene::Output::summary))
      io::write_file_atomically(out / "summary.json", summary.dump(2) + "\n");
  });
  return summary;
}

}  // namespace hpcontact::driver
