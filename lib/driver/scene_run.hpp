// Running a scene: exactly the effects its [run] table asks for (contact problems, the inf-sup
// constant, convergence under refinement), building each operator at most once, then writing the
// outputs it asks for. One pipeline for every model (model.hpp); `hpcontact solve` is this
// function plus option parsing and printing.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <string>

#include "driver/run_result.hpp"
#include "io/csv_writer.hpp"
#include "io/vtu_writer.hpp"
#include "linalg/distribution.hpp"
#include "scene/scene.hpp"

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
  /// If given, receives every solution the run writes as a VTU (output "vtu"), as its arrays, by
  /// the file's stem without "solution_" ("signorini", "frictionless_bottom"): this rank's cells.
  std::map<std::string, io::VtuGrid>* fields = nullptr;
  /// Write the output files into `out`; false: only return the result (and fill `tables`).
  bool write_files = true;
};

/// Runs the effects of `scene` (scalar model or elastic body) and writes into `out`:
///   summary.json              (output "summary") the RunResult (summary_json.hpp)
///   boundary_<problem>.csv    (output "boundary") the fields sampled on Γ_C: x,u,obstacle|s,lambda,
///                             y,s_arc,zone (scalar); x,y,s_arc,u_n,u_t,gap,pressure,traction_t,
///                             sigma_xx,sigma_yy,sigma_zz,sigma_xy,zone (elastic)
///   solution_<problem>.vtu    (output "vtu") u and ∇u (scalar) or the displacement and von Mises
///                             stress (elastic) on Ω, VTK Lagrange cells of the largest p; under
///                             mpirun solution_<problem>.pvtu naming one piece per rank,
///                             solution_<problem>_rank<r>.vtu (that rank's cells)
///   contact_<problem>.vtu     (output "vtu") the boundary samples on Γ_C, line cells along each zone
///   solution_<problem>_level<k>.vtu (.pvtu), solution_<problem>.pvd
///                             (output "vtu", effect convergence) u on every level, as a series
///   mode.csv                  (output "mode", effect infsup) the eigenvector of α
///   convergence.csv           (effect convergence) problem,level,p,pC,n,m,ndofs,nmult,energy,
///                              error_energy,error_lambda,seconds,p_rule,pC_rule; p and pC the
///                              largest degrees (numbers), p_rule and pC_rule as the scene writes
///                              them (a number or a rule's text); errors against the finest level
/// Nothing is written unless every effect succeeded.
RunResult run_scene(const scene::Scene& scene, const SceneRunOptions& options);

/// convergence.csv's rows as a table (the columns above).
io::CsvTable convergence_table(const std::vector<ConvergenceRow>& rows);

}  // namespace hpcontact::driver
