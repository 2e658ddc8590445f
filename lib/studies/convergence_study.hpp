// Convergence study of S^p(T_h) against a manufactured solution on the paper's §7 square:
// errors in H¹ and L² for every (p, n) asked for, as rows of a CSV table.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "io/csv_writer.hpp"

namespace hpcontact::studies {

/// A study file (TOML), e.g. studies/convergence/study.toml:
///   [solution]  u, ux, uy, f   expressions in x, y with f = -Δu and u = 0 on Γ_D
///   [mesh]      perturb (0 ≤ a < 0.25, default 0), seed (default 1)
///   [[runs]]    p (degrees), n (cells per side, even): every pair p × n is computed
struct ConvergenceStudy {
  std::string file;
  std::string u, ux, uy, f;
  double perturb = 0.0;
  std::uint32_t seed = 1;
  std::vector<std::pair<int, int>> points;  ///< (p, n), in file order, without repeats
};

/// @throws InputError naming file, key, value and the allowed range, and if the solution is
/// inconsistent (∇u or -Δu disagree with ux, uy, f; u ≠ 0 on Γ_D).
ConvergenceStudy read_convergence_study(const std::string& path);

struct ConvergenceRow {
  int p = 0, n = 0, ndofs = 0;
  double h = 0.0, error_h1 = 0.0, error_l2 = 0.0, error_energy = 0.0, seconds = 0.0;
};

/// Runs every point; `on_row` is called after each (for progress output).
std::vector<ConvergenceRow> run_convergence_study(const ConvergenceStudy& study,
                                                  const std::function<void(const ConvergenceRow&)>& on_row = {});

/// Columns p, n, ndofs, h, error_h1, error_l2, seconds (seconds = assembly + solve).
io::CsvTable convergence_table(const std::vector<ConvergenceRow>& rows);

}  // namespace hpcontact::studies
