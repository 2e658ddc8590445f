// Running a scene: exactly the effects its [run] table asks for (contact problems (9), (13), (15),
// the inf-sup constant, convergence under refinement), building each operator at most once, then
// writing the outputs it asks for. `hpcontact solve` is this function plus option parsing.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "driver/scene_discretization.hpp"
#include "io/csv_writer.hpp"
#include "linalg/distribution.hpp"
#include "scene/scene_mesh.hpp"
#include "scene/scene_reader.hpp"

namespace hpcontact::driver {

struct SceneRunOptions {
  std::filesystem::path out;                         ///< output folder (created when everything is computed)
  std::function<void(const std::string&)> progress;  ///< one line per step, if given
  /// Under mpirun: every rank runs the scene with K and A_G factorized over the ranks by this
  /// solver; rank 0 writes the files, and each rank its piece of the ParaView files.
  linalg::Distribution distribution = {};  ///< serial
  /// If given, receives every table the run writes, by file stem ("boundary_signorini", "mode",
  /// "convergence"), so that callers (the Python module) get the data without files.
  std::map<std::string, io::CsvTable>* tables = nullptr;
  /// Write the output files into `out`; false: only return the summary (and fill `tables`).
  bool write_files = true;
};

/// Runs the effects of `scene` and writes into `out`:
///   summary.json              (output "summary") every effect's results, the operators built with
///                              their sizes and seconds, and timings
///   boundary_<problem>.csv    (output "boundary") u, obstacle or bound, λ sampled on Γ_C
///   solution_<problem>.vtu    (output "vtu") u and ∇u on Ω, VTK Lagrange cells of the largest p;
///                             under mpirun solution_<problem>.pvtu naming one piece per rank,
///                             solution_<problem>_rank<r>.vtu (that rank's cells)
///   contact_<problem>.vtp     (output "vtu") the boundary samples on Γ_C, one polyline per zone
///   solution_<problem>_level<k>.vtu (.pvtu), solution_<problem>.pvd
///                             (output "vtu", effect convergence) u on every level, as a series
///   mode.csv                  (output "mode", effect infsup) the eigenvector of α
///   convergence.csv           (effect convergence) problem,level,p,pC,n,m,ndofs,nmult,energy,
///                              error_energy,error_lambda,seconds,p_rule,pC_rule; p and pC the
///                              largest degrees (numbers), p_rule and pC_rule as the scene writes
///                              them (a number or a rule's text); errors against the finest level
/// Nothing is written unless every effect succeeded. Returns the summary.
nlohmann::json run_scene(const scene::Scene& scene, const SceneRunOptions& options);

/// The inf-sup effect on `setup` (α, its error, whether λ is unique, Π, the eigensolver) as the
/// "infsup" entry of summary.json; with output "mode" the sampled eigenvector into `mode`.
nlohmann::json infsup_effect(const scene::Scene& scene, const SceneDiscretization& d, const infsup::InfSupSetup& setup,
                             std::optional<io::CsvTable>& mode);

/// Hands a run's tables to options.tables, if set: the boundary samples of each problem (as
/// "boundary_<problem>"), mode and convergence where computed.
void hand_over_tables(const SceneRunOptions& options,
                      const std::vector<std::pair<std::string, const io::CsvTable*>>& boundary,
                      const std::optional<io::CsvTable>& mode, const std::optional<io::CsvTable>& convergence);

/// A contact problem's sample files into `folder`: boundary_<name>.csv (output "boundary") and
/// contact_<name>.vtp (output "vtu").
void write_sample_files(const scene::Scene& scene, const std::filesystem::path& folder, const std::string& name,
                        const io::CsvTable& samples);

/// A file of the output folder made before the folder is written: its name and content.
struct OutputText {
  std::string name, text;
};
/// The solution file of level k of the convergence effect: solution_<problem>_level<k> (.vtu, or
/// .pvtu when distributed: driver::solution_file_name).
std::string level_file_name(const std::string& problem, int level);
/// solution_<problem>.pvd: the levels 0 … `finest` of a problem with the level as ParaView's time.
OutputText level_collection(const std::string& problem, int finest, bool distributed);

/// summary.json's "operators": each operator built, with its size and seconds, and for a
/// factorization solved by iterations (BDDC) "iterations": {solves, total, most}.
nlohmann::json operators_summary(const OperatorLog& log);

/// Appends the operator records of convergence level `level` to the run's `log`, each named
/// "<name> (convergence level <level>)".
void append_level_log(const OperatorLog& level_log, int level, OperatorLog& log);

/// The columns of convergence.csv and of the work–precision study's rows.
std::vector<std::string> refinement_columns();
/// The largest of a level's degrees: the numeric p and pC of a convergence row (a degree rule's
/// text goes into p_rule, pC_rule).
long long largest_degree(const std::vector<int>& degrees);

}  // namespace hpcontact::driver
