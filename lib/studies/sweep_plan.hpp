// Planning a stability sweep, without building anything: the points it computes (level × p ×
// problem × norm × family × p_C × ratio), grouped by (level, p) because the points of a group share T_h
// and one factorization of A_G (and by ratio too on many processes), a cost estimate per group,
// the groups scheduled on the slices of a sharded sweep, and the units of work the MPI ranks
// take in turn.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "infsup/infsup_operators.hpp"
#include "scene/ratio.hpp"
#include "scene/scene.hpp"

namespace hpcontact::studies {

struct StabilitySweep;

struct SweepPoint {
  std::string problem, norm;  ///< labels in alpha.csv
  infsup::PairingProblem pairing = infsup::PairingProblem::signorini;
  infsup::GramNorm gram = infsup::GramNorm::interpolation;
  space::MultiplierFamily family;
  std::size_t level = 0, ratio = 0;  ///< ratio: index into ratio_choices
  std::optional<int> p, pc;          ///< as given to the scene; empty: the scene's own
  int reported_p = 0, reported_pc = 0;
  long m = 0;  ///< segments of T_{C,H}
  /// The point's key in alpha.csv (see sweep_rows.hpp).
  std::string key() const;
};

/// The sweep's ratios, or one empty choice: the scene's own contact mesh.
std::vector<std::optional<scene::Ratio>> ratio_choices(const StabilitySweep& sweep);

/// What a sweep point sets in its level's scene; an empty member keeps the scene's value.
struct PointChoice {
  std::optional<int> p{}, pc{};         ///< replace the scene's degree (or degree rule)
  std::optional<scene::Ratio> ratio{};  ///< replaces the scene's m, ratio or breakpoints
  std::optional<infsup::PairingProblem> problem{};
  std::optional<infsup::GramNorm> norm{};
  std::optional<space::MultiplierFamily> family{};
};

/// The scene of one point: the level's scene with what `choice` sets.
scene::Scene point_scene(scene::Scene scene, const PointChoice& choice);

/// "level 2 (domain.n_x=24 domain.n_y=24)", for messages and progress.
std::string level_name(const StabilitySweep& sweep, std::size_t level);

/// Every point, in the order of alpha.csv: by level, p, problem, norm, family, p_C, ratio (p_C ≥ p
/// skipped with pc_rule = "below_p", p_C = 0 for the standard and dual families).
std::vector<SweepPoint> list_sweep_points(const StabilitySweep& sweep);

/// Per (level, ratio index): the p_C as given that the level's points use, from which the envelope
/// multiplier space of the level's Gram matrices is built.
std::map<std::pair<std::size_t, std::size_t>, std::set<std::optional<int>>> multiplier_degrees_used(
    const std::vector<SweepPoint>& points);

/// Points sharing (level, p), consecutive in alpha.csv; split by ratio (only the points of one
/// ratio) when more processes than levels run the sweep, so that the extension norm's references,
/// which depend on the level and the ratio, are built once each.
struct SweepGroup {
  std::size_t first = 0, last = 0;  ///< points [first, last)
  std::size_t level = 0;
  std::size_t share = 0;   ///< the shared work it needs: index into SweepPlan::shared_cost
  bool todo = false;       ///< some point is not stored yet
  bool extension = false;  ///< some point to do uses the extension norm
  double cost = 0.0;       ///< estimated work of the points to do
  int owner = 0;           ///< the process (a --shard slice) schedule_sweep_groups gives it
  /// The ratio index of its points, or every_ratio.
  std::size_t ratio = every_ratio;
  static constexpr std::size_t every_ratio = static_cast<std::size_t>(-1);
  /// Whether point k (of [first, last)) belongs to the group.
  bool holds(const SweepPoint& point) const { return ratio == every_ratio || point.ratio == ratio; }
};

struct SweepPlan {
  std::vector<SweepGroup> groups;
  /// Per share (a level, or a (level, ratio) when the groups are split by ratio): the estimated
  /// work every rank that runs a group of the share repeats (the extension norm's references); 0
  /// when no group of it needs them.
  std::vector<double> shared_cost;
  /// Set by schedule_sweep_groups: whether its schedule keeps every share on one rank.
  bool whole_shares = false;
};

/// Groups the points, skipping those whose key is in `done`, split by ratio if `split_ratios`,
/// with cost estimates: the factorizations grow like (dofs)^1.2 (dofs ~ cells p²), each point
/// adds a little, the extension norm's references (~ 4 cells (p + 2)² dofs at the sweep's
/// largest p, one per ratio) are shared by a level's groups of the ratio.
SweepPlan plan_sweep(const StabilitySweep& sweep, const std::vector<SweepPoint>& points,
                     const std::set<std::string>& done, bool split_ratios = false);

/// Sets the owner of every group to do on `ranks` processes (the slices of --shard; under mpirun
/// only whether shares stay whole is used, see sweep_work_units), by whichever of two schedules finishes
/// first by the estimates: whole shares (levels, or (level, ratio)) longest first, each to the least loaded rank (no
/// shared work repeated), or single groups longest first, each to the rank that would finish it first counting the
/// share's work on a rank without a group of that share yet (better when there are fewer shares than ranks). Returns
/// the estimated finishing time (the largest load).
double schedule_sweep_groups(SweepPlan& plan, int ranks);

/// The units of work that idle ranks take in turn under mpirun (a dynamic queue, so a group that
/// takes longer than its estimate delays no other rank's work): whole shares when the plan's
/// schedule keeps them together (their shared work then done once), single groups otherwise;
/// on several ranks longest first by the estimates, shared work included; on one rank in the
/// plan's order (coarse levels first, as the rows are written). Each unit lists its groups in
/// order.
std::vector<std::vector<std::size_t>> sweep_work_units(const SweepPlan& plan, int ranks);

}  // namespace hpcontact::studies
