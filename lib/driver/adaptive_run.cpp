// The adaptive loop: solve, estimate, mark, refine or raise p.
#include "driver/adaptive_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/timer.hpp"
#include "driver/model.hpp"
#include "driver/pairing_stability.hpp"
#include "mesh/adaptive_mesh.hpp"
#include "scene/scene_mesh.hpp"
#include "space/multiplier_family.hpp"

namespace hpcontact::driver {
namespace {

// Red generations a leaf may reach: 2⁻³⁰ of a coarse cell is near mesh::kFinestRelativeCell of the
// domain, below which vertex round-off spoils the cells' shapes.
constexpr int kDeepestLevel = 30;

// The fewest leaves whose η² hold `fraction` of the sum (Dörfler), largest first.
std::vector<int> dorfler_marks(const std::vector<double>& eta2, double fraction) {
  std::vector<int> order(eta2.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return eta2[a] > eta2[b]; });
  const double total = std::accumulate(eta2.begin(), eta2.end(), 0.0);
  std::vector<int> marked;
  double held = 0.0;
  for (const int leaf : order) {
    if (held >= fraction * total) break;
    marked.push_back(leaf), held += eta2[leaf];
  }
  return marked;
}

double predicted_alpha(const scene::Scene& scene, const SceneDiscretization& d) {
  try {
    return infsup::predict_alpha(trace_pairing_of(scene, *d.contact, d.held_zone_ends, *d.boundary_mesh,
                                                  d.segment_degrees, nullptr, d.trace_degrees))
        .alpha;
  } catch (const NumericalError&) {
    return NAN;  // no prediction is no reason to stop adapting: the column says it is missing
  }
}

// What the forest and its degrees are between steps.
struct Forest {
  mesh::AdaptiveMesh leaves;
  std::vector<int> degree;  ///< p per leaf
};

// Step 4 of the loop (header): splits or raises the marked leaves; counts into `row`.
void refine_marked(const scene::Scene& scene, Forest& forest, const std::vector<int>& leaf_of_cell,
                   const std::vector<double>& eta2_of_cell, const std::vector<double>& theta_of_cell, AdaptStep& row) {
  std::vector<double> eta2(forest.leaves.n_leaves(), 0.0), theta(forest.leaves.n_leaves(), 0.0);
  for (std::size_t c = 0; c < leaf_of_cell.size(); ++c) {
    eta2[leaf_of_cell[c]] += eta2_of_cell[c];
    theta[leaf_of_cell[c]] = std::max(theta[leaf_of_cell[c]], theta_of_cell[c]);
  }
  std::vector<int> split;
  for (const int leaf : dorfler_marks(eta2, scene.adapt.fraction)) {
    const bool may_raise = forest.degree[leaf] < scene.adapt.max_degree;
    const bool may_split = forest.leaves.level(leaf) < kDeepestLevel;
    if (may_raise && (theta[leaf] <= scene.adapt.smoothness || !may_split))
      ++forest.degree[leaf], ++row.raised;
    else if (may_split)
      split.push_back(leaf);
  }
  const auto parent = forest.leaves.refine(split);
  row.split = static_cast<int>(split.size());
  std::vector<int> degree(parent.size());
  for (std::size_t k = 0; k < parent.size(); ++k) degree[k] = forest.degree[parent[k]];
  forest.degree = std::move(degree);
}

}  // namespace

AdaptedLevel adapt_level(const scene::Scene& scene, const std::function<void(const std::string&)>& say,
                         const AdaptStepVisitor& visit) {
  HPC_VERIFY(scene.is_adaptive(), "adapt_level of a scene without adapt.target");
  Stopwatch clock;
  const auto& settings = scene.adapt;
  const mesh::Mesh coarse = scene::build_scene_mesh(scene);
  Forest forest{mesh::AdaptiveMesh(coarse, scene.file), scene::scene_cell_degrees(scene, coarse)};
  AdaptedLevel out;
  out.summary.target = settings.target;
  out.summary.reference_energy = settings.reference_energy;
  for (int step = 0;; ++step) {
    throw_if_cancelled();
    // 1. T_h, its degrees and T_{C,H}.
    std::vector<int> leaf_of_cell;
    mesh::Mesh mesh = forest.leaves.conforming_mesh(&leaf_of_cell);
    std::vector<int> degrees(leaf_of_cell.size());
    AdaptStep row;
    for (std::size_t c = 0; c < degrees.size(); ++c) {
      degrees[c] = forest.degree[leaf_of_cell[c]];
      row.largest_degree = std::max(row.largest_degree, degrees[c]);
      row.deepest_level = std::max(row.deepest_level, forest.leaves.level(leaf_of_cell[c]));
    }
    auto level = std::make_unique<Level>();
    level->scene = scene;
    level->d = discretize_adapted(scene, std::move(mesh), std::move(degrees), scene.p.value - scene.pc.value);
    // 2. The model, its solve and estimate.
    level->model = build_model(level->scene, *level->d, &level->log, linalg::Distribution{});
    if (step > 0 && level->model->n_dofs() > settings.max_unknowns) {
      out.summary.stopped = "max_unknowns";
      break;
    }
    const auto& solved = level->solved.emplace_back(level->model->solve(level->model->problems().front()));
    HPC_VERIFY(solved.indicators, "an adaptive scene's solve without indicators");
    row.step = step;
    row.unknowns = level->model->n_dofs();
    row.multipliers = space::multiplier_function_count(*level->d->multipliers, scene.family);
    row.estimate = 0.5 * solved.indicators->residual.squared();
    row.energy = solved.result.energy;
    row.moment_half_width = solved.result.moment_half_width.value_or(NAN);
    row.alpha = predicted_alpha(scene, *level->d);
    row.seconds = clock.seconds();
    if (say)
      say(fmt::format("adapt step {}: {} unknowns, {} multipliers, p ≤ {}, estimate {:.3e}, energy {:.12g}, α {:.3f}",
                      step, row.unknowns, row.multipliers, row.largest_degree, row.estimate, row.energy, row.alpha));
    if (visit) visit(row, *level);
    // 3. Stop?
    const bool reached = row.estimate <= settings.target, last = step + 1 >= settings.max_steps;
    if (reached || last) {
      out.summary.steps.push_back(row);
      out.summary.stopped = reached ? "target" : "max_steps";
      out.level = std::move(level);
      break;
    }
    // 4. Mark and refine.
    refine_marked(scene, forest, leaf_of_cell, solved.indicators->residual.cell, solved.indicators->theta, row);
    out.summary.steps.push_back(row);
    // Kept in case the next step exceeds max_unknowns, without its factorizations (rebuilt on use).
    level->model->release_factors();
    out.level = std::move(level);
  }
  return out;
}

io::CsvTable adapt_table(const AdaptSummary& summary) {
  std::vector<std::string> columns{"step",    "unknowns",  "multipliers",   "estimate", "energy", "alpha",
                                   "seconds", "largest_p", "deepest_level", "split",    "raised", "moment_half_width"};
  const auto& reference = summary.reference_energy;
  if (reference) columns.insert(columns.end(), {"error_energy", "effectivity"});
  io::CsvTable table(columns);
  for (const auto& r : summary.steps) {
    std::vector<io::CsvCell> row{static_cast<long long>(r.step),
                                 r.unknowns,
                                 r.multipliers,
                                 r.estimate,
                                 r.energy,
                                 r.alpha,
                                 r.seconds,
                                 static_cast<long long>(r.largest_degree),
                                 static_cast<long long>(r.deepest_level),
                                 static_cast<long long>(r.split),
                                 static_cast<long long>(r.raised),
                                 r.moment_half_width};
    if (reference) {
      const double error = std::abs(r.energy - *reference);
      row.insert(row.end(), {error, std::sqrt(r.estimate / error)});
    }
    table.add_row(std::move(row));
  }
  return table;
}

}  // namespace hpcontact::driver
