// `hpcontact sweep STUDY.toml --out DIR`: α over a grid of (problem, norm, p, p_C, n, h/H) into
// DIR/alpha.csv (resumable), then rate fits and verdicts into DIR/verdicts.csv; with --shard i/N
// one slice of it (a job of an array), with --merge DIR… the slices' rows into one alpha.csv.
#include <fmt/format.h>
#include <mpi.h>

#include <filesystem>
#include <memory>

#include "commands.hpp"
#include "core/petsc_session.hpp"
#include "core/rank_agreement.hpp"
#include "core/timer.hpp"
#include "io/atomic_file.hpp"
#include "progress_bar.hpp"
#include "studies/stability_sweep.hpp"
#include "studies/sweep_folder.hpp"

namespace hpcontact::tools {
namespace {

struct SweepOptions {
  std::string study_file, out_dir = "results/stability";
  bool restart = false;
  std::string shard;
  std::vector<std::string> merge_dirs;
  int ranks_per_unit = 1;
  std::string distributed_solver = "substructuring";
};

void add_sweep_options(CLI::App& command, SweepOptions& o) {
  command.add_option("study", o.study_file, "Sweep file (TOML), e.g. studies/stability/study.toml")
      ->required()
      ->check(CLI::ExistingFile);
  command.add_option("--out", o.out_dir, "Output folder (points already in alpha.csv are skipped)")
      ->capture_default_str();
  command.add_flag("--restart", o.restart, "Start afresh: replace DIR/alpha.csv instead of resuming it");
  command.add_option("--shard", o.shard,
                     "i/N: compute only slice i (0 <= i < N) of the sweep, e.g. one job of a batch array, each slice "
                     "with its own --out folder; merge the slices' folders with --merge");
  command
      .add_option("--merge", o.merge_dirs,
                  "Folders of --shard runs: their rows into DIR/alpha.csv (every point must be in one), then "
                  "the verdicts")
      ->excludes("--shard")
      ->excludes("--restart");
  command
      .add_option("--ranks-per-unit", o.ranks_per_unit,
                  "Under mpirun: groups of this many ranks take units together, each unit's factorizations (K + M "
                  "and the extension norm's references) distributed over its group; it must divide the ranks")
      ->capture_default_str();
  command
      .add_option("--distributed-solver", o.distributed_solver,
                  "With --ranks-per-unit > 1: substructuring (CHOLMOD per rank, dense interface) | mumps (MPIAIJ + "
                  "MUMPS) | bddc (MATIS + CG with PCBDDC)")
      ->capture_default_str();
}

// The verdicts of `rows` into DIR/verdicts.csv; returns how many configurations it holds.
std::size_t write_verdicts(const studies::StabilitySweep& sweep, const std::vector<infsup::InfSupRecord>& rows,
                           const std::filesystem::path& verdicts_csv) {
  const auto verdicts = studies::fit_verdicts(rows, sweep.fit_levels);
  verdicts.write(verdicts_csv);
  return verdicts.n_rows();
}

// Merging is quick and serial: rank 0 writes, the others wait for the outcome.
int merge_slices(const SweepOptions& o, const studies::StabilitySweep& sweep) {
  const auto alpha_csv = std::filesystem::path(o.out_dir) / "alpha.csv";
  const auto verdicts_csv = std::filesystem::path(o.out_dir) / "verdicts.csv";
  run_on_all_ranks_agreeing([&] {
    if (mpi_rank_and_size().first != 0) return;
    const studies::FolderLock lock(o.out_dir);
    const auto rows = studies::merge_sweep_shards(sweep, {o.merge_dirs.begin(), o.merge_dirs.end()}, alpha_csv);
    const auto configurations = write_verdicts(sweep, rows, verdicts_csv);
    fmt::print("merged {} folders into {} and {} ({} configurations)\n", o.merge_dirs.size(), alpha_csv.string(),
               verdicts_csv.string(), configurations);
  });
  return 0;
}

// One sweep per folder at a time: rank 0 takes the lock, held until the process ends, with
// --restart removes the old rows, and checks that stored rows are this study's, before any rank
// reads them.
std::unique_ptr<studies::FolderLock> open_folder(const SweepOptions& o, const studies::StabilitySweep& sweep) {
  std::unique_ptr<studies::FolderLock> lock;
  run_on_all_ranks_agreeing([&] {
    if (mpi_rank_and_size().first == 0) lock = studies::open_sweep_folder(sweep, o.out_dir, o.restart);
  });
  return lock;
}

int run_sweep(const SweepOptions& o) {
  // 1. Read and check the whole sweep before computing anything.
  const auto sweep = studies::read_stability_sweep(o.study_file);
  const studies::SweepShard shard =
      o.shard.empty() ? studies::SweepShard{} : studies::parse_sweep_shard(o.shard, "command line");
  const studies::SweepRanks sweep_ranks{
      o.ranks_per_unit, linalg::parse_distributed_solver(o.distributed_solver, "command line", "--distributed-solver")};
  const int rank = mpi_rank_and_size().first, size = mpi_rank_and_size().second;
  studies::check_sweep_ranks(sweep_ranks, size);
  io::ensure_writable_directory(o.out_dir);
  if (!o.merge_dirs.empty()) return merge_slices(o, sweep);
  const auto alpha_csv = std::filesystem::path(o.out_dir) / "alpha.csv";
  const auto lock = open_folder(o, sweep);
  // 2. Run, with a progress line on stderr when it is a terminal (rank 0 only under mpirun).
  Stopwatch clock;
  const auto bar = progress_bar(rank == 0);
  const auto outcome = studies::run_stability_sweep(
      sweep, alpha_csv,
      [&](int done, int total, double work_done, const std::string& label) {
        if (bar) bar(done - 1, total, work_done, label);
      },
      shard, sweep_ranks);
  finish_progress_bar(bar);
  // 3. Fit rates and write verdicts (rank 0, which holds every row); a shard's rows wait for --merge.
  if (rank != 0) return 0;
  const std::string ranks = fmt::format("{:.1f} s on {} rank{}", clock.seconds(), size, size > 1 ? "s" : "");
  if (!outcome.complete) {
    fmt::print("wrote {} (slice {}/{}, {}); merge the slices with: hpcontact sweep {} --merge DIR... --out DIR\n",
               alpha_csv.string(), shard.index, shard.count, ranks, o.study_file);
    return 0;
  }
  const auto verdicts_csv = std::filesystem::path(o.out_dir) / "verdicts.csv";
  const auto configurations = write_verdicts(sweep, outcome.rows, verdicts_csv);
  fmt::print("wrote {} and {} ({} configurations, {})\n", alpha_csv.string(), verdicts_csv.string(), configurations,
             ranks);
  return 0;
}

}  // namespace

void add_sweep_command(CLI::App& app, CommandAction& action) {
  auto* command =
      app.add_subcommand("sweep", "Stability sweep over p, pC, n, h/H, norms, problems: alpha.csv and verdicts.csv");
  auto options = std::make_shared<SweepOptions>();
  add_sweep_options(*command, *options);
  command->callback([&action, options] { action = [options] { return run_sweep(*options); }; });
}

}  // namespace hpcontact::tools
