// Candidates of a multiplier discretization, ranked by the predicted α (pairing_advice.hpp).
#include "studies/pairing_advice.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/error.hpp"
#include "core/timer.hpp"
#include "driver/pairing_stability.hpp"
#include "driver/run_stages.hpp"
#include "infsup/infsup_analysis.hpp"
#include "scene/scene_mesh.hpp"
#include "space/multiplier_space.hpp"
#include "studies/sweep_plan.hpp"

namespace hpcontact::studies {
namespace {

// The ratios h/H tried: T_h's edges, T_{C,H} not nested in T_h, and coarser ones.
const std::vector<std::pair<double, std::string>> kRatios{{1.0, "1"},   {0.75, "3/4"},    {2.0 / 3, "2/3"},
                                                          {0.5, "1/2"}, {1.0 / 3, "1/3"}, {0.25, "1/4"}};

// The edits that turn `scene` into `c`.
std::vector<std::string> edits_of(const scene::Scene& scene, const AdviceCandidate& c) {
  std::vector<std::string> edits;
  if (!scene.pc.rule.empty() || scene.pc.value != c.pc) edits.push_back(fmt::format("[discretization] pC = {}", c.pc));
  const bool same_ratio = scene.ratio.size() == 1 && std::abs(scene.ratio.front().value - c.ratio.value) < 1e-12;
  if (!same_ratio) {
    const std::string replaced = !scene.m.empty()             ? " (in place of m)"
                                 : !scene.breakpoints.empty() ? " (in place of breakpoints)"
                                 : scene.ratio.size() > 1     ? " (one ratio for every zone)"
                                                              : "";
    edits.push_back(fmt::format("[contact_mesh] ratio = \"{}\"{}", c.ratio.text, replaced));
  }
  if (!(scene.family == c.family))
    edits.push_back(fmt::format("[contact_mesh] family = \"{}\"", space::to_string(c.family)));
  if (!scene.constraint_points.empty())
    edits.push_back(c.constraint_points ? "[solve] constraint_points removed (p_C + 1, the default)"
                                        : "[solve] constraint_points removed (the family constrains its nodes)");
  return edits;
}

scene::Scene candidate_scene(const scene::Scene& scene, const AdviceCandidate& c) {
  auto out = point_scene(scene, {.pc = c.pc, .ratio = c.ratio, .family = c.family});
  out.constraint_points.clear();
  return out;
}

// α of the candidate's pairing as `hpcontact infsup` computes it: the run's own stages.
double global_alpha(const scene::Scene& scene) {
  const driver::StageContext context{};
  const auto level = driver::discretize(scene, context);
  driver::build_operators(*level, nullptr, context, scene.norm == infsup::GramNorm::extension);
  const auto setup = level->model->infsup_setup();
  return driver::infsup_summary(*level, setup, infsup::analyse_infsup(setup, infsup::EigenBackend::slepc)).record.alpha;
}

}  // namespace

PairingAdvice advise_pairing(const scene::Scene& scene, const AdviceOptions& options) {
  Stopwatch clock;
  const auto say = [&](const std::string& line) {
    if (options.progress) options.progress(line);
  };
  if (options.alpha_min && !(*options.alpha_min > 0 && *options.alpha_min <= 1))
    throw_bad_input("hpcontact advise", "--alpha-min", fmt::format("{}", *options.alpha_min), "in (0, 1]");
  // T_h and the operators once: the candidates differ in T_{C,H} and p_C only.
  say("meshing and building the operators");
  const driver::StageContext context{};
  const auto base = driver::discretize(scene, context);
  driver::build_operators(*base, nullptr, context, false);
  const auto& contact = *base->d->contact;
  const auto* projection = base->model->master_projection();
  PairingAdvice advice;
  advice.p = scene.p.label();
  say("predicting α of the candidates");
  for (int pc = 0; pc <= base->d->largest_cell_degree; ++pc)
    for (const auto& [value, text] : kRatios)
      for (const auto& family : space::all_multiplier_families()) {
        AdviceCandidate c;
        c.pc = pc;
        c.ratio = {value, text};
        c.family = family;
        const bool discontinuous = family.kind == space::MultiplierFamilyKind::discontinuous;
        if (!discontinuous && pc == 0) continue;
        if (discontinuous) c.constraint_points = pc + 1;
        const auto predicted =
            driver::predict_candidate(candidate_scene(scene, c), contact, base->d->held_zone_ends, projection);
        if (!predicted) continue;  // a ratio without whole segments on this mesh, a family that does not fit
        c.alpha_predicted = predicted->alpha;
        c.nmult = predicted->nmult;
        c.unknowns = base->model->n_dofs() + c.nmult;
        c.edits = edits_of(scene, c);
        advice.candidates.push_back(std::move(c));
      }
  if (advice.candidates.empty())
    throw InputError(scene.file +
                     ": no multiplier discretization fits this mesh (no ratio h/H of 1, 3/4, 2/3, 1/2, "
                     "1/3, 1/4 gives whole segments)");
  double best = 0.0;
  for (const auto& c : advice.candidates) best = std::max(best, c.alpha_predicted);
  advice.alpha_min = options.alpha_min.value_or(std::max(0.1 * best, infsup::kStablePatchAlpha));
  for (auto& c : advice.candidates) c.admitted = c.alpha_predicted >= advice.alpha_min;
  std::stable_sort(advice.candidates.begin(), advice.candidates.end(), [](const auto& a, const auto& b) {
    if (a.admitted != b.admitted) return a.admitted;
    if (a.admitted && a.nmult != b.nmult) return a.nmult > b.nmult;
    return a.alpha_predicted > b.alpha_predicted;
  });
  for (std::size_t i = 0; i < advice.candidates.size() && i < 2; ++i) {
    if (!advice.candidates[i].admitted) break;
    (i == 0 ? advice.recommended : advice.runner_up) = i;
    auto& c = advice.candidates[i];
    say(fmt::format("global α of the {}: p_C = {}, h/H = {}, family {}", i == 0 ? "recommendation" : "runner-up", c.pc,
                    c.ratio.text, space::to_string(c.family)));
    c.alpha = global_alpha(candidate_scene(scene, c));
  }
  advice.seconds = clock.seconds();
  return advice;
}

io::CsvTable advice_table(const PairingAdvice& advice) {
  io::CsvTable table({"zone", "p", "pC", "ratio", "family", "constraint_points", "alpha_predicted", "alpha", "unknowns",
                      "recommended"});
  for (std::size_t i = 0; i < advice.candidates.size(); ++i) {
    const auto& c = advice.candidates[i];
    table.add_row({std::string("all"), advice.p, static_cast<long long>(c.pc), c.ratio.text, space::to_string(c.family),
                   c.constraint_points ? io::CsvCell(static_cast<long long>(*c.constraint_points))
                                       : io::CsvCell(std::string("nodes")),
                   c.alpha_predicted, c.alpha ? io::CsvCell(*c.alpha) : io::CsvCell(std::string()), c.unknowns,
                   std::string(advice.recommended == i ? "yes"
                               : advice.runner_up == i ? "runner-up"
                                                       : "no")});
  }
  return table;
}

}  // namespace hpcontact::studies
