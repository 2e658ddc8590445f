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
#include "studies/sweep_rows.hpp"

namespace hpcontact::tools {

void add_sweep_command(CLI::App& app, CommandAction& action) {
  auto* command =
      app.add_subcommand("sweep", "Stability sweep over p, pC, n, h/H, norms, problems: alpha.csv and verdicts.csv");
  auto study_file = std::make_shared<std::string>();
  auto out_dir = std::make_shared<std::string>("results/stability");
  command->add_option("study", *study_file, "Sweep file (TOML), e.g. studies/stability/study.toml")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--out", *out_dir, "Output folder (points already in alpha.csv are skipped)")
      ->capture_default_str();
  auto restart = std::make_shared<bool>(false);
  command->add_flag("--restart", *restart, "Start afresh: replace DIR/alpha.csv instead of resuming it");
  auto shard_text = std::make_shared<std::string>();
  command->add_option("--shard", *shard_text,
                      "i/N: compute only slice i (0 <= i < N) of the sweep, e.g. one job of a batch array, each slice "
                      "with its own --out folder; merge the slices' folders with --merge");
  auto merge_dirs = std::make_shared<std::vector<std::string>>();
  command
      ->add_option("--merge", *merge_dirs,
                   "Folders of --shard runs: their rows into DIR/alpha.csv (every point must be in one), then "
                   "the verdicts")
      ->excludes("--shard")
      ->excludes("--restart");
  auto ranks_per_unit = std::make_shared<int>(1);
  command
      ->add_option("--ranks-per-unit", *ranks_per_unit,
                   "Under mpirun: groups of this many ranks take units together, each unit's factorizations (K + M "
                   "and the extension norm's references) distributed over its group; it must divide the ranks")
      ->capture_default_str();
  auto solver_text = std::make_shared<std::string>("substructuring");
  command
      ->add_option("--distributed-solver", *solver_text,
                   "With --ranks-per-unit > 1: substructuring (CHOLMOD per rank, dense interface) | mumps (MPIAIJ + "
                   "MUMPS) | bddc (MATIS + CG with PCBDDC)")
      ->capture_default_str();
  command->callback([&action, study_file, out_dir, restart, shard_text, merge_dirs, ranks_per_unit, solver_text] {
    action = [study_file, out_dir, restart, shard_text, merge_dirs, ranks_per_unit, solver_text] {
      // 1. Read and check the whole sweep before computing anything.
      const auto sweep = studies::read_stability_sweep(*study_file);
      const studies::SweepShard shard =
          shard_text->empty() ? studies::SweepShard{} : studies::parse_sweep_shard(*shard_text, "command line");
      const studies::SweepRanks sweep_ranks{
          *ranks_per_unit, linalg::parse_distributed_solver(*solver_text, "command line", "--distributed-solver")};
      studies::check_sweep_ranks(sweep_ranks, mpi_rank_and_size().second);
      io::ensure_writable_directory(*out_dir);
      const auto alpha_csv = std::filesystem::path(*out_dir) / "alpha.csv";
      const auto verdicts_csv = std::filesystem::path(*out_dir) / "verdicts.csv";
      if (!merge_dirs->empty()) {
        // Merging is quick and serial: rank 0 writes, the others wait for the outcome.
        run_on_all_ranks_agreeing([&] {
          if (mpi_rank_and_size().first != 0) return;
          const studies::FolderLock lock(*out_dir);
          studies::merge_sweep_shards(sweep, {merge_dirs->begin(), merge_dirs->end()}, alpha_csv);
          const auto verdicts = studies::fit_verdicts(alpha_csv, sweep.fit_levels);
          verdicts.write(verdicts_csv);
          fmt::print("merged {} folders into {} and {} ({} configurations)\n", merge_dirs->size(), alpha_csv.string(),
                     verdicts_csv.string(), verdicts.n_rows());
        });
        return 0;
      }
      const int rank = mpi_rank_and_size().first, size = mpi_rank_and_size().second;
      // One sweep per folder at a time (rank 0 holds the lock until the process ends).
      std::unique_ptr<studies::FolderLock> lock;
      run_on_all_ranks_agreeing([&] {
        if (rank != 0) return;
        lock = std::make_unique<studies::FolderLock>(*out_dir);
        if (*restart) {
          std::filesystem::remove(alpha_csv);
          for (const auto& shard : studies::existing_shards(alpha_csv)) std::filesystem::remove(shard);
        }
      });  // no rank reads the old files before they are gone
      // 2. Run, with a progress line on stderr when it is a terminal (rank 0 only under mpirun).
      Stopwatch clock;
      const auto bar = progress_bar(rank == 0);
      const bool complete = studies::run_stability_sweep(
          sweep, alpha_csv,
          [&](int done, int total, const std::string& label) {
            if (bar) bar(done - 1, total, label);
          },
          shard, sweep_ranks);
      finish_progress_bar(bar);
      // 3. Fit rates and write verdicts (rank 0; alpha.csv is complete on every rank here); a
      // shard's rows wait for --merge.
      if (rank != 0) return 0;
      if (!complete) {
        fmt::print(
            "wrote {} (slice {}/{}, {:.1f} s on {} rank{}); merge the slices with: hpcontact sweep {} --merge "
            "DIR... --out DIR\n",
            alpha_csv.string(), shard.index, shard.count, clock.seconds(), size, size > 1 ? "s" : "", *study_file);
        return 0;
      }
      const auto verdicts = studies::fit_verdicts(alpha_csv, sweep.fit_levels);
      verdicts.write(verdicts_csv);
      fmt::print("wrote {} and {} ({} configurations, {:.1f} s on {} rank{})\n", alpha_csv.string(),
                 verdicts_csv.string(), verdicts.n_rows(), clock.seconds(), size, size > 1 ? "s" : "");
      return 0;
    };
  });
}

}  // namespace hpcontact::tools
