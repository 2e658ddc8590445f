// The sweep's points, groups, cost estimates and schedule.
#include "studies/sweep_plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "studies/stability_sweep.hpp"
#include "studies/sweep_rows.hpp"

namespace hpcontact::studies {

std::string SweepPoint::key() const {
  return point_key(problem, norm, reported_p, reported_pc, family, static_cast<int>(level) + 1, m);
}

std::vector<std::optional<scene::Ratio>> ratio_choices(const StabilitySweep& sweep) {
  if (sweep.ratios.empty()) return {std::nullopt};
  return {sweep.ratios.begin(), sweep.ratios.end()};
}

scene::Scene point_scene(scene::Scene scene, const PointChoice& choice) {
  if (choice.p) scene.p = scene::Degree{*choice.p, {}};
  // A contact pair: the master's degree too (its multiplier space is not used).
  if (choice.p && scene.pair) {
    auto pair = std::make_shared<scene::ContactPair>(*scene.pair);
    pair->master.p = scene.p;
    scene.pair = std::move(pair);
  }
  if (choice.pc) scene.pc = scene::Degree{*choice.pc, {}};
  if (choice.ratio) {
    scene.ratio = {*choice.ratio};
    scene.m.clear();
    scene.breakpoints.clear();
  }
  if (choice.problem) scene.problem = *choice.problem;
  if (choice.norm) scene.norm = *choice.norm;
  if (choice.family) scene.family = *choice.family;
  return scene;
}

std::string level_name(const StabilitySweep& sweep, std::size_t level) {
  const auto& label = sweep.levels[level].label;
  return fmt::format("level {}{}", level + 1, label.empty() ? "" : " (" + label + ")");
}

std::vector<SweepPoint> list_sweep_points(const StabilitySweep& sweep) {
  const std::size_t ratios = ratio_choices(sweep).size();
  // No list: one choice, the scene's own degree.
  const auto choices = [](const std::vector<int>& list) {
    return list.empty() ? std::vector<std::optional<int>>{std::nullopt}
                        : std::vector<std::optional<int>>(list.begin(), list.end());
  };
  const auto degrees = choices(sweep.degrees), multiplier_degrees = choices(sweep.multiplier_degrees);
  std::vector<SweepPoint> points;
  for (std::size_t level = 0; level < sweep.levels.size(); ++level) {
    const auto& facts = sweep.level_facts[level];
    for (const auto p : degrees)
      for (const auto problem : sweep.problems)
        for (const auto norm : sweep.norms)
          for (const auto& family : sweep.families)
            for (const auto pc : multiplier_degrees)
              for (std::size_t r = 0; r < ratios; ++r) {
                const int reported_p = p.value_or(facts.scene_p), reported_pc = pc.value_or(facts.scene_pc[r]);
                if (sweep.pc_below_p && reported_pc >= reported_p) continue;
                if (family.kind != space::MultiplierFamilyKind::discontinuous && reported_pc < 1) continue;
                points.push_back({infsup::to_string(problem), infsup::to_string(norm), problem, norm, family, level, r,
                                  p, pc, reported_p, reported_pc, facts.segments[r]});
              }
  }
  return points;
}

std::map<std::pair<std::size_t, std::size_t>, std::set<std::optional<int>>> multiplier_degrees_used(
    const std::vector<SweepPoint>& points) {
  std::map<std::pair<std::size_t, std::size_t>, std::set<std::optional<int>>> used;
  for (const auto& point : points) used[{point.level, point.ratio}].insert(point.pc);
  return used;
}

SweepPlan plan_sweep(const StabilitySweep& sweep, const std::vector<SweepPoint>& points,
                     const std::set<std::string>& done, bool split_ratios) {
  SweepPlan plan;
  const std::size_t ratios = ratio_choices(sweep).size();
  const bool split = split_ratios && ratios > 1;
  plan.shared_cost.assign(sweep.levels.size() * (split ? ratios : 1), 0.0);
  const double largest_p = sweep.degrees.empty() ? 0.0 : *std::max_element(sweep.degrees.begin(), sweep.degrees.end());
  // Per share: the ratios whose extension references some point to do needs (one each).
  std::vector<std::set<std::size_t>> extension_ratios(plan.shared_cost.size());
  for (std::size_t first = 0; first < points.size();) {
    std::size_t last = first;
    while (last < points.size() && points[last].level == points[first].level && points[last].p == points[first].p)
      ++last;
    const std::size_t level = points[first].level;
    for (std::size_t r = 0; r < (split ? ratios : 1); ++r) {
      SweepGroup group{first, last, level, split ? level * ratios + r : level};
      if (split) group.ratio = r;
      int todo_points = 0;
      for (std::size_t k = first; k < last; ++k) {
        if (!group.holds(points[k]) || done.contains(points[k].key())) continue;
        group.todo = true;
        ++todo_points;
        if (points[k].gram == infsup::GramNorm::extension) {
          group.extension = true;
          extension_ratios[group.share].insert(points[k].ratio);
        }
      }
      const double cells = sweep.level_facts[level].cells, p = points[first].reported_p;
      const double dofs = cells * p * p;
      group.cost = std::pow(dofs, 1.2) + 0.05 * todo_points * dofs;
      if (group.extension) {
        const double largest = largest_p > 0 ? largest_p : p;
        const double reference = std::pow(4.0 * cells * (largest + 2) * (largest + 2), 1.2);
        plan.shared_cost[group.share] = reference * static_cast<double>(extension_ratios[group.share].size());
      }
      plan.groups.push_back(group);
    }
    first = last;
  }
  return plan;
}

namespace {

std::vector<std::size_t> longest_first(std::vector<std::size_t> order, const std::vector<double>& cost) {
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
  return order;
}

}  // namespace

double schedule_sweep_groups(SweepPlan& plan, int ranks) {
  auto& groups = plan.groups;
  const std::size_t shares = plan.shared_cost.size();
  std::vector<std::size_t> todo;
  std::vector<double> share_cost(shares, 0.0), group_cost;
  for (const auto& group : groups) group_cost.push_back(group.cost);
  for (std::size_t i = 0; i < groups.size(); ++i) {
    if (!groups[i].todo) continue;
    todo.push_back(i);
    share_cost[groups[i].share] += groups[i].cost;
  }
  std::vector<std::size_t> busy_shares;
  for (std::size_t share = 0; share < shares; ++share)
    if (share_cost[share] > 0) {
      share_cost[share] += plan.shared_cost[share];
      busy_shares.push_back(share);
    }
  // (a) Whole shares.
  std::vector<double> load(static_cast<std::size_t>(ranks), 0.0);
  std::vector<int> share_owner(shares, 0);
  for (std::size_t share : longest_first(busy_shares, share_cost)) {
    share_owner[share] = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
    load[static_cast<std::size_t>(share_owner[share])] += share_cost[share];
  }
  const double by_shares = *std::max_element(load.begin(), load.end());
  // (b) Single groups.
  std::fill(load.begin(), load.end(), 0.0);
  std::vector<int> group_owner(groups.size(), 0);
  std::set<std::pair<int, std::size_t>> has_share;  // (rank, share)
  for (std::size_t i : longest_first(todo, group_cost)) {
    const std::size_t share = groups[i].share;
    auto finish = [&](int r) {
      return load[static_cast<std::size_t>(r)] + groups[i].cost +
             (has_share.contains({r, share}) ? 0.0 : plan.shared_cost[share]);
    };
    int owner = 0;
    for (int r = 1; r < ranks; ++r)
      if (finish(r) < finish(owner)) owner = r;
    load[static_cast<std::size_t>(owner)] = finish(owner);
    has_share.insert({owner, share});
    group_owner[i] = owner;
  }
  const double by_groups = *std::max_element(load.begin(), load.end());
  plan.whole_shares = by_shares <= by_groups;
  for (std::size_t i : todo) groups[i].owner = plan.whole_shares ? share_owner[groups[i].share] : group_owner[i];
  return std::min(by_shares, by_groups);
}

std::vector<std::vector<std::size_t>> sweep_work_units(const SweepPlan& plan, int ranks) {
  std::vector<std::vector<std::size_t>> units;
  std::vector<double> cost;
  std::map<std::size_t, std::size_t> unit_of_share;
  for (std::size_t i = 0; i < plan.groups.size(); ++i) {
    const SweepGroup& group = plan.groups[i];
    if (!group.todo) continue;
    const auto share_unit = unit_of_share.find(group.share);
    std::size_t unit = units.size();
    if (plan.whole_shares && share_unit != unit_of_share.end()) {
      unit = share_unit->second;
    } else {
      units.emplace_back();
      cost.push_back(plan.shared_cost[group.share]);
      unit_of_share[group.share] = unit;
    }
    units[unit].push_back(i);
    cost[unit] += group.cost;
  }
  if (ranks == 1) return units;
  std::vector<std::size_t> order(units.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::vector<std::vector<std::size_t>> sorted;
  for (std::size_t k : longest_first(order, cost)) sorted.push_back(std::move(units[k]));
  return sorted;
}

}  // namespace hpcontact::studies
