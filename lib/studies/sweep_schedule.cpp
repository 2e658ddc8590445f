// SweepSchedule: the plan of a run over the slices and groups of ranks, the units taken from the
// shared counter, durable saving and the ranks' agreement on failures.
#include "studies/sweep_schedule.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <memory>

#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/petsc_session.hpp"
#include "core/rank_agreement.hpp"
#include "io/atomic_file.hpp"

namespace hpcontact::studies {
namespace {

// The plan of what is left of `shard` for `workers` groups of ranks.
SweepPlan plan_of_run(const StabilitySweep& sweep, const std::vector<SweepPoint>& points,
                      const std::set<std::string>& stored, SweepShard shard, int workers) {
  // More processes than levels split the groups by ratio, so that each builds only the extension
  // references of its ratios (splitting a level by p instead repeats all of them): 10 slices of
  // the full grid 83 -> 44 s. With fewer, whole levels keep the processes busy and a split only
  // repeats each (level, p)'s factorizations per ratio (2 ranks: 71-77 -> 84 s). Slices decide by
  // their count alone, so that a slice's groups do not depend on the ranks it runs on.
  const bool split_ratios = (shard.count > 1 ? shard.count : workers) > static_cast<int>(sweep.levels.size());
  SweepPlan plan = plan_sweep(sweep, points, stored, split_ratios);
  if (shard.count > 1) {
    // The shard's groups come from the plan of the whole sweep, so they do not move when this
    // shard (or another) resumes with part of its rows stored.
    SweepPlan whole = plan_sweep(sweep, points, {}, split_ratios);
    HPC_VERIFY(whole.groups.size() == plan.groups.size(), "a sweep's groups must not depend on its stored rows");
    schedule_sweep_groups(whole, shard.count);
    for (std::size_t g = 0; g < plan.groups.size(); ++g)
      if (whole.groups[g].owner != shard.index) plan.groups[g].todo = false;
  }
  // The schedule on the groups decides whether shares stay whole (sweep_work_units).
  schedule_sweep_groups(plan, workers);
  return plan;
}

std::string progress_label(const StabilitySweep& sweep, const SweepPoint& point) {
  const auto ratio = ratio_choices(sweep)[point.ratio];  // a copy: the list is a temporary
  return fmt::format("{} {} p={} pC={} {}{}", point.problem, point.norm, point.reported_p, point.reported_pc,
                     level_name(sweep, point.level), ratio ? " h/H=" + ratio->text : "");
}

}  // namespace

SweepSchedule::SweepSchedule(const StabilitySweep& sweep, const std::vector<SweepPoint>& points, const AlphaRows& rows,
                             SweepShard shard, const RankGroups& ranks)
    : sweep_(sweep),
      points_(points),
      ranks_(ranks),
      plan_(plan_of_run(sweep, points, rows.keys(), shard, ranks.n_groups())),
      units_(sweep_work_units(plan_, ranks.n_groups())) {
  // A share's Gram ladders are kept until no unit left to take holds the share (units are taken
  // in order), so a rank that takes a share's groups in several turns builds them once.
  for (std::size_t u = 0; u < units_.size(); ++u)
    for (std::size_t g : units_[u]) last_unit_of_share_[plan_.groups[g].share] = static_cast<long>(u);
  stored_ = static_cast<int>(std::ranges::count_if(points, [&](const SweepPoint& p) { return rows.has(p.key()); }));
  total_ = stored_;
  // A group's estimated cost shared by its points to do, as parts of all of this run's; every
  // point costs at least what a point of ~1500 unknowns does (its fixed work: ~3 ms on the
  // tutorial's sweep), which the plan's asymptotic estimate leaves out.
  constexpr double kPointFloor = 5e3;
  std::vector<double> cost(points.size(), 0.0);
  double total_cost = 0.0;
  for (const SweepGroup& g : plan_.groups) {
    int todo = 0;
    for (std::size_t k = g.first; g.todo && k < g.last; ++k) todo += g.holds(points[k]) && !rows.has(points[k].key());
    total_ += todo;
    for (std::size_t k = g.first; todo > 0 && k < g.last; ++k)
      if (g.holds(points[k]) && !rows.has(points[k].key())) {
        cost[k] = g.cost / todo + kPointFloor;
        total_cost += cost[k];
      }
  }
  point_work_.resize(points.size(), 0);
  for (std::size_t k = 0; k < points.size() && total_cost > 0.0; ++k)
    point_work_[k] = std::lround(cost[k] / total_cost * static_cast<double>(kWorkUnits));
}

void SweepSchedule::run(const SweepWork& work, AlphaRows& rows, const std::filesystem::path& alpha_csv,
                        const SweepProgress& progress) {
  const long n_units = static_cast<long>(units_.size());
  run_on_all_ranks_agreeing([&] {
    try {
      take_units(work, rows, alpha_csv, progress);
    } catch (...) {
      if (leader()) next_unit_.exhaust(n_units);
      throw;
    }
  });
  write_every_row(rows, alpha_csv);
}

// The leader takes the next unit and tells the rest of its group.
long SweepSchedule::take_unit() {
  long unit = leader() ? next_unit_.take() : 0;
  if (ranks_.group_size() > 1) MPI_Bcast(&unit, 1, MPI_LONG, 0, ranks_.group());
  return unit;
}

// Units taken in turn by whichever group of ranks is idle, until none is left.
void SweepSchedule::take_units(const SweepWork& work, AlphaRows& rows, const std::filesystem::path& alpha_csv,
                               const SweepProgress& progress) {
  for (;;) {
    try {
      const long unit = take_unit();
      if (unit >= static_cast<long>(units_.size())) return;
      release_shares_before(unit, work);
      for (std::size_t g : units_[static_cast<std::size_t>(unit)])
        run_group(plan_.groups[g], work, rows, alpha_csv, progress);
    } catch (...) {
      // A group's collective failure (a solve that failed, the leader's write) is raised on all
      // its ranks; a rank failing alone would wait for the others forever in run()'s agreement,
      // while they wait in the unit's collective calls: it ends the job instead.
      group_fails_within(ranks_.failure_channel(), kFailurePatience);
      throw;
    }
  }
}

void SweepSchedule::release_shares_before(long unit, const SweepWork& work) {
  std::erase_if(held_shares_, [&](std::size_t share) {
    if (last_unit_of_share_.at(share) >= unit) return false;
    work.release_share(share);
    return true;
  });
}

void SweepSchedule::run_group(const SweepGroup& group, const SweepWork& work, AlphaRows& rows,
                              const std::filesystem::path& alpha_csv, const SweepProgress& progress) {
  held_shares_.insert(group.share);
  const auto record_of = work.start_group(group);
  std::vector<std::pair<int, infsup::InfSupRecord>> computed;
  for (std::size_t k = group.first; k < group.last; ++k) {
    const SweepPoint& point = points_[k];
    if (!group.holds(point) || rows.has(point.key())) continue;
    throw_if_cancelled();
    if (progress && leader())
      progress(stored_ + static_cast<int>(points_computed_.value()) + 1, total_,
               static_cast<double>(work_computed_.value()) / kWorkUnits, progress_label(sweep_, point));
    const auto record = record_of(point);
    if (leader()) {
      points_computed_.take();
      work_computed_.take(point_work_[k]);
    }
    rows.set(point.key(), record);
    computed.emplace_back(static_cast<int>(k), record);
  }
  save_group(computed, rows, alpha_csv);
}

// A finished group on disk: serially all of alpha.csv rewritten; under mpirun the leader appends
// the group's rows to its shard (alpha.csv is written once, at the end), and its failure (a full
// disk) ends the group's unit on all its ranks.
void SweepSchedule::save_group(const std::vector<std::pair<int, infsup::InfSupRecord>>& computed, const AlphaRows& rows,
                               const std::filesystem::path& alpha_csv) {
  const int rank = mpi_rank_and_size().first, size = mpi_rank_and_size().second;
  if (size == 1) {
    io::write_file_atomically(alpha_csv, rows.content());
    return;
  }
  if (leader()) new_rows_.insert(new_rows_.end(), computed.begin(), computed.end());
  std::vector<infsup::InfSupRecord> records;
  for (const auto& [index, record] : computed) records.push_back(record);
  run_on_all_ranks_agreeing(
      [&] {
        if (leader() && !records.empty()) append_durably(shard_path(alpha_csv, rank), records);
      },
      ranks_.group());
}

// Every rank's rows into alpha.csv (rank 0), in the order of the points, and the shards removed
// once it is complete.
void SweepSchedule::write_every_row(AlphaRows& rows, const std::filesystem::path& alpha_csv) {
  const int rank = mpi_rank_and_size().first, size = mpi_rank_and_size().second;
  run_on_all_ranks_agreeing([&] {
    if (size > 1)
      for (const auto& [point_index, record] : gather_rows_on_rank_zero(new_rows_))
        rows.set(points_[static_cast<std::size_t>(point_index)].key(), record);
    if (rank == 0) {
      io::write_file_atomically(alpha_csv, rows.content());
      for (const auto& rank_shard : existing_shards(alpha_csv)) std::filesystem::remove(rank_shard);
    }
  });
}

}  // namespace hpcontact::studies
