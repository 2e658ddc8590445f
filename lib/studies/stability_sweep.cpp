// Reading a stability sweep, running it (SweepSchedule hands out the points, SweepEvaluation
// computes them) and merging the folders of its slices.
#include "studies/stability_sweep.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <charconv>
#include <memory>

#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "core/rank_groups.hpp"
#include "io/atomic_file.hpp"
#include "io/toml_reader.hpp"
#include "studies/sweep_evaluation.hpp"
#include "studies/sweep_folder.hpp"
#include "studies/sweep_level_facts.hpp"
#include "studies/sweep_plan.hpp"
#include "studies/sweep_rows.hpp"
#include "studies/sweep_schedule.hpp"

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
  sweep.families.clear();
  for (const auto& family : table.string_list("family", std::vector<std::string>{space::to_string(first.family)}))
    sweep.families.push_back(space::parse_multiplier_family(family, path, "sweep.family"));
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

std::vector<infsup::InfSupRecord> merge_sweep_shards(const StabilitySweep& sweep,
                                                     const std::vector<std::filesystem::path>& shards,
                                                     const std::filesystem::path& alpha_csv) {
  const auto points = list_sweep_points(sweep);
  const auto identity = sweep_identity(sweep);
  AlphaRows merged(points);
  for (const auto& folder : shards) {
    const auto file = folder / "alpha.csv";
    if (!std::filesystem::exists(file) && existing_shards(file).empty())
      throw_bad_input("command line", "--merge", folder.string(), "a folder with an alpha.csv of this sweep");
    claim_sweep_folder(folder, identity, true);
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
  // Rows without an identity are refused at a resume, so a merge stopped half-way leaves no rows
  // that pass for another study's.
  const auto folder = alpha_csv.parent_path();
  std::filesystem::remove(identity_path(folder));
  for (const auto& stale : existing_shards(alpha_csv)) std::filesystem::remove(stale);  // (superseded)
  io::write_file_atomically(alpha_csv, merged.content());
  write_sweep_identity(folder, identity);
  return merged.records();
}

void check_sweep_ranks(const SweepRanks& sweep_ranks, int ranks) {
  const std::string value = std::to_string(sweep_ranks.per_unit);
  if (sweep_ranks.per_unit < 1 || ranks % sweep_ranks.per_unit != 0)
    throw_bad_input("command line", "--ranks-per-unit", value,
                    fmt::format("a divisor of the {} rank{} of this run (the ranks form groups of equal size)", ranks,
                                ranks > 1 ? "s" : ""));
}

SweepOutcome run_stability_sweep(const StabilitySweep& sweep, const std::filesystem::path& alpha_csv,
                                 const SweepProgress& progress, SweepShard shard, SweepRanks sweep_ranks) {
  check_sweep_ranks(sweep_ranks, mpi_rank_and_size().second);
  // The groups of ranks that take units (a group's leader, its rank 0, takes them and keeps their
  // rows), the points and the rows an earlier run stored.
  const RankGroups ranks(sweep_ranks.per_unit);
  const auto points = list_sweep_points(sweep);
  AlphaRows rows(points);
  rows.read(alpha_csv, mpi_rank_and_size().first == 0);
  SweepEvaluation evaluation(sweep, points, linalg::distribution_over(ranks.group(), sweep_ranks.solver));
  SweepSchedule schedule(sweep, points, rows, shard, ranks);
  const SweepWork work{[&](const SweepGroup& group) {
                         return [&evaluation, built = evaluation.start_group(group)](const SweepPoint& point) {
                           return evaluation.evaluate_point(point, *built);
                         };
                       },
                       [&](std::size_t share) { evaluation.release_share(share); }};
  schedule.run(work, rows, alpha_csv, progress);
  return {rows.records(), rows.complete()};
}

}  // namespace hpcontact::studies
