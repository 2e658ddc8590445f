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

namespace hpcontact::driver {

/// One solution's ParaView file.
struct SolutionFile {
  std::string name;                                 ///< without extension: solution_file_name gives the file
  std::vector<std::pair<std::string, int>> fields;  ///< its point fields (name, components)
  std::string text;  ///< this rank's VTU: the whole mesh when serial, the rank's cells when distributed
};

/// The file a solution file `name` becomes: name.vtu serial, name.pvtu distributed (its pieces
/// name/rank_<r>.vtu beside it).
std::string solution_file_name(const std::string& name, bool distributed);

/// Writes the outputs into a staging folder and moves it into place at `out` (io::OutputFolder):
/// `write_rest(folder)` on rank 0, then `solutions` (pieces by every rank when distributed).
/// Collective on MPI_COMM_WORLD: a failure on any rank ends every rank with the same error, and
/// `out` keeps what it held.
void write_run_outputs(const std::filesystem::path& out, bool distributed, const std::vector<SolutionFile>& solutions,
                       const std::function<void(const std::filesystem::path& folder)>& write_rest);

}  // namespace hpcontact::driver
