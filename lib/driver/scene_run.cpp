// The run pipeline: a scene's effects in stages (run_stages.hpp), its result, its files.
#include "driver/scene_run.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/petsc_session.hpp"
#include "core/timer.hpp"
#include "driver/adaptive_run.hpp"
#include "driver/free_boundary_fit.hpp"
#include "driver/pairing_stability.hpp"
#include "driver/run_outputs.hpp"
#include "driver/run_stages.hpp"
#include "driver/solid_run.hpp"
#include "driver/summary_json.hpp"
#include "io/atomic_file.hpp"

namespace hpcontact::driver {
namespace {

// 0. The scene with its mesh graded towards the free boundary of its contact problems.
scene::Scene fitted_scene(const scene::Scene& scene, const StageContext& context, RunResult& result) {
  context.say("fitting the mesh to the free boundary");
  Stopwatch clock;
  const auto fit = context.distribution.distributed()
                       ? fit_free_boundary_once(scene, scene.contact_effects(), context.distribution.ranks)
                       : fit_free_boundary(scene, scene.contact_effects());
  result.free_boundary = FreeBoundarySummary{fit.points, fit.solves, fit.moved, clock.seconds()};
  return fit.scene;
}

// 1–3. An adaptive scene's level: the last of its adaptive steps, solved (serial).
std::unique_ptr<Level> adapted_level(const scene::Scene& scene, const StageContext& context, RunResult& result) {
  if (context.distribution.distributed())
    throw InputError(scene.file + ": an adaptive scene (adapt.target given) runs serially: run it without mpirun");
  context.say("adapting T_h and T_{C,H}");
  auto adapted = adapt_level(scene, context.progress);
  result.adapt = std::move(adapted.summary);
  const auto& last = result.adapt->steps.back();
  if (result.adapt->stopped != "target")
    context.say(
        fmt::format("warning: the adaptivity stopped at {} with the estimate {:.3g} above adapt.target = {:.3g}",
                    result.adapt->stopped == "max_steps" ? "adapt.max_steps" : "adapt.max_unknowns", last.estimate,
                    result.adapt->target));
  return std::move(adapted.level);
}

// What the result says of the run as a whole: the scene, its discretization, the operators built.
void describe_run(const Level& base, const OperatorLog& log, const linalg::Distribution& distribution,
                  RunResult& result) {
  const auto& scene = base.scene;
  result.scene = scene.file;
  for (const auto effect : scene.effects) result.effects.push_back(scene::to_string(effect));
  result.p = scene.p.label();
  result.pc = scene.pc.label();
  result.family = space::to_string(scene.family);
  result.material = base.model->material();
  result.edges_on_contact = static_cast<long long>(base.d->contact->edges().size());
  result.m = base.d->boundary_mesh->n_segments();
  result.n_dofs = base.model->n_dofs();
  result.nmult = space::multiplier_function_count(*base.d->multipliers, scene.family);
  result.operators = log.records();
  for (const auto& solved : base.solved) result.contacts.push_back(solved.result);
  result.convergence_refinements = scene.convergence_refinements;
  result.ranks = mpi_rank_and_size().second;
  result.distributed_solver = linalg::to_string(distribution.solver);
}

// Every table the run writes, to options.tables (the Python module's arrays).
void hand_over_tables(const Level& base, const RunResult& result, const RunFiles& files,
                      const SceneRunOptions& options) {
  if (!options.tables) return;
  if (base.scene.wants_output(scene::Output::boundary))
    for (const auto& solved : base.solved) options.tables->insert_or_assign("boundary_" + solved.name, solved.samples);
  if (files.mode) options.tables->insert_or_assign("mode", *files.mode);
  if (!result.convergence.empty())
    options.tables->insert_or_assign("convergence", convergence_table(result.convergence));
}

// Every solution's VTU arrays, to options.fields (the Python module's fields).
void hand_over_fields(const Level& base, const SceneRunOptions& options) {
  if (!options.fields || !base.scene.wants_output(scene::Output::vtu)) return;
  for (const auto& solved : base.solved)
    for (const auto& solution : solved.solutions)
      options.fields->insert_or_assign(solved.name + solution.suffix, solution.grid());
}

// 6. The outputs as one set: rank 0 writes all but the pieces of the solutions' ParaView files; a
// failure to write ends every rank the same way.
void write_outputs(const Level& base, const RunResult& result, RunFiles& files, const SceneRunOptions& options) {
  const auto& scene = base.scene;
  if (scene.wants_output(scene::Output::vtu))
    for (const auto& solved : base.solved)
      for (const auto& solution : solved.solutions)
        files.solutions.push_back({"solution_" + solved.name + solution.suffix, solution.fields, solution.grid});
  write_run_outputs(options.out, options.distribution, files.solutions, [&](const std::filesystem::path& out) {
    for (const auto& solved : base.solved) write_sample_files(scene, out, solved.name, solved.samples);
    for (const auto& file : files.texts) io::write_file_atomically(out / file.name, file.text);
    if (files.mode) files.mode->write(out / "mode.csv");
    if (!result.convergence.empty()) convergence_table(result.convergence).write(out / "convergence.csv");
    if (result.adapt) adapt_table(*result.adapt).write(out / "adapt.csv");
    if (scene.wants_output(scene::Output::summary))
      io::write_file_atomically(out / "summary.json", summary_json(result));
  });
}

}  // namespace

RunResult run_scene(const scene::Scene& given_scene, const SceneRunOptions& options) {
  // A box of hexahedra has its own discretization; the outputs are the same files.
  if (given_scene.dimension() == 3) return run_solid_scene(given_scene, options);
  Stopwatch clock;
  const StageContext context{options.distribution, options.progress,
                             given_scene.wants_output(scene::Output::vtu) && options.write_files};
  RunResult result;
  OperatorLog log;
  RunFiles files;
  // 0. Optionally the mesh graded towards the free boundary; the effects then run on that mesh.
  const scene::Scene scene = given_scene.fit_free_boundary ? fitted_scene(given_scene, context, result) : given_scene;
  // 1. Meshes and degrees (an adaptive scene's: adapted). 2. The model's operators, built on first
  //    use and shared by the effects.
  const auto base = scene.is_adaptive() ? adapted_level(scene, context, result) : discretize(scene, context);
  if (!base->model) build_operators(*base, &log, context, reads_whole_mesh_after_operators(scene));
  throw_if_cancelled();  // (a cancellation point between stages: core/interrupt.hpp)
  // 2b. Whether the pairing is stable, predicted before anything is solved: a refused run stops
  //     here, a warned one is told before its time is spent.
  if (!scene.contact_effects().empty() || !scene.elastic_effects().empty() || scene.has_effect(scene::Effect::infsup)) {
    result.stability = predict_stability(scene, *base->d, base->model->master_projection());
    act_on_stability(scene, *result.stability, context.progress);
  }
  // 3. The contact problems (an adaptive level's solved already).
  if (base->solved.empty()) solve_contact_problems(*base, context, "");
  throw_if_cancelled();
  // 4. The inf-sup constant of the pairing: whether λ is unique.
  if (scene.has_effect(scene::Effect::infsup)) result.infsup = analyse_infsup(*base, context, files.mode);
  throw_if_cancelled();
  // 5. Convergence under uniform refinement of every contact problem.
  if (scene.has_effect(scene::Effect::convergence)) result.convergence = refine_and_repeat(*base, context, log, files);
  // 6. The result, then every file at once (the factorizations freed first: the solutions'
  //    ParaView text is built beside them otherwise).
  base->model->release_factors();
  describe_run(*base, scene.is_adaptive() ? base->log : log, options.distribution, result);
  result.seconds_total = clock.seconds();
  hand_over_tables(*base, result, files, options);
  hand_over_fields(*base, options);
  if (options.write_files) write_outputs(*base, result, files, options);
  return result;
}

io::CsvTable convergence_table(const std::vector<ConvergenceRow>& rows) {
  io::CsvTable table({"problem", "level", "p", "pC", "n", "m", "ndofs", "nmult", "energy", "error_energy",
                      "error_lambda", "seconds", "p_rule", "pC_rule"});
  for (const auto& r : rows)
    table.add_row({r.problem, static_cast<long long>(r.level), r.p, r.pc, r.n, r.m, r.n_dofs, r.nmult, r.energy,
                   r.error_energy, r.error_lambda, r.seconds, r.p_rule, r.pc_rule});
  return table;
}

}  // namespace hpcontact::driver
