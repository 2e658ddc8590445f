// Reading, running and fitting stability sweeps.
#include "studies/stability_sweep.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <charconv>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "core/rank_agreement.hpp"
#include "core/rank_groups.hpp"
#include "core/shared_counter.hpp"
#include "driver/elastic_scene.hpp"
#include "driver/scene_discretization.hpp"
#include "io/atomic_file.hpp"
#include "io/toml_reader.hpp"
#include "mesh/boundary_mesh.hpp"
#include "mesh/contact_boundary.hpp"
#include "norms/h_minus_half_gram.hpp"
#include "operators/elastic_operators.hpp"
#include "operators/primal_operators.hpp"
#include "scene/scene_mesh.hpp"
#include "space/multiplier_space.hpp"
#include "studies/sweep_level_facts.hpp"
#include "studies/sweep_plan.hpp"
#include "studies/sweep_rows.hpp"

namespace hpcontact::studies {

namespace {

std::vector<int> to_int(const std::vector<long long>& values) { return {values.begin(), values.end()}; }

}  // namespace

StabilitySweep read_stability_sweep(const std::string& path, MPI_Comm ranks) {
  const io::TomlTable root = io::parse_toml_file(path);
  StabilitySweep sweep;
  sweep.file = path;
  const auto table = root.table("sweep", true);
  const std::string base = (std::filesystem::path(path).parent_path() / table.string("scene")).string();
  if (!std::filesystem::is_regular_file(base))
    throw_bad_input(path, "sweep.scene", table.string("scene"),
                    "a scene file, relative to the sweep file (" + base + " does not exist)");
  table.has("set");
  table.has("levels");
  sweep.levels = scene::scene_variants(base, table.table("set"), table.table("levels"), path + ": key 'sweep.levels'");
  if (table.has("p")) sweep.degrees = to_int(table.integer_list("p", 1, 20));
  if (table.has("pC")) sweep.multiplier_degrees = to_int(table.integer_list("pC", 0, 19));
  sweep.pc_below_p = table.choice("pc_rule", {"below_p", "all"}, "below_p") == "below_p";
  for (const auto& r : table.string_list("ratio", std::vector<std::string>{}))
    sweep.ratios.push_back(scene::parse_ratio(r, path, "sweep.ratio"));
  const scene::Scene& first = sweep.levels.front().scene;
  for (const auto& norm : table.string_list("norm", std::vector<std::string>{infsup::to_string(first.norm)}))
    sweep.norms.push_back(infsup::parse_gram_norm(norm, path + ": key 'sweep.norm'"));
  for (const auto& problem : table.string_list("problem", std::vector<std::string>{infsup::to_string(first.problem)}))
    sweep.problems.push_back(infsup::parse_pairing_problem(problem, path + ": key 'sweep.problem'"));
  sweep.fit_levels = static_cast<int>(table.integer("fit_levels", 2, 20, 3));
  sweep.eigensolver = table.choice("eigensolver", {"slepc", "dense"}, "slepc");
  sweep.alpha_tolerance = table.number_in("alpha_tol", 1e-12, 0.1, 1e-4);
  table.reject_unknown_keys();
  if (root.has("reference"))
    throw_bad_input(path, "reference", "(table)",
                    "no longer read: the H^{-1/2} references are refined until alpha_error is below [sweep] alpha_tol");
  root.reject_unknown_keys();

  // Every level's meshes, degrees and data, checked now: a sweep does not stop half-way on input.
  sweep.level_facts = sweep_level_facts(sweep, base, ranks);
  return sweep;
}

std::vector<std::string> alpha_columns() {
  return {"problem", "norm",  "p",  "pC",    "level",       "n",     "m",     "h",      "h_min",
          "H",       "ratio", "Pi", "alpha", "alpha_error", "ndofs", "nmult", "seconds"};
}

namespace {

// What the points of one share (a level, or a (level, ratio): SweepGroup::share) have in common:
// per (norm, ratio) the Gram ladder of the envelope
// multiplier space, whose degree on each segment is the largest of the sweep's p_C there: every
// point's G is a principal submatrix of it (norms::restrict_gram), so one Gram matrix per
// reference level serves all p_C (and, for the extension norm, one reference at the sweep's
// largest p serves all p).
struct EnvelopeGram {
  std::unique_ptr<mesh::BoundaryMesh> boundary;
  std::unique_ptr<space::MultiplierSpace> multipliers;
  std::unique_ptr<norms::GramLadder> ladder;
};
struct ShareGrams {
  std::map<std::pair<infsup::GramNorm, std::size_t>, EnvelopeGram> envelopes;
};

// The sweep's points and what does not change while it runs.
struct SweepRun {
  const StabilitySweep& sweep;
  std::vector<SweepPoint> points;
  std::vector<std::optional<scene::Ratio>> ratios;
  std::map<std::pair<std::size_t, std::size_t>, std::set<int>> degrees_used;
  infsup::EigenBackend backend;
  int largest_p;
  /// The factorizations of a unit: serial, or over the ranks of this rank's group.
  linalg::Distribution distribution;
};

// T_h of one group (level, p) and its operators, shared by the group's points. Distributed, T_h
// and its degrees are on the group's first rank only (the operators and the extension norm's
// references send the others their parts), Γ_C on every rank.
struct GroupMesh {
  scene::Scene scene;
  driver::SceneMesh built;
  mesh::ContactBoundary contact;
  /// The operators of the scalar model, or of an elastic scene (its α pairs [S^p(T_h)]² with the
  /// normal and tangential multipliers): one of the two, each split over the group's ranks once.
  std::unique_ptr<operators::PrimalOperators> primal;
  std::unique_ptr<operators::ElasticOperators> elastic;
  GroupMesh(const scene::Scene& level_scene, linalg::Distribution distribution)
      : scene(level_scene),
        built(driver::build_scene_mesh_on_first_rank(scene, distribution)),
        contact(*built.contact_cells) {
    if (scene.is_elastic())
      elastic = driver::scene_elastic_operators(scene, built.mesh.get(), built.cell_degrees, nullptr, distribution);
    else
      primal =
          std::make_unique<operators::PrimalOperators>(built.mesh.get(), built.cell_degrees, nullptr, distribution);
  }
};

/// The scene's degrees on `mesh` where it is (distributed: the first rank), a failure raised on
/// every rank alike; empty elsewhere.
std::vector<int> cell_degrees_on_first_rank(const scene::Scene& scene, const mesh::Mesh* mesh,
                                            linalg::Distribution distribution) {
  std::vector<int> degrees;
  const auto evaluate = [&] {
    if (mesh) degrees = scene::scene_cell_degrees(scene, *mesh);
  };
  if (distribution.distributed())
    run_on_all_ranks_agreeing(evaluate, distribution.ranks);
  else
    evaluate();
  return degrees;
}

/// The envelope Gram ladder of the point's (norm, ratio) on its level, built on first use.
const EnvelopeGram& envelope_of(const SweepRun& run, const SweepPoint& point, const GroupMesh& group,
                                const mesh::BoundaryMesh& boundary, ShareGrams& grams) {
  auto& envelope = grams.envelopes[{point.gram, point.ratio}];
  if (envelope.multipliers) return envelope;
  const scene::Scene& level_scene = run.sweep.levels[point.level].scene;
  envelope.boundary = std::make_unique<mesh::BoundaryMesh>(boundary);
  std::vector<int> degrees(boundary.n_segments(), 0);
  for (int pc : run.degrees_used.at({point.level, point.ratio})) {
    const auto at_pc =
        scene::scene_segment_degrees(point_scene(level_scene, 0, pc, run.ratios[point.ratio]), group.contact, boundary);
    for (std::size_t k = 0; k < degrees.size(); ++k) degrees[k] = std::max(degrees[k], at_pc[k]);
  }
  envelope.multipliers = std::make_unique<space::MultiplierSpace>(*envelope.boundary, std::move(degrees));
  envelope.ladder = std::make_unique<norms::GramLadder>(
      point.gram == infsup::GramNorm::interpolation
          ? norms::interpolation_gram_ladder(*envelope.multipliers)
          : norms::extension_gram_ladder(
                group.built.mesh.get(),
                cell_degrees_on_first_rank(point_scene(level_scene, run.largest_p, -1, std::nullopt),
                                           group.built.mesh.get(), run.distribution),
                *envelope.multipliers, run.distribution));
  return envelope;
}

/// α of one point, as its line of alpha.csv.
std::string compute_point(const SweepRun& run, const SweepPoint& point, const GroupMesh& group, ShareGrams& grams) {
  const auto& sweep = run.sweep;
  const auto& ratio = run.ratios[point.ratio];
  const scene::Scene scene = point_scene(group.scene, 0, point.pc, ratio, point.pairing, point.gram);
  const auto boundary = scene::build_scene_boundary_mesh(scene, group.contact);
  auto segment_degrees = scene::scene_segment_degrees(scene, group.contact, boundary);
  auto setup = group.elastic ? driver::infsup_setup_of(scene, group.built.mesh.get(), group.built.cell_degrees,
                                                       boundary, std::move(segment_degrees), *group.elastic)
                             : driver::infsup_setup_of(scene, group.built.mesh.get(), group.built.cell_degrees,
                                                       boundary, std::move(segment_degrees), *group.primal);
  setup.alpha_tolerance = sweep.alpha_tolerance;
  const auto& envelope = envelope_of(run, point, group, boundary, grams);
  const norms::GramLadder ladder = norms::restricted_ladder(*envelope.ladder, *envelope.multipliers,
                                                            space::MultiplierSpace(boundary, setup.segment_degrees));
  setup.grams = &ladder;
  const auto result = infsup::analyse_infsup(setup, run.backend);
  const auto& facts = sweep.level_facts[point.level];
  io::CsvTable row(alpha_columns());
  row.add_row({point.problem, point.norm, static_cast<long long>(point.reported_p),
               static_cast<long long>(point.reported_pc), static_cast<long long>(point.level + 1),
               static_cast<long long>(facts.contact_edges), static_cast<long long>(point.m), result.h,
               facts.contact_h_min, result.H, ratio ? ratio->value : static_cast<double>(point.m) / facts.contact_edges,
               result.pi, result.alpha, result.alpha_error, static_cast<long long>(result.n_primal_dofs),
               static_cast<long long>(result.n_multiplier_dofs), result.seconds});
  const std::string text = row.to_string();
  return text.substr(text.find('\n') + 1);
}

}  // namespace

SweepShard parse_sweep_shard(const std::string& text, const std::string& origin) {
  const auto slash = text.find('/');
  int index = -1, count = 0;
  if (slash != std::string::npos) {
    const char* end = text.data() + text.size();
    const auto [after_index, e1] = std::from_chars(text.data(), text.data() + slash, index);
    const auto [after_count, e2] = std::from_chars(text.data() + slash + 1, end, count);
    if (e1 != std::errc() || after_index != text.data() + slash || e2 != std::errc() || after_count != end) index = -1;
  }
  if (index < 0 || count < 1 || index >= count)
    throw_bad_input(origin, "--shard", text, "i/N with 0 <= i < N, e.g. 3/16 (job i of an array of N)");
  return {index, count};
}

void merge_sweep_shards(const StabilitySweep& sweep, const std::vector<std::filesystem::path>& shards,
                        const std::filesystem::path& alpha_csv) {
  const auto points = list_sweep_points(sweep);
  AlphaRows merged(points);
  for (const auto& folder : shards) {
    const auto file = folder / "alpha.csv";
    if (!std::filesystem::exists(file) && existing_shards(file).empty())
      throw_bad_input("command line", "--merge", folder.string(), "a folder with an alpha.csv of this sweep");
    const auto conflicts = merged.merge_slice(file);
    if (!conflicts.empty())
      fmt::print(stderr,
                 "hpcontact: warning: {} has {} point{} that an earlier folder gives with other numbers (e.g. {}); "
                 "the earlier folder's rows are kept\n",
                 folder.string(), conflicts.size(), conflicts.size() > 1 ? "s" : "", conflicts.front());
  }
  std::vector<std::string> missing;
  for (const auto& point : points)
    if (!merged.has(point.key())) missing.push_back(point.key());
  if (!missing.empty())
    throw_bad_input("command line", "--merge", fmt::format("{} folder{}", shards.size(), shards.size() > 1 ? "s" : ""),
                    fmt::format("{} of the {} points are in none of them (e.g. {}): run or resume the slices (--shard "
                                "i/N) that own them, then merge again",
                                missing.size(), points.size(), missing.front()));
  io::write_file_atomically(alpha_csv, merged.content());
}

void check_sweep_ranks(const SweepRanks& sweep_ranks, int ranks) {
  const std::string value = std::to_string(sweep_ranks.per_unit);
  if (sweep_ranks.per_unit < 1 || ranks % sweep_ranks.per_unit != 0)
    throw_bad_input("command line", "--ranks-per-unit", value,
                    fmt::format("a divisor of the {} rank{} of this run (the ranks form groups of equal size)", ranks,
                                ranks > 1 ? "s" : ""));
}

bool run_stability_sweep(const StabilitySweep& sweep, const std::filesystem::path& alpha_csv,
                         const std::function<void(int, int, const std::string&)>& progress, SweepShard shard,
                         SweepRanks sweep_ranks) {
  // 1. The groups of ranks that take units, the points, the rows an earlier run stored, and the
  // plan of what is left. A group's leader (its rank 0) takes the units and keeps their rows.
  const int rank = mpi_rank_and_size().first;
  const int size = mpi_rank_and_size().second;
  check_sweep_ranks(sweep_ranks, size);
  const RankGroups groups(sweep_ranks.per_unit);
  const bool leader = groups.rank_in_group() == 0;
  const int workers = groups.n_groups();
  SweepRun run{sweep,
               list_sweep_points(sweep),
               ratio_choices(sweep),
               {},
               infsup::parse_eigen_backend(sweep.eigensolver, sweep.file),
               sweep.degrees.empty() ? 0 : *std::max_element(sweep.degrees.begin(), sweep.degrees.end()),
               linalg::distribution_over(groups.group(), sweep_ranks.solver)};
  run.degrees_used = multiplier_degrees_used(run.points);
  AlphaRows rows(run.points);
  rows.read(alpha_csv, rank == 0);
  // More processes than levels split the groups by ratio, so that each builds only the extension
  // references of its ratios (splitting a level by p instead repeats all of them): 10 slices of
  // the full grid 83 -> 44 s. With fewer, whole levels keep the processes busy and a split only
  // repeats each (level, p)'s factorizations per ratio (2 ranks: 71-77 -> 84 s). Slices decide by
  // their count alone, so that a slice's groups do not depend on the ranks it runs on.
  const bool split_ratios = (shard.count > 1 ? shard.count : workers) > static_cast<int>(sweep.levels.size());
  SweepPlan plan = plan_sweep(sweep, run.points, rows.keys(), split_ratios);
  if (shard.count > 1) {
    // The shard's groups come from the plan of the whole sweep, so they do not move when this
    // shard (or another) resumes with part of its rows stored.
    SweepPlan whole = plan_sweep(sweep, run.points, {}, split_ratios);
    HPC_VERIFY(whole.groups.size() == plan.groups.size(), "a sweep's groups must not depend on its stored rows");
    schedule_sweep_groups(whole, shard.count);
    for (std::size_t g = 0; g < plan.groups.size(); ++g)
      if (whole.groups[g].owner != shard.index) plan.groups[g].todo = false;
  }
  // The schedule on the groups decides whether shares stay whole (sweep_work_units).
  schedule_sweep_groups(plan, workers);

  // 2. Units of groups, taken in turn by whichever group of ranks is idle; every group saved
  // durably when it is finished: an interrupted sweep resumes from the last finished group. A
  // failure on one rank (bad data at a level, a full disk) ends its group's unit on every rank of
  // the group, lets no group take new work and ends the run on every rank.
  std::vector<std::pair<int, std::string>> new_rows;  // (point index, CSV line) under mpirun
  const auto units = sweep_work_units(plan, workers);
  const long n_units = static_cast<long>(units.size());
  SharedCounter next_unit;
  // A share's Gram ladders (a level's, or a (level, ratio)'s when groups are split by ratio) are
  // kept until no unit left to take holds the share (units are taken in order), so a rank that
  // takes a share's groups in several turns builds them once.
  std::map<std::size_t, ShareGrams> grams_of_share;
  std::map<std::size_t, long> last_unit_of_share;
  for (std::size_t u = 0; u < units.size(); ++u)
    for (std::size_t g : units[u]) last_unit_of_share[plan.groups[g].share] = static_cast<long>(u);
  // The progress count: points stored before and points computed by all ranks, of those stored and
  // those to do in this run (a slice's own).
  SharedCounter points_computed;
  const int stored =
      static_cast<int>(std::ranges::count_if(run.points, [&](const SweepPoint& p) { return rows.has(p.key()); }));
  int total = stored;
  for (const SweepGroup& g : plan.groups)
    for (std::size_t k = g.first; g.todo && k < g.last; ++k)
      total += g.holds(run.points[k]) && !rows.has(run.points[k].key());
  auto run_group = [&](const SweepGroup& g) {
    ShareGrams& grams = grams_of_share[g.share];
    const GroupMesh group(point_scene(sweep.levels[g.level].scene, run.points[g.first].p, -1, std::nullopt),
                          run.distribution);
    std::string group_lines;
    for (std::size_t k = g.first; k < g.last; ++k) {
      const SweepPoint& point = run.points[k];
      if (!g.holds(point) || rows.has(point.key())) continue;
      const auto& ratio = run.ratios[point.ratio];
      if (progress && leader)
        progress(stored + static_cast<int>(points_computed.value()) + 1, total,
                 fmt::format("{} {} p={} pC={} {}{}", point.problem, point.norm, point.reported_p, point.reported_pc,
                             level_name(sweep, g.level), ratio ? " h/H=" + ratio->text : ""));
      const std::string line = compute_point(run, point, group, grams);
      if (leader) points_computed.take();
      rows.set(point.key(), line);
      group_lines += line;
      if (size > 1 && leader) new_rows.emplace_back(static_cast<int>(k), line);
    }
    if (size == 1)
      io::write_file_atomically(alpha_csv, rows.content());
    else  // the leader writes; its failure (a full disk) ends the group's unit on all its ranks
      run_on_all_ranks_agreeing(
          [&] {
            if (leader && !group_lines.empty()) append_durably(shard_path(alpha_csv, rank), group_lines);
          },
          groups.group());
  };
  // The leader takes the next unit and tells the rest of its group.
  auto take_unit = [&] {
    long unit = leader ? next_unit.take() : 0;
    if (groups.group_size() > 1) MPI_Bcast(&unit, 1, MPI_LONG, 0, groups.group());
    return unit;
  };
  run_on_all_ranks_agreeing([&] {
    try {
      for (;;) {
        try {
          const long unit = take_unit();
          if (unit >= n_units) break;
          std::erase_if(grams_of_share, [&](const auto& held) { return last_unit_of_share[held.first] < unit; });
          for (std::size_t g : units[static_cast<std::size_t>(unit)]) run_group(plan.groups[g]);
        } catch (...) {
          // A group's collective failure (a solve that failed, the leader's write) is raised on all
          // its ranks; a rank failing alone would wait for the others forever in the agreement
          // below, while they wait in the unit's collective calls: it ends the job instead.
          group_fails_within(groups.failure_channel(), kFailurePatience);
          throw;
        }
      }
    } catch (...) {
      if (leader) next_unit.exhaust(n_units);
      throw;
    }
  });
  // 3. Every rank's rows into alpha.csv (rank 0), in the serial order, and the shards removed
  // once it is complete.
  run_on_all_ranks_agreeing([&] {
    if (size > 1)
      for (const auto& [point_index, line] : gather_rows_on_rank_zero(new_rows))
        rows.set(run.points[static_cast<std::size_t>(point_index)].key(), line);
    if (rank == 0) {
      io::write_file_atomically(alpha_csv, rows.content());
      for (const auto& rank_shard : existing_shards(alpha_csv)) std::filesystem::remove(rank_shard);
    }
  });
  return std::ranges::all_of(run.points, [&](const SweepPoint& point) { return rows.has(point.key()); });
}

}  // namespace hpcontact::studies
