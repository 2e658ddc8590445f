// The adaptive loop: solve, estimate, mark, refine or raise p.
#include "driver/adaptive_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

#include "adapt/elastic_residual_estimator.hpp"
#include "adapt/legendre_decay.hpp"
#include "adapt/residual_estimator.hpp"
#include "assembly/cell_field.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/timer.hpp"
#include "driver/elastic_scene.hpp"
#include "driver/pairing_stability.hpp"
#include "mesh/adaptive_mesh.hpp"
#include "operators/primal_operators.hpp"
#include "postprocess/moment_half_width.hpp"
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

// What a step's solve leaves for the marking and for adapt.csv: η_T² and θ_T per cell of T_h.
struct SolvedStep {
  long long unknowns = 0;
  double energy = 0.0, estimate = 0.0, moment_half_width = NAN;
  std::vector<double> eta2, theta;
};

// Step 2 of the loop on a scalar scene; nullopt (nothing solved) where T_h has more than `limit`
// unknowns.
std::optional<SolvedStep> solve_scalar_step(const scene::Scene& scene, const SceneDiscretization& d, long long limit) {
  const operators::PrimalOperators primal(*d.mesh, d.cell_degrees);
  if (primal.space().n_dofs() > limit) return std::nullopt;
  const auto setup = contact_setup_of(scene, d, scene.contact_effects().front(), primal);
  const auto solution = contact::solve_contact(setup);
  const auto indicators = adapt::residual_indicators(setup, solution, primal.space());
  const auto field = assembly::scalar_field(primal.space(), solution.u, solution.u_rows, solution.lift);
  SolvedStep out{primal.space().n_dofs(),
                 solution.energy,
                 0.5 * indicators.squared(),
                 NAN,
                 indicators.cell,
                 adapt::legendre_decay(primal.space(), field)};
  if (setup.problem == contact::ContactProblem::signorini)  // λ ≤ 0 where in contact
    out.moment_half_width = postprocess::moment_half_width(*d.multipliers, -solution.lambda_legendre);
  return out;
}

// The same on an elastic scene (its one contact problem against the rigid obstacle).
std::optional<SolvedStep> solve_elastic_step(const scene::Scene& scene, const SceneDiscretization& d, long long limit) {
  const auto operators = scene_elastic_operators(scene, d.mesh.get(), d.cell_degrees);
  if (operators->n_dofs() > limit) return std::nullopt;
  const auto setup = elastic_setup_of(scene, d, scene.elastic_effects().front(), *operators);
  const auto solution = contact::solve_elastic_contact(setup);
  const auto indicators =
      adapt::elastic_residual_indicators(setup, solution, scene::scene_fixed_components(scene, *d.mesh));
  const auto field = assembly::vector_field(operators->vector_space(), solution.u, solution.u_rows, solution.lift);
  SolvedStep out{operators->n_dofs(),
                 solution.energy,
                 0.5 * indicators.squared(),
                 NAN,
                 indicators.cell,
                 adapt::legendre_decay(operators->space(), field)};
  if (setup.problem != contact::ElasticContactProblem::tied)
    out.moment_half_width = postprocess::moment_half_width(*d.multipliers, solution.pressure);
  return out;
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

AdaptedDiscretization adapt_discretization(const scene::Scene& scene,
                                           const std::function<void(const std::string&)>& say) {
  HPC_VERIFY(scene.is_adaptive(), "adapt_discretization of a scene without adapt.target");
  Stopwatch clock;
  const auto& settings = scene.adapt;
  const mesh::Mesh coarse = scene::build_scene_mesh(scene);
  Forest forest{mesh::AdaptiveMesh(coarse, scene.file), scene::scene_cell_degrees(scene, coarse)};
  AdaptedDiscretization out;
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
    auto d = discretize_adapted(scene, std::move(mesh), std::move(degrees), scene.p.value - scene.pc.value);
    // 2. Solve and estimate.
    const long long limit = step > 0 ? settings.max_unknowns : std::numeric_limits<long long>::max();
    auto solved = scene.is_elastic() ? solve_elastic_step(scene, *d, limit) : solve_scalar_step(scene, *d, limit);
    if (!solved) {
      out.summary.stopped = "max_unknowns";
      break;
    }
    row.step = step;
    row.unknowns = solved->unknowns;
    row.multipliers = space::multiplier_function_count(*d->multipliers, scene.family);
    row.estimate = solved->estimate;
    row.energy = solved->energy;
    row.moment_half_width = solved->moment_half_width;
    row.alpha = predicted_alpha(scene, *d);
    row.seconds = clock.seconds();
    if (say)
      say(fmt::format("adapt step {}: {} unknowns, {} multipliers, p ≤ {}, estimate {:.3e}, energy {:.12g}, α {:.3f}",
                      step, row.unknowns, row.multipliers, row.largest_degree, row.estimate, row.energy, row.alpha));
    // 3. Stop?
    const bool reached = row.estimate <= settings.target, last = step + 1 >= settings.max_steps;
    if (reached || last) {
      out.summary.steps.push_back(row);
      out.summary.stopped = reached ? "target" : "max_steps";
      out.d = std::move(d);
      break;
    }
    // 4. Mark and refine.
    refine_marked(scene, forest, leaf_of_cell, solved->eta2, solved->theta, row);
    out.summary.steps.push_back(row);
    out.d = std::move(d);
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
