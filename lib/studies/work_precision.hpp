// The work–precision study: what accuracy costs in time. Families of discretizations of a base
// scene (h-refinement at fixed p, p-refinement on a fixed mesh, geometric meshes with growing p)
// are solved for each contact problem and compared with a far finer reference whose own accuracy
// is estimated against a coarser one (one uniform refinement or a lower degree); references may
// be fitted to the free boundary.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "scene/scene_variants.hpp"

namespace hpcontact::studies {

/// A study file (TOML), e.g. studies/work_precision/study.toml; keys in studies/README.md:
///   [study]      scene (base scene, relative to the study file), problems, tolerances, repeats
///   [[reference]] problem, set (scene keys), coarser (scene keys of the accuracy estimate; default
///                one refinement less), fit_free_boundary
///   [[family]]   name, problems (default: all), set, vary (see scene/scene_variants.hpp); a family whose
///                set gives adapt.target runs the adaptivity (driver/adaptive_run.hpp): one row per step
struct WorkPrecisionStudy {
  std::string file;
  std::vector<std::string> problems;
  std::vector<double> tolerances;
  int repeats = 3;  ///< solves under 1 s are timed this many times; the fastest counts
  struct Reference {
    std::string problem;
    /// `coarser`: the scene with the reference's `coarser` keys applied (default: one uniform
    /// refinement less), for the accuracy estimate.
    scene::Scene scene, coarser;
    /// Grade both towards the free boundary, located iteratively (studies::fit_free_boundary).
    bool fit_free_boundary = false;
  };
  std::vector<Reference> references;  ///< one per problem, in `problems` order
  struct Family {
    std::string name;
    std::vector<std::string> problems;
    std::vector<scene::SceneVariant> variants;
  };
  std::vector<Family> families;
};

/// Reads and checks the study, every variant parsed as a scene. @throws InputError.
WorkPrecisionStudy read_work_precision_study(const std::string& path);

/// Runs the study and writes into `out`:
///   work_precision.csv  problem,p,pC,n,m,ndofs,nmult,error_energy,error_lambda,seconds,family,energy
///                       (n: edges of T_h on Γ_C, m: segments of T_{C,H}; error_energy = |E(u_h) − E_ref|,
///                       error_lambda = ‖λ_H − λ_ref‖_{L²(Γ_C)} for (9), (15), ‖s(λ_H − λ_ref)‖_{L²(Γ_C)} for (13)
///                       (driver::multiplier_error_weight); seconds: wall time meshes → u, an adaptive
///                       step's since the adaptivity began; p, pC of an adaptive step: its largest)
///   reference.csv       problem,energy,energy_coarser,accuracy_energy,accuracy_lambda,ndofs,seconds,
///                       free_boundary (fitted points "x y" separated by ";"), free_boundary_moved
///   cheapest.csv        problem,tolerance,verdict,family,p,pC,n,ndofs,error_energy,seconds: the fastest
///                       run whose error is certainly below the tolerance, error_energy + the
///                       reference's accuracy ≤ tolerance ("reached"); "not reached"; or "below
///                       reference accuracy" when the tolerance is under the reference's accuracy
/// `progress(done, total, label)` before each solve.
void run_work_precision_study(const WorkPrecisionStudy& study, const std::filesystem::path& out,
                              const std::function<void(int, int, const std::string&)>& progress = {});

}  // namespace hpcontact::studies
