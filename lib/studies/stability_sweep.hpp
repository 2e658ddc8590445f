// Stability sweeps: α(h, H, p, p_C) over the levels of a base scene and lists of p, p_C, h/H,
// norms and problems, with a fitted rate α ≈ C h^r and a verdict per configuration.
#pragma once

#include <mpi.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "infsup/infsup_analysis.hpp"
#include "infsup/infsup_record.hpp"
#include "linalg/distribution.hpp"
#include "scene/ratio.hpp"
#include "scene/scene_variants.hpp"
#include "studies/sweep_verdicts.hpp"

namespace hpcontact::studies {

/// A sweep file (TOML), e.g. studies/stability/study.toml; every key is documented in
/// studies/README.md:
///   [sweep] scene (the base scene, relative to the sweep file), set (scene keys replaced),
///           levels (scene keys varied jointly, one level per value: the mesh sequence of the fit),
///           p, pC (integers, lists or "a..b"; absent: the scene's degree or rule),
///           pc_rule ("below_p" | "all"), ratio (h/H: numbers or fractions "2/3"; absent: the
///           scene's contact mesh), norm, problem (absent: the scene's [infsup] norm, problem),
///           family (multiplier families; absent: the scene's contact_mesh.family),
///           fit_levels, eigensolver ("slepc" | "dense"), alpha_tol (relative error of every α)
struct StabilitySweep {
  std::string file;
  std::vector<scene::SceneVariant> levels;  ///< the base scene at each level, coarsest first
  /// What each level's meshes are, found when the file is read (resuming and scheduling need
  /// them before anything is built): per level, and per ratio (one entry, the scene's contact
  /// mesh, when `ratios` is empty).
  struct LevelFacts {
    int cells = 0, contact_edges = 0;
    double contact_h_min = 0.0;           ///< shortest edge of T_h on Γ_C
    int scene_p = 0;                      ///< smallest p_T of the scene's own degree (rule)
    std::vector<int> segments, scene_pc;  ///< per ratio: m, largest p_C of the scene's own degree
  };
  std::vector<LevelFacts> level_facts;
  std::vector<int> degrees, multiplier_degrees;  ///< empty: the scene's p (p_C) or degree rule
  bool pc_below_p = true;
  std::vector<scene::Ratio> ratios;  ///< empty: the scene's contact mesh
  std::vector<infsup::GramNorm> norms;
  std::vector<infsup::PairingProblem> problems;
  std::vector<space::MultiplierFamily> families{space::MultiplierFamily{}};  ///< the scene's own when not listed
  int fit_levels = 3;
  std::string eigensolver = "slepc";
  double alpha_tolerance = 1e-4;
};

/// Reads the file and checks every level's scene, contact mesh (n_C · ratio whole for every
/// ratio) and data (s for the friction problem) before anything is computed. Collective on
/// `ranks` (every rank reads the file; the first alone builds the levels' meshes).
/// @throws InputError naming file, key, value and the allowed range, and the level (on every rank).
StabilitySweep read_stability_sweep(const std::string& path, MPI_Comm ranks = MPI_COMM_WORLD);

/// Slice `index` of `count` of a sweep (`hpcontact sweep --shard index/count`): the groups the
/// scheduler gives to process `index` of `count` on the whole sweep, the same in every run, so
/// that the jobs of a batch scheduler's array compute disjoint parts without talking to each other.
struct SweepShard {
  int index = 0, count = 1;
};
/// "i/N" with 0 ≤ i < N. @throws InputError naming `origin`, the option and the allowed form.
SweepShard parse_sweep_shard(const std::string& text, const std::string& origin);

/// How the ranks of mpirun share a sweep's units (`hpcontact sweep --ranks-per-unit k
/// --distributed-solver S`): groups of k consecutive ranks take units together, and factorize each
/// point's K + M and the extension norm's references over the group by S; with k = 1 each rank
/// takes units alone.
struct SweepRanks {
  int per_unit = 1;
  linalg::DistributedSolver solver = linalg::DistributedSolver::substructuring;
};
/// @throws InputError naming --ranks-per-unit unless it divides `ranks`.
void check_sweep_ranks(const SweepRanks& sweep_ranks, int ranks);

/// What a run leaves in alpha.csv: its rows in the order of the points (every rank's on rank 0,
/// the others hold their own and those stored before), and whether they are every point of the
/// sweep (on rank 0).
struct SweepOutcome {
  std::vector<infsup::InfSupRecord> rows;
  bool complete = false;
};

/// progress(done, total, work_done, label) before each point (see run_stability_sweep).
using SweepProgress = std::function<void(int done, int total, double work_done, const std::string& label)>;

/// Runs every point (of `shard`) not already in `alpha_csv` (resumable), rewriting the file
/// atomically after each group of points sharing (level, p). `progress(done, total, work_done,
/// label)` is called before each point (`done`: the points stored before and those all ranks
/// computed so far, this one included; `total`: those stored and those to do in this run, a
/// slice's own; `work_done`: the fraction of this run's estimated work (the plan's cost of each
/// point) the points computed so far make up). Under
/// mpirun the groups of `sweep_ranks` (single ranks by default) take units of groups (whole levels
/// or single groups, longest first: sweep_work_units) as they become idle, and rank 0 writes the
/// rows in the serial order (the file is then written once, at the end). Who computes what:
/// SweepSchedule; what a point computes: SweepEvaluation.
SweepOutcome run_stability_sweep(const StabilitySweep& sweep, const std::filesystem::path& alpha_csv,
                                 const SweepProgress& progress = {}, SweepShard shard = {},
                                 SweepRanks sweep_ranks = {});

/// The alpha.csv of every folder in `shards` (and the per-rank shards beside each) into
/// `alpha_csv`, in the serial order: equal to a serial run's file but for the seconds column. A
/// point in two folders keeps the first folder's row (a warning names points whose numbers differ).
/// Returns the rows written, in that order.
/// @throws InputError if a point of the sweep is in none of them (naming how many and one).
std::vector<infsup::InfSupRecord> merge_sweep_shards(const StabilitySweep& sweep,
                                                     const std::vector<std::filesystem::path>& shards,
                                                     const std::filesystem::path& alpha_csv);

}  // namespace hpcontact::studies
