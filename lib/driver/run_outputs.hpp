// A run's output folder written as one set, under mpirun too: rank 0 writes the tables and the
// summary; each solution's ParaView file is one VTU when serial, and when distributed a PVTU
// (written by rank 0) naming one VTU piece per rank, each rank writing its own cells — so no rank
// holds the whole field or the whole text.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "io/csv_writer.hpp"
#include "io/vtu_writer.hpp"
#include "linalg/distribution.hpp"
#include "scene/scene.hpp"

namespace hpcontact::driver {

/// One solution's ParaView file.
struct SolutionFile {
  std::string name;                                 ///< without extension: solution_file_name gives the file
  std::vector<std::pair<std::string, int>> fields;  ///< its point fields (name, components)
  /// This rank's VTU arrays (the whole mesh when serial, the rank's cells when distributed),
  /// built when the file is written (called once), so that one solution at a time is held.
  std::function<io::VtuGrid()> grid;
};

/// `file` with its arrays built now, for a solution whose operators end before the files are
/// written (a convergence level's).
SolutionFile built_now(SolutionFile file);

/// The file a solution file `name` becomes: name.vtu serial, name.pvtu distributed (its pieces
/// name_rank<r>.vtu beside it, r (4 digits) the rank in the distribution's communicator).
std::string solution_file_name(const std::string& name, bool distributed);

/// Writes the outputs into a staging folder and moves it into place at `out` (io::OutputFolder):
/// when distributed, every rank writes its pieces of `solutions`; then rank 0 writes their VTU
/// (serial) or PVTU files, calls `write_rest(folder)` and commits. Collective on the
/// distribution's ranks (serial: on MPI_COMM_WORLD, rank 0 writing): a failure on any rank ends
/// every rank with the same error, and `out` keeps what it held.
void write_run_outputs(const std::filesystem::path& out, const linalg::Distribution& distribution,
                       const std::vector<SolutionFile>& solutions,
                       const std::function<void(const std::filesystem::path& folder)>& write_rest);

/// A file of the output folder made before the folder is written: its name and content.
struct OutputText {
  std::string name, text;
};

/// The solution file of level k of the convergence effect: solution_<problem>_level<k> (.vtu, or
/// .pvtu when distributed: solution_file_name).
std::string level_file_name(const std::string& problem, int level);
/// solution_<problem>.pvd: the levels 0 … `finest` of a problem with the level as ParaView's time.
OutputText level_collection(const std::string& problem, int finest, bool distributed);

/// A contact problem's sample files into `folder`: boundary_<name>.csv (output "boundary") and
/// contact_<name>.vtu (output "vtu").
void write_sample_files(const scene::Scene& scene, const std::filesystem::path& folder, const std::string& name,
                        const io::CsvTable& samples);

}  // namespace hpcontact::driver
