// Stability sweeps: α(h, H, p, p_C) over lists of p, p_C, n, h/H, norms and problems on the
// paper's §7 geometry, with a fitted rate α ≈ C h^r and a verdict per configuration.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "infsup/infsup_analysis.hpp"
#include "io/csv_writer.hpp"

namespace hpcontact::studies {

/// A sweep file (TOML), e.g. studies/stability/study.toml; every key is documented in
/// studies/README.md:
///   [sweep] p, pC, n (integers, lists or "a..b"), pc_rule ("below_p" | "all"), ratio (list of
///           numbers or fractions "2/3"), norm (["interp", "extension"]), problem
///           (["signorini", "friction"]), fit_levels, eigensolver ("slepc" | "dense")
///   [reference] interp_subdivisions, interp_degree, extension_refinements, extension_extra_degree
struct StabilitySweep {
  std::string file;
  std::vector<int> degrees, multiplier_degrees, levels;
  bool pc_below_p = true;
  std::vector<std::string> ratios;  ///< as written ("1/2"), parsed where used
  std::vector<std::string> norms, problems;
  int fit_levels = 3;
  std::string eigensolver = "slepc";
  norms::InterpolationReference interpolation_reference;
  norms::ExtensionReference extension_reference;
};

/// @throws InputError naming file, key, value and the allowed range (also when n · ratio is not
/// a whole number for some n and ratio).
StabilitySweep read_stability_sweep(const std::string& path);

/// A ratio h/H given as a number or fraction ("1", "0.5", "2/3"). @throws InputError.
double parse_ratio(const std::string& text, const std::string& where);

/// Columns of alpha.csv (one row per point).
std::vector<std::string> alpha_columns();

/// Runs every point not already in `alpha_csv` (resumable), rewriting the file atomically after
/// each group of points sharing (n, p). `progress(done, total, label)` is called before each point.
/// Under mpirun the groups are distributed round-robin over the ranks of MPI_COMM_WORLD and rank 0
/// writes the rows in the serial order (the file is then written once, at the end).
void run_stability_sweep(const StabilitySweep& sweep, const std::filesystem::path& alpha_csv,
                         const std::function<void(int, int, const std::string&)>& progress = {});

/// Fits α ≈ C h^r over the `fit_levels` finest levels of each configuration in alpha.csv and
/// returns verdicts.csv: problem,norm,p,pC,ratio,rate,C,alpha_finest,verdict with verdict
///   singular  α_finest ≤ 1e-6 (α² ≤ 1e-12 λ_max, as λ_max ≤ 1 here: zero to working precision)
///   decaying  r ≥ 0.3 (α → 0 like h^r)
///   stable    otherwise (α bounded below)
io::CsvTable fit_verdicts(const std::filesystem::path& alpha_csv, int fit_levels);

}  // namespace hpcontact::studies
