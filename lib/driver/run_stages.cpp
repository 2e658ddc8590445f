// The stages of a run that work on one level: discretize, build operators, solve, analyse α.
#include "driver/run_stages.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <variant>

#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "driver/pairing_stability.hpp"
#include "postprocess/mode_samples.hpp"

namespace hpcontact::driver {

std::unique_ptr<Level> discretize(const scene::Scene& scene, const StageContext& context) {
  auto level = std::make_unique<Level>();
  level->scene = scene;
  level->d = discretize_scene(level->scene, context.distribution);
  return level;
}

void build_operators(Level& level, OperatorLog* log, const StageContext& context, bool keep_whole_mesh) {
  level.model = build_model(level.scene, *level.d, log, context.distribution);
  // Distributed, the operators now hold the rank's part: nothing else needs the whole mesh.
  if (!keep_whole_mesh) release_whole_mesh(*level.d, level.model->operators_mesh());
}

namespace {

// A solve whose numbers overflowed (data near 1e154 square to infinity in the energy) is a
// numerical failure, not a result: the energy and every sample must be finite.
void check_finite(const SolvedProblem& solved, const std::string& where) {
  bool finite = std::isfinite(solved.result.energy);
  for (const auto& row : solved.samples.rows())
    for (const auto& cell : row)
      if (const auto* value = std::get_if<double>(&cell)) finite = finite && std::isfinite(*value);
  if (!finite)
    throw NumericalError(fmt::format(
        "the {} solve{} gave non-finite numbers (energy = {}): the data overflow double precision (a load, gap or "
        "bound near 1e150 squares to infinity); scale the problem (its units) so that f, g, s and E stay far from "
        "1e150",
        solved.name, where, solved.result.energy));
}

}  // namespace

void solve_contact_problems(Level& level, const StageContext& context, const std::string& where) {
  for (const auto problem : level.model->problems()) {
    throw_if_cancelled();
    context.say("solving " + scene::to_string(problem) + where);
    level.solved.push_back(level.model->solve(problem));
    check_finite(level.solved.back(), where);
  }
}

InfSupSummary infsup_summary(const Level& level, const infsup::InfSupSetup& setup, const infsup::InfSupResult& alpha) {
  const auto& d = *level.d;
  const int n = static_cast<int>(d.contact->edges().size());
  // For degree rules the worst case, as in Π: the smallest p, the largest p_C.
  const infsup::PairingFacts pairing{
      .problem = setup.problem,
      .norm = setup.norm,
      .family = setup.family,
      .p = d.smallest_cell_degree,
      .pc = *std::max_element(d.segment_degrees.begin(), d.segment_degrees.end()),
      .level = 1,
      .n = n,
      .m = d.boundary_mesh->n_segments(),
      .h_min = infsup::shortest_contact_edge(*d.contact),
      .ratio = level.scene.ratio.size() == 1 ? std::optional<double>(level.scene.ratio.front().value) : std::nullopt};
  InfSupSummary s;
  s.record = infsup::make_infsup_record(pairing, alpha);
  s.record.alpha_predicted =
      infsup::predict_alpha(trace_pairing_of(level.scene, *d.contact, d.held_zone_ends, *d.boundary_mesh,
                                             d.segment_degrees, level.model->master_projection(), d.trace_degrees))
          .alpha;
  s.reference_level = alpha.reference_level;
  s.lambda_unique = !alpha.singular;
  if (setup.elastic) s.primal_norm = operators::to_string(setup.primal_norm);
  s.lambda_min = alpha.lambda_min;
  s.lambda_max = alpha.lambda_max;
  s.eigensolver = alpha.method;
  s.residual = alpha.residual;
  s.zone_alpha = alpha.zone_alpha;
  return s;
}

InfSupSummary analyse_infsup(Level& level, const StageContext& context, std::optional<io::CsvTable>& mode) {
  context.say("inf-sup constant");
  const auto setup = level.model->infsup_setup();
  const auto alpha = infsup::analyse_infsup(setup, infsup::EigenBackend::slepc);
  if (level.scene.wants_output(scene::Output::mode))
    mode = postprocess::sample_mode(*level.d->contact, *level.d->multipliers, alpha.mode);
  release_whole_mesh(*level.d, level.model->operators_mesh());
  return infsup_summary(level, setup, alpha);
}

}  // namespace hpcontact::driver
