// Convergence study of S^p(T_h) against a manufactured solution on the paper's §7 square or on a
// scene's mesh (curved or polygonal): errors in H¹ and L² for every point asked for, as rows of a
// CSV table.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "io/csv_writer.hpp"

namespace hpcontact::studies {

/// One run of the study: degree p on the square with n × n cells, or on the scene's mesh refined
/// `refinements` times with its curves or polygonal.
struct ConvergencePoint {
  int p = 1;
  int n = 0;  ///< cells per side of the square; 0 on a scene's mesh
  int refinements = 0;
  std::string geometry = "curved";  ///< a scene's mesh: "curved" or "polygonal"
  bool operator==(const ConvergencePoint&) const = default;
};

/// A study file (TOML), e.g. studies/convergence/study.toml:
///   [solution]  u, ux, uy, f   expressions in x, y with f = -Δu
///               u_D            Dirichlet data on Γ_D (default: u itself; "0" on a curved Γ_D
///                              makes the polygonal geometry's error visible)
///   [mesh]      perturb (0 ≤ a < 0.25, default 0), seed (default 1): the §7 square; or
///               scene: a scene file whose domain and boundary (Γ_D; the rest Neumann with ∇u·n)
///               are used, relative to the study file
///   [[runs]]    p (degrees) × n (cells per side, even) on the square, or
///               p × refinements (uniform, 0 … 8) × geometry ("curved", "polygonal") on a scene
struct ConvergenceStudy {
  std::string file;
  std::string u, ux, uy, f, u_d;
  double perturb = 0.0;
  std::uint32_t seed = 1;
  std::string scene_file;                ///< empty: the §7 square
  std::vector<ConvergencePoint> points;  ///< in file order, without repeats
};

/// @throws InputError naming file, key, value and the allowed range, and if the solution is
/// inconsistent (∇u or -Δu disagree with ux, uy, f).
ConvergenceStudy read_convergence_study(const std::string& path);

struct ConvergenceRow {
  ConvergencePoint point;
  int cells = 0, ndofs = 0;
  double h = 0.0, error_h1 = 0.0, error_l2 = 0.0, error_energy = 0.0, seconds = 0.0;
};

/// Runs every point; `on_row` is called after each (for progress output).
std::vector<ConvergenceRow> run_convergence_study(const ConvergenceStudy& study,
                                                  const std::function<void(const ConvergenceRow&)>& on_row = {});

/// Columns p, n, refinements, cells, ndofs, h, error_h1, error_l2, seconds (assembly + solve),
/// geometry ("square", "curved" or "polygonal").
io::CsvTable convergence_table(const std::vector<ConvergenceRow>& rows);

}  // namespace hpcontact::studies
