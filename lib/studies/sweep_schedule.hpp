// Who computes what in a stability sweep run: the groups of ranks that take units of work from a
// shared counter, the slice of --shard they own, the progress count, the durable saving of every
// finished group, and the ranks' agreement on a failure. What a point computes is given to it
// (SweepWork; the sweep's own is SweepEvaluation).
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/rank_groups.hpp"
#include "core/shared_counter.hpp"
#include "infsup/infsup_record.hpp"
#include "studies/stability_sweep.hpp"
#include "studies/sweep_plan.hpp"
#include "studies/sweep_rows.hpp"

namespace hpcontact::studies {

/// What the schedule hands out, group by group. Both are called on every rank of the group of
/// ranks that took the unit, and may be collective over it.
struct SweepWork {
  /// Builds what the points of a group share (its T_h and operators) and returns the record of
  /// each of its points, called in the points' order.
  std::function<std::function<infsup::InfSupRecord(const SweepPoint&)>(const SweepGroup&)> start_group;
  /// Frees what the points of a share (SweepGroup::share) reuse: no unit left to take holds it.
  std::function<void(std::size_t share)> release_share;
};

class SweepSchedule {
 public:
  /// Plans the points of `shard` that `rows` (stored by an earlier run) lacks into units of work
  /// for the groups of `ranks`. Collective over MPI_COMM_WORLD (the shared counters).
  SweepSchedule(const StabilitySweep& sweep, const std::vector<SweepPoint>& points, const AlphaRows& rows,
                SweepShard shard, const RankGroups& ranks);

  /// Runs the units: each group of ranks takes the next unit when idle, computes its groups' points
  /// by `work` into `rows` and saves every finished group durably (serially alpha_csv itself, under
  /// mpirun the leader's shard beside it). A failure ends the unit on every rank of its group, lets
  /// no group take new work and is raised on every rank. At the end rank 0 holds every row and
  /// writes alpha_csv in the points' order, and the shards are removed. Collective.
  void run(const SweepWork& work, AlphaRows& rows, const std::filesystem::path& alpha_csv,
           const SweepProgress& progress);

 private:
  bool leader() const { return ranks_.rank_in_group() == 0; }
  long take_unit();
  void take_units(const SweepWork& work, AlphaRows& rows, const std::filesystem::path& alpha_csv,
                  const SweepProgress& progress);
  void release_shares_before(long unit, const SweepWork& work);
  void run_group(const SweepGroup& group, const SweepWork& work, AlphaRows& rows,
                 const std::filesystem::path& alpha_csv, const SweepProgress& progress);
  void save_group(const std::vector<std::pair<int, infsup::InfSupRecord>>& computed, const AlphaRows& rows,
                  const std::filesystem::path& alpha_csv);
  void write_every_row(AlphaRows& rows, const std::filesystem::path& alpha_csv);

  const StabilitySweep& sweep_;
  const std::vector<SweepPoint>& points_;
  const RankGroups& ranks_;
  SweepPlan plan_;
  std::vector<std::vector<std::size_t>> units_;  ///< groups of plan_, in the order they are taken
  std::map<std::size_t, long> last_unit_of_share_;
  std::set<std::size_t> held_shares_;  ///< shares this rank has started groups of, not yet released
  /// The progress count: points stored before and points computed by all ranks, of those stored
  /// and those to do in this run (a slice's own).
  int stored_ = 0, total_ = 0;
  /// The work of each point to do in this run, in units of kWorkUnits for all of it (the plan's
  /// cost estimates), and the units of the points all ranks computed so far.
  static constexpr long kWorkUnits = 1000000000;
  std::vector<long> point_work_;
  SharedCounter next_unit_, points_computed_, work_computed_;
  std::vector<std::pair<int, infsup::InfSupRecord>> new_rows_;  ///< (point index, record) of this leader
};

}  // namespace hpcontact::studies
