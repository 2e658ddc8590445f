// hp-adaptivity of T_h and T_{C,H} for the scalar contact problems and elastic contact against a
// rigid obstacle: solve, estimate (adapt/residual_estimator.hpp, adapt/elastic_residual_estimator.hpp),
// mark, refine (mesh/adaptive_mesh.hpp) or raise p (adapt/legendre_decay.hpp), until the estimate
// meets [adapt] target. The last step is the run's level: its model and solved problem go on to
// the run's other stages and outputs without being built or solved again (scene_run.cpp).
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "driver/run_result.hpp"
#include "driver/run_stages.hpp"
#include "io/csv_writer.hpp"
#include "scene/scene.hpp"

namespace hpcontact::driver {

/// The loop, step k:
///   1. T_h the closed leaves of the red-refinement forest (start: the scene's mesh), p_T per
///      leaf; T_{C,H} the trace of T_h, p_C = p_T − (p − p_C) of the scene, at least 0;
///   2. the scene's model built on them and its contact problem solved (driver/model.hpp), η_T²
///      per cell, η²/2 the estimate; the pairing's α predicted (infsup/local_alpha.hpp);
///   3. stop at estimate ≤ adapt.target, after adapt.max_steps solves, or before a step whose
///      unknowns would exceed adapt.max_unknowns (the last solved discretization is kept);
///   4. Dörfler marking of the leaves (η² of a leaf: its cells'), each marked leaf given p + 1
///      where θ_T ≤ adapt.smoothness and p < adapt.max_degree, split otherwise (children keep p).
struct AdaptedLevel {
  /// The last step: its scene, discretization, model (operators recorded into its log) and solved
  /// problem.
  std::unique_ptr<Level> level;
  AdaptSummary summary;
};

/// What a caller may read of each step once it is solved and estimated (before its refinement):
/// its row of adapt.csv and its level (a study measures the step's error against a reference).
using AdaptStepVisitor = std::function<void(const AdaptStep& row, const Level& level)>;

/// @pre scene.is_adaptive() (scene::check_adapt has passed). `say` (may be empty) gets one line per
/// step. @throws InputError as the scene's builders do; NumericalError if a solve fails.
AdaptedLevel adapt_level(const scene::Scene& scene, const std::function<void(const std::string&)>& say,
                         const AdaptStepVisitor& visit = {});

/// adapt.csv: step,unknowns,multipliers,estimate,energy,alpha,seconds,largest_p,deepest_level,split,
/// raised,moment_half_width, and error_energy,effectivity (|E − E_ref| and √(estimate / |E − E_ref|))
/// with a reference energy.
io::CsvTable adapt_table(const AdaptSummary& summary);

}  // namespace hpcontact::driver
