// Performance benchmark: every cost as a ratio against a baseline timed in the same run, the
// time of one linear solve of the same matrix with the same solver (static condensation of the
// cell interiors, CHOLMOD on the skeleton, one solve) — K for the contact problems, A_G = K + M
// for α — on the §7 data; optionally the same solves on the assembled matrices for comparison.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "io/csv_writer.hpp"

namespace hpcontact::studies {

/// A benchmark file (TOML), e.g. studies/performance/benchmark.toml:
///   [benchmark] p, pC (degrees), ratio (h/H), n (list of levels, cells per side),
///               kinds (any of "signorini", "friction", "friction_s", "alpha", "assembled":
///               CHOLMOD on the assembled K and A_G, as ratios to the condensed solves, and
///               "elastic": an elastic body on the same mesh, its frictionless and Coulomb contact
///               solves against one linear solve with the elasticity matrix A, "two_body": two
///               elastic blocks on non-matching meshes (two_body_benchmark.hpp), "three_d": an
///               elastic cube on n³ hexahedra on both paths of S (solid_benchmark.hpp), "three_d_scene":
///               the elastic 3-D scene file `scene` at p and pC, its contact by products against one
///               linear solve, once, "startup": a tiny whole-process solve against `--version`,
///               once, before the levels)
///               scene (kind "three_d_scene": a 3-D elastic scene file, relative to this file)
struct PerformanceBenchmark {
  std::string file;
  std::string executable;  ///< the hpcontact executable, for kind "startup"
  int p = 4, pc = 3;
  std::string ratio = "1/2";
  std::vector<int> levels;
  std::vector<std::string> kinds;
  std::string scene;  ///< kind "three_d_scene", resolved against the benchmark file's folder
};

/// @throws InputError naming file, key, value and the allowed range.
PerformanceBenchmark read_performance_benchmark(const std::string& path);

struct BenchmarkRow {
  std::string kind;  ///< "linear_K", "linear_AG", a contact problem, "alpha", "linear_K_assembled",
                     ///< "linear_AG_assembled", "linear_A", "elastic_frictionless", "elastic_coulomb",
                     ///< "linear_A_two_body", "two_body_frictionless", "linear_A_3d",
                     ///< "three_d_frictionless_dense", "three_d_frictionless_products", "linear_AG_3d",
                     ///< "alpha_3d_products", "alpha_3d_dense", "linear_A_3d_scene",
                     ///< "three_d_scene_products", "linear_A_3d_scene_gamg",
                     ///< "three_d_scene_saddle_point", "startup"
  int p = 0, pc = 0, n = 0, m = 0, ndofs = 0, nmult = 0, n_trace = 0;
  double seconds_assembly = 0.0;  ///< not part of either side of the ratio
  double seconds_baseline = 0.0;  ///< one linear solve of the same matrix
  double seconds = 0.0;           ///< the measured operation (assembly excluded)
  double ratio = 0.0;             ///< seconds / seconds_baseline
  double peak_rss_mb = 0.0;       ///< peak resident memory during this row (with what earlier rows left resident)
  /// products by S (the 3-D contact rows on the products path); CG iterations (the iterative rows)
  long products = 0;
};

/// Peak resident memory in MB since the last reset_peak_rss (or the process's start).
double peak_rss_mb();
void reset_peak_rss();

/// Runs every level (in the given order) and kind; `on_row` after each row (progress).
std::vector<BenchmarkRow> run_performance_benchmark(const PerformanceBenchmark& benchmark,
                                                    const std::function<void(const BenchmarkRow&)>& on_row = {});

/// Columns kind,p,pC,n,m,ndofs,nmult,n_trace,seconds_assembly,seconds_baseline,seconds,ratio,peak_rss_mb,
/// products.
io::CsvTable benchmark_table(const std::vector<BenchmarkRow>& rows);

/// Least-squares exponent b of seconds ≈ a · ndofs^b per kind: columns kind,exponent,rows.
io::CsvTable scaling_exponents(const std::vector<BenchmarkRow>& rows);

}  // namespace hpcontact::studies
