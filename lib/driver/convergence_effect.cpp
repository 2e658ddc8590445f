// The effect convergence: the scene's contact problems on uniform refinements beyond its mesh,
// errors of the energy and of the multiplier against the finest level.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "contact/multiplier_distance.hpp"
#include "core/rank_agreement.hpp"
#include "driver/run_stages.hpp"

namespace hpcontact::driver {
namespace {

long long largest(const std::vector<int>& degrees) { return *std::max_element(degrees.begin(), degrees.end()); }

// Level k's solutions as solution_<name>_level<k>, their arrays built now (the level's operators
// end before the files are written); every rank builds its piece when distributed.
void add_level_files(const Level& level, int k, const StageContext& context, RunFiles& files) {
  if (!context.writes_level_files) return;
  run_on_all_ranks_agreeing([&] {
    for (const auto& solved : level.solved)
      for (const auto& solution : solved.solutions)
        files.solutions.push_back(
            built_now({level_file_name(solved.name + solution.suffix, k), solution.fields, solution.grid}));
  });
}

// Level k beyond `base`: its own operators, its problems solved, then its factors freed (its
// files are built first) and its operator records added to the run's `log` under its name.
std::unique_ptr<Level> refined_level(const Level& base, int k, const StageContext& context, OperatorLog& log,
                                     RunFiles& files) {
  scene::Scene scene = base.scene;
  scene.refinements += k;
  auto level = discretize(scene, context);
  build_operators(*level, &level->log, context, false);
  solve_contact_problems(*level, context, fmt::format(" (convergence level {})", k));
  add_level_files(*level, k, context, files);
  level->model->release_factors();  // (records their iterations)
  for (auto record : level->log.records()) {
    record.name = fmt::format("{} (convergence level {})", record.name, k);
    log.append(std::move(record));
  }
  // Only the results, the meshes and the multipliers are read from here on.
  for (auto& solved : level->solved) solved.solutions.clear();
  level->model.reset();
  return level;
}

ConvergenceRow convergence_row(const Level& base, const Level& level, int k, std::size_t problem, const Level& finest) {
  const auto& d = *level.d;
  const auto& solved = level.solved[problem];
  const auto& reference = finest.solved[problem];
  const auto& r = solved.result;
  return {r.problem,
          k,
          d.largest_cell_degree,
          largest(d.segment_degrees),
          static_cast<long long>(d.contact->edges().size()),
          d.boundary_mesh->n_segments(),
          r.n_dofs,
          r.nmult,
          r.energy,
          std::abs(r.energy - reference.result.energy),
          contact::multiplier_l2_distance(
              *d.multipliers, solved.error_multiplier, *finest.d->multipliers, reference.error_multiplier,
              base.model->multiplier_error_weight(base.model->problems()[problem], *finest.d)),
          r.seconds.total,
          base.scene.p.label(),
          base.scene.pc.label()};
}

}  // namespace

std::vector<ConvergenceRow> refine_and_repeat(const Level& base, const StageContext& context, OperatorLog& log,
                                              RunFiles& files) {
  add_level_files(base, 0, context, files);
  std::vector<std::unique_ptr<Level>> refined;
  for (int k = 1; k <= base.scene.convergence_refinements; ++k)
    refined.push_back(refined_level(base, k, context, log, files));
  std::vector<const Level*> levels{&base};
  for (const auto& level : refined) levels.push_back(level.get());
  std::vector<ConvergenceRow> rows;
  for (std::size_t problem = 0; problem < base.solved.size(); ++problem)
    for (std::size_t k = 0; k < levels.size(); ++k)
      rows.push_back(convergence_row(base, *levels[k], static_cast<int>(k), problem, *levels.back()));
  if (context.writes_level_files)
    for (const auto& solved : base.solved)
      files.texts.push_back(
          level_collection(solved.name, base.scene.convergence_refinements, context.distribution.distributed()));
  return rows;
}

}  // namespace hpcontact::driver
