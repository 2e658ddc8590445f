// Sweeps: the plan of a stability sweep (its points, groups and the schedule over MPI ranks),
// its rows and its verdicts are pure and checked here without building a mesh.
#include "studies/sweep_plan.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <set>

#include "io/infsup_record_csv.hpp"
#include "studies/stability_sweep.hpp"
#include "studies/sweep_verdicts.hpp"

using namespace hpcontact;
using studies::SweepGroup;
using studies::SweepPlan;

namespace {

// Two levels of a sweep over p = 1..3, every p_C, two ratios, both norms.
studies::StabilitySweep two_level_sweep() {
  studies::StabilitySweep sweep;
  sweep.levels.resize(2);
  for (int level = 0; level < 2; ++level) {
    studies::StabilitySweep::LevelFacts facts;
    facts.cells = 64 << (2 * level);
    facts.contact_edges = 8 << level;
    facts.scene_p = 1;
    facts.segments = {8 << level, 4 << level};
    facts.scene_pc = {0, 0};
    sweep.level_facts.push_back(facts);
  }
  sweep.degrees = {1, 2, 3};
  sweep.multiplier_degrees = {0, 1, 2};
  sweep.ratios = {scene::Ratio{1.0, "1"}, scene::Ratio{0.5, "1/2"}};
  sweep.norms = {infsup::GramNorm::interpolation, infsup::GramNorm::extension};
  sweep.problems = {infsup::PairingProblem::signorini};
  return sweep;
}

double load_of(const SweepPlan& plan, int rank) {
  double load = 0.0;
  std::set<std::size_t> levels;
  for (const auto& group : plan.groups)
    if (group.todo && group.owner == rank) {
      load += group.cost;
      levels.insert(group.share);
    }
  for (std::size_t level : levels) load += plan.shared_cost[level];
  return load;
}

}  // namespace

// Points in alpha.csv order, p_C < p only, distinct keys; groups are the runs of (level, p).
TEST(SweepPlan, PointsAndGroups) {
  const auto sweep = two_level_sweep();
  const auto points = studies::list_sweep_points(sweep);
  // Per level: p = 1 (p_C 0), p = 2 (0, 1), p = 3 (0, 1, 2): 6 pairs × 2 norms × 2 ratios.
  ASSERT_EQ(points.size(), 2u * 6 * 2 * 2);
  std::set<std::string> keys;
  for (const auto& point : points) {
    EXPECT_LT(point.reported_pc, point.reported_p);
    keys.insert(point.key());
  }
  EXPECT_EQ(keys.size(), points.size());
  const auto plan = studies::plan_sweep(sweep, points, {});
  ASSERT_EQ(plan.groups.size(), 6u);
  for (const auto& group : plan.groups) {
    EXPECT_TRUE(group.todo);
    EXPECT_TRUE(group.extension);
    for (std::size_t k = group.first; k < group.last; ++k) {
      EXPECT_EQ(points[k].level, group.level);
      EXPECT_EQ(points[k].p, points[group.first].p);
    }
  }
  EXPECT_GT(plan.shared_cost[1], plan.shared_cost[0]);
  // Stored points are not planned again; a group with nothing left is not to do.
  std::set<std::string> done;
  for (std::size_t k = plan.groups[0].first; k < plan.groups[0].last; ++k) done.insert(points[k].key());
  const auto resumed = studies::plan_sweep(sweep, points, done);
  EXPECT_FALSE(resumed.groups[0].todo);
  EXPECT_TRUE(resumed.groups[1].todo);
}

// A family axis multiplies the points; the standard and dual families skip p_C = 0.
TEST(SweepPlan, AFamilyAxisSkipsDegreeZeroForContinuousFamilies) {
  auto sweep = two_level_sweep();
  sweep.families = {space::MultiplierFamily{}, {space::MultiplierFamilyKind::dual, true}};
  const auto points = studies::list_sweep_points(sweep);
  // Per level: discontinuous 6 (p, p_C) pairs, dual-modified 3 (p_C = 1 … p − 1); 2 norms, 2 ratios.
  ASSERT_EQ(points.size(), 2u * (6 + 3) * 2 * 2);
  std::set<std::string> keys;
  for (const auto& point : points) {
    if (point.family.kind == space::MultiplierFamilyKind::dual) {
      EXPECT_GE(point.reported_pc, 1);
    }
    keys.insert(point.key());
  }
  EXPECT_EQ(keys.size(), points.size());
  const auto scene = studies::point_scene(scene::Scene{}, {.family = sweep.families[1]});
  EXPECT_EQ(scene.family, sweep.families[1]);
}

// Split by ratio (several processes): per (level, p) one group per ratio, every point in exactly one
// group, of its ratio; the shares are (level, ratio), each needing one extension reference (the
// unsplit share of a level needs two, one per ratio); a stored ratio's group is not to do.
TEST(SweepPlan, GroupsSplitByRatioShareOneReferenceEach) {
  const auto sweep = two_level_sweep();
  const auto points = studies::list_sweep_points(sweep);
  const auto whole = studies::plan_sweep(sweep, points, {});
  const auto plan = studies::plan_sweep(sweep, points, {}, true);
  ASSERT_EQ(plan.groups.size(), 12u);
  ASSERT_EQ(plan.shared_cost.size(), 4u);
  std::vector<int> groups_of_point(points.size(), 0);
  for (const auto& group : plan.groups) {
    EXPECT_EQ(group.share, group.level * 2 + group.ratio);
    for (std::size_t k = group.first; k < group.last; ++k)
      if (group.holds(points[k])) {
        ++groups_of_point[k];
        EXPECT_EQ(points[k].ratio, group.ratio);
        EXPECT_EQ(points[k].level, group.level);
      }
  }
  EXPECT_TRUE(std::ranges::all_of(groups_of_point, [](int n) { return n == 1; }));
  EXPECT_DOUBLE_EQ(whole.shared_cost[0], 2 * plan.shared_cost[0]);
  EXPECT_GT(plan.shared_cost[2], plan.shared_cost[0]);
  // Resuming: the same groups (a slice maps them by index), a stored ratio's group not to do; the
  // unsplit level still needs the references of every ratio some point to do uses.
  std::set<std::string> done;
  for (std::size_t k = plan.groups[1].first; k < plan.groups[1].last; ++k)
    if (plan.groups[1].holds(points[k])) done.insert(points[k].key());
  const auto resumed = studies::plan_sweep(sweep, points, done, true);
  ASSERT_EQ(resumed.groups.size(), plan.groups.size());
  for (std::size_t g = 0; g < plan.groups.size(); ++g) {
    EXPECT_EQ(resumed.groups[g].first, plan.groups[g].first);
    EXPECT_EQ(resumed.groups[g].ratio, plan.groups[g].ratio);
  }
  EXPECT_TRUE(resumed.groups[0].todo);
  EXPECT_FALSE(resumed.groups[1].todo);
  // Level 0 with p = 1's ratio-0 points, p = 2's ratio-1 points and all of p = 3 stored: p = 1
  // still needs ratio 1's reference and p = 2 ratio 0's, so the level needs both.
  std::set<std::string> mixed;
  for (const auto& point : points)
    if (point.level == 0 && ((point.reported_p == 1 && point.ratio == 0) ||
                             (point.reported_p == 2 && point.ratio == 1) || point.reported_p == 3))
      mixed.insert(point.key());
  const auto mixed_whole = studies::plan_sweep(sweep, points, mixed);
  EXPECT_DOUBLE_EQ(mixed_whole.shared_cost[0], whole.shared_cost[0]);
}

// The schedule: one rank gets everything; two ranks split two equal levels one each, and split one
// level's equal groups when nothing is shared; the estimate returned is the largest load.
TEST(SweepPlan, ScheduleBalancesTheRanks) {
  SweepPlan equal_levels{{{0, 1, 0, 0, true, false, 5.0},
                          {1, 2, 0, 0, true, false, 5.0},
                          {2, 3, 1, 1, true, false, 5.0},
                          {3, 4, 1, 1, true, false, 5.0}},
                         {0.0, 0.0}};
  SweepPlan serial = equal_levels;
  EXPECT_DOUBLE_EQ(studies::schedule_sweep_groups(serial, 1), 20.0);
  for (const auto& group : serial.groups) EXPECT_EQ(group.owner, 0);
  EXPECT_DOUBLE_EQ(studies::schedule_sweep_groups(equal_levels, 2), 10.0);
  EXPECT_DOUBLE_EQ(load_of(equal_levels, 0), 10.0);
  EXPECT_DOUBLE_EQ(load_of(equal_levels, 1), 10.0);

  SweepPlan one_level{{{0, 1, 0, 0, true, false, 4.0},
                       {1, 2, 0, 0, true, false, 4.0},
                       {2, 3, 0, 0, true, false, 4.0},
                       {3, 4, 0, 0, true, false, 4.0},
                       {4, 5, 0, 0, false, false, 100.0}},
                      {0.0}};
  EXPECT_DOUBLE_EQ(studies::schedule_sweep_groups(one_level, 2), 8.0);
  EXPECT_DOUBLE_EQ(load_of(one_level, 0), 8.0);
  EXPECT_DOUBLE_EQ(load_of(one_level, 1), 8.0);

  // Two levels whose shared work dominates: splitting a level would repeat it, so each level
  // stays whole on its own rank (52 each, where splitting groups would take 102).
  SweepPlan shared{{{0, 1, 0, 0, true, true, 1.0},
                    {1, 2, 0, 0, true, true, 1.0},
                    {2, 3, 1, 1, true, true, 1.0},
                    {3, 4, 1, 1, true, true, 1.0}},
                   {50.0, 50.0}};
  EXPECT_DOUBLE_EQ(studies::schedule_sweep_groups(shared, 2), 52.0);
  EXPECT_EQ(shared.groups[0].owner, shared.groups[1].owner);
  EXPECT_EQ(shared.groups[2].owner, shared.groups[3].owner);
  EXPECT_NE(shared.groups[0].owner, shared.groups[2].owner);
}

// The units idle ranks take under mpirun: whole levels when the schedule keeps levels together,
// single groups otherwise, each group to do in exactly one unit, longest first on several ranks
// (shared work counted), groups in order within a unit; groups already stored are in none.
TEST(SweepPlan, WorkUnitsFollowTheScheduleLongestFirst) {
  SweepPlan shared{{{0, 1, 0, 0, true, true, 1.0},
                    {1, 2, 0, 0, true, true, 1.0},
                    {2, 3, 1, 1, true, true, 1.0},
                    {3, 4, 1, 1, true, true, 1.0},
                    {4, 5, 1, 1, false, true, 9.0}},
                   {40.0, 50.0}};
  studies::schedule_sweep_groups(shared, 2);
  ASSERT_TRUE(shared.whole_shares);
  const auto levels = studies::sweep_work_units(shared, 2);
  ASSERT_EQ(levels.size(), 2u);
  EXPECT_EQ(levels[0], (std::vector<std::size_t>{2, 3}));  // level 1: 52 before level 0: 42
  EXPECT_EQ(levels[1], (std::vector<std::size_t>{0, 1}));
  // One rank: the plan's order.
  studies::schedule_sweep_groups(shared, 1);
  EXPECT_EQ(studies::sweep_work_units(shared, 1), (std::vector<std::vector<std::size_t>>{{0, 1}, {2, 3}}));

  SweepPlan one_level{{{0, 1, 0, 0, true, false, 2.0},
                       {1, 2, 0, 0, true, false, 4.0},
                       {2, 3, 0, 0, false, false, 100.0},
                       {3, 4, 0, 0, true, false, 3.0}},
                      {0.0}};
  studies::schedule_sweep_groups(one_level, 2);
  ASSERT_FALSE(one_level.whole_shares);
  const auto groups = studies::sweep_work_units(one_level, 2);
  ASSERT_EQ(groups.size(), 3u);
  EXPECT_EQ(groups[0], (std::vector<std::size_t>{1}));
  EXPECT_EQ(groups[1], (std::vector<std::size_t>{3}));
  EXPECT_EQ(groups[2], (std::vector<std::size_t>{0}));
}

namespace {

infsup::InfSupRecord record_at(double h_min, double alpha) {
  infsup::InfSupRecord record;
  record.problem = infsup::PairingProblem::friction;
  record.norm = infsup::GramNorm::extension;
  record.p = 3, record.pc = 2, record.level = 2, record.n = 16, record.m = 8;
  record.family = {space::MultiplierFamilyKind::dual, true};
  record.h = 0.125, record.h_min = h_min, record.H = 0.25, record.ratio = 0.5, record.pi = 2.0 / 3.0;
  record.alpha = alpha, record.alpha_error = 1e-11, record.alpha_converged = true;
  record.ndofs = 1089, record.nmult = 24, record.seconds = 0.1;
  return record;
}

}  // namespace

// A record written as a row of alpha.csv reads back as itself (every number to the last bit),
// but for alpha_converged, which is not a column; a row with a column missing, an unknown label or
// a number that does not parse completely reads as none.
TEST(SweepRows, ARecordReadsBackFromItsRow) {
  const auto record = record_at(0.1, 0.123456789012345678);
  io::CsvTable table(io::alpha_columns());
  io::add_alpha_row(table, record);
  std::string row = table.rows_to_string();
  ASSERT_EQ(row.back(), '\n');
  row.pop_back();
  auto expected = record;
  expected.alpha_converged.reset();
  ASSERT_TRUE(io::read_alpha_row(row).has_value()) << row;
  EXPECT_EQ(*io::read_alpha_row(row), expected);
  EXPECT_FALSE(io::read_alpha_row(row.substr(0, row.rfind(','))));                          // seconds missing
  EXPECT_FALSE(io::read_alpha_row("Friction" + row.substr(row.find(','))));                 // not a label
  EXPECT_FALSE(io::read_alpha_row(std::string(row).replace(row.find(",3,"), 3, ",3.5,")));  // p not whole
  EXPECT_FALSE(io::read_alpha_row(row + "x"));                                              // seconds cut
  EXPECT_FALSE(io::read_alpha_row(std::string(row).replace(row.find("dual-modified"), 13, "mortar")));  // no family
}

// Verdicts from records: α = h_min decays at rate 1, α constant is stable, α ≤ 1e-6 singular, one
// level too few; the fit uses the finest fit_levels levels whatever the rows' order.
TEST(SweepVerdicts, FitRatesOfTypedRows) {
  std::vector<infsup::InfSupRecord> rows;
  for (double h : {0.5, 0.25, 0.125, 0.0625}) {
    auto decaying = record_at(h, 2 * h), stable = record_at(h, 0.3), singular = record_at(h, 1e-9);
    stable.pc = 1, singular.pc = 0;
    rows.insert(rows.begin(), {decaying, stable, singular});
  }
  auto alone = record_at(0.5, 0.3);
  alone.p = 4;
  rows.push_back(alone);
  const auto verdicts = studies::fit_verdicts(rows, 3);
  ASSERT_EQ(verdicts.n_rows(), 4u);
  std::vector<std::string> seen;
  for (const auto& row : verdicts.rows()) {
    seen.push_back(std::get<std::string>(row.back()));
    EXPECT_EQ(std::get<std::string>(row[0]), "friction");
    EXPECT_EQ(std::get<std::string>(row[1]), "extension");
    EXPECT_EQ(std::get<std::string>(row[4]), "dual-modified");
    EXPECT_DOUBLE_EQ(std::get<double>(row[5]), 0.5);
    if (seen.back() == "decaying") {
      EXPECT_NEAR(std::get<double>(row[6]), 1.0, 1e-12);
      EXPECT_NEAR(std::get<double>(row[7]), 2.0, 1e-12);
      EXPECT_DOUBLE_EQ(std::get<double>(row[8]), 0.125);
    }
  }
  // Ordered by (problem, norm, p, pC, family, ratio): p = 3 with pC 0, 1, 2, then p = 4.
  EXPECT_EQ(seen, (std::vector<std::string>{"singular", "stable", "decaying", "too_few_levels"}));
}
