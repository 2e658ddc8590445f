// write_run_outputs: the staging folder made by rank 0, its path broadcast, pieces written by
// every rank, then rank 0's files and the commit — each step agreed over the ranks.
#include "driver/run_outputs.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <memory>
#include <optional>

#include "core/interrupt.hpp"
#include "core/petsc_session.hpp"
#include "core/rank_agreement.hpp"
#include "io/atomic_file.hpp"
#include "io/line_samples_vtu.hpp"
#include "io/output_folder.hpp"
#include "io/vtk_xml_document.hpp"
#include "io/vtu_writer.hpp"

namespace hpcontact::driver {

namespace {

// Beside the PVTU, not in a subfolder: the staging folder's clean-up on an interrupt and its sync
// before the commit cover the files of one flat folder.
std::string piece_name(const std::string& name, int rank) { return fmt::format("{}_rank{:04d}.vtu", name, rank); }

// The staging folder's path from rank 0 to every rank of `ranks` (one rank: MPI may not be running).
std::filesystem::path broadcast_path(const std::filesystem::path& path, MPI_Comm ranks, int size) {
  if (size == 1) return path;
  std::string text = path.string();
  long length = static_cast<long>(text.size());
  MPI_Bcast(&length, 1, MPI_LONG, 0, ranks);
  text.resize(static_cast<std::size_t>(length));
  MPI_Bcast(text.data(), static_cast<int>(length), MPI_CHAR, 0, ranks);
  return text;
}

}  // namespace

SolutionFile built_now(SolutionFile file) {
  auto grid = std::make_shared<io::VtuGrid>(file.grid());
  file.grid = [grid] { return std::move(*grid); };
  return file;
}

std::string solution_file_name(const std::string& name, bool distributed) {
  return name + (distributed ? ".pvtu" : ".vtu");
}

void write_run_outputs(const std::filesystem::path& out, const linalg::Distribution& distribution,
                       const std::vector<SolutionFile>& solutions,
                       const std::function<void(const std::filesystem::path& folder)>& write_rest) {
  const bool distributed = distribution.distributed();
  const MPI_Comm ranks = distributed ? distribution.ranks : MPI_COMM_WORLD;
  const auto [rank, size] = distributed ? rank_and_size(ranks) : mpi_rank_and_size();
  std::optional<io::OutputFolder> folder;
  run_on_all_ranks_agreeing(
      [&, rank = rank] {
        if (rank == 0) folder.emplace(out);
      },
      ranks);
  const std::filesystem::path staging = broadcast_path(folder ? folder->path() : std::filesystem::path(), ranks, size);
  // On an interrupt every rank's handler empties the staging folder and removes it: rank 0's
  // alone (OutputFolder registers it there) could meet another rank's temporary piece not yet
  // removed, fail to remove the folder and leave it behind. Whichever handler runs last finds it
  // empty. (After the commit the path no longer exists and the handler does nothing.)
  struct InterruptCleanup {
    int slot = -1;
    ~InterruptCleanup() { release_file_in_progress(slot); }
  } cleanup;
  if (distributed && rank != 0) cleanup.slot = register_folder_in_progress(staging.string());
  if (distributed)
    run_on_all_ranks_agreeing(
        [&, rank = rank] {
          for (const auto& solution : solutions)
            io::write_file_atomically(staging / piece_name(solution.name, rank), io::vtu_text(solution.grid()));
        },
        ranks);
  run_on_all_ranks_agreeing(
      [&, rank = rank, size = size] {
        if (rank != 0) return;
        for (const auto& solution : solutions) {
          const auto file = staging / solution_file_name(solution.name, distributed);
          if (!distributed) {
            io::write_file_atomically(file, io::vtu_text(solution.grid()));
            continue;
          }
          std::vector<std::string> pieces;
          for (int r = 0; r < size; ++r) pieces.push_back(piece_name(solution.name, r));
          io::write_file_atomically(file, io::pvtu_text(pieces, solution.fields));
        }
        write_rest(staging);
        folder->commit();
      },
      ranks);
}

std::string level_file_name(const std::string& problem, int level) {
  return fmt::format("solution_{}_level{}", problem, level);
}

OutputText level_collection(const std::string& problem, int finest, bool distributed) {
  std::vector<io::PvdEntry> entries;
  for (int k = 0; k <= finest; ++k)
    entries.push_back({static_cast<double>(k), solution_file_name(level_file_name(problem, k), distributed)});
  return {"solution_" + problem + ".pvd", io::pvd_text(entries)};
}

void write_sample_files(const scene::Scene& scene, const std::filesystem::path& folder, const std::string& name,
                        const io::CsvTable& samples) {
  if (scene.wants_output(scene::Output::boundary)) samples.write(folder / ("boundary_" + name + ".csv"));
  if (scene.wants_output(scene::Output::vtu))
    io::write_file_atomically(folder / ("contact_" + name + ".vtu"), io::line_samples_vtu_text(samples));
}

}  // namespace hpcontact::driver
