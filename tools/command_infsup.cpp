// `hpcontact infsup`: the inf-sup constant α(h, H, p, p_C) of (11) / (22) on the paper's §7
// geometry, with Π of (20), optional CSV row and spurious-mode samples.
#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "commands.hpp"
#include "core/error.hpp"
#include "infsup/infsup_analysis.hpp"
#include "io/atomic_file.hpp"
#include "mesh/rectangle_mesh.hpp"

namespace hpcontact::tools {
namespace {

struct InfSupOptions {
  int p = 1, pc = 0, n = 8;
  std::string ratio = "1";
  std::string norm = "interp", problem = "signorini", eigensolver = "slepc";
  std::string csv, mode;
  int reference_subdivisions = 2, reference_degree = 0;
  int reference_refinements = 1, reference_extra_degree = 2;
};

// "0.5", "2" or a fraction "2/3" (so that 1/3 needs no rounded decimal).
double parse_ratio(const std::string& text, const std::string& where) {
  double value = 0.0;
  try {
    std::size_t used = 0;
    const auto slash = text.find('/');
    if (slash == std::string::npos) {
      value = std::stod(text, &used);
      if (used != text.size()) value = NAN;
    } else {
      const double numerator = std::stod(text.substr(0, slash), &used);
      if (used != slash) value = NAN;
      else value = numerator / std::stod(text.substr(slash + 1), &used);
      if (used != text.size() - slash - 1) value = NAN;
    }
  } catch (const std::exception&) {
    value = NAN;
  }
  if (!(value > 0.0) || !std::isfinite(value))
    throw_bad_input(where, "--ratio", text, "must be a positive number or fraction such as 2/3");
  return value;
}

int run_infsup(const InfSupOptions& o) {
  // 1. Check the input.
  const std::string where = "hpcontact infsup";
  if (o.p < 1) throw_bad_input(where, "--p", std::to_string(o.p), "must be >= 1");
  if (o.pc < 0) throw_bad_input(where, "--pc", std::to_string(o.pc), "must be >= 0");
  const double ratio = parse_ratio(o.ratio, where);
  const double m_real = o.n * ratio;
  const int m = static_cast<int>(std::lround(m_real));
  if (m < 1 || std::abs(m_real - m) > 1e-9 * m_real)
    throw_bad_input(where, "--ratio", o.ratio,
                    fmt::format("n · ratio = {} must be a whole number of segments m", m_real));
  infsup::InfSupSetup setup;
  setup.norm = infsup::parse_gram_norm(o.norm, where);
  setup.problem = infsup::parse_pairing_problem(o.problem, where);
  const auto backend = infsup::parse_eigen_backend(o.eigensolver, where);
  for (const auto& file : {o.csv, o.mode})
    if (!file.empty())
      io::ensure_writable_directory(std::filesystem::absolute(file).parent_path());

  // 2. Meshes: T_h on the §7 square, T_{C,H} with m = n · ratio uniform segments.
  const mesh::QuadMesh mesh = mesh::make_paper_square_mesh(o.n);
  const mesh::BoundaryMesh boundary_mesh = mesh::BoundaryMesh::uniform(2.0, m);
  setup.mesh = &mesh;
  setup.cell_degrees.assign(mesh.n_cells(), o.p);
  setup.boundary_mesh = &boundary_mesh;
  setup.segment_degrees.assign(m, o.pc);
  setup.friction_bound = [](const mesh::Point& x) { return (1.0 - x.x()) * (1.0 - x.x()); };
  setup.interpolation_reference = {o.reference_subdivisions, o.reference_degree};
  setup.extension_reference = {o.reference_refinements, o.reference_extra_degree};

  // 3. Solve the eigenproblem.
  const auto result = infsup::analyse_infsup(setup, backend);

  // 4. Report and save.
  fmt::print("alpha = {:.17g}\n", result.alpha);
  fmt::print("# problem {} norm {} p {} pC {} n {} m {} h/H {} Pi {:.6g} ndofs {} nmult {}\n",
             o.problem, infsup::to_string(setup.norm), o.p, o.pc, o.n, m, o.ratio, result.pi,
             result.n_primal_dofs, result.n_multiplier_dofs);
  fmt::print("# lambda_min {:.6e} lambda_max {:.6e}{} solver {} residual {:.2e} seconds {:.3f}\n",
             result.lambda_min, result.lambda_max,
             result.singular ? " (singular to working precision: alpha = 0)" : "", result.method,
             result.residual, result.seconds);
  if (!o.csv.empty()) {
    io::CsvTable row({"problem", "norm", "p", "pC", "n", "m", "h", "H", "ratio", "Pi", "alpha",
                      "ndofs", "nmult", "seconds"});
    row.add_row({o.problem, infsup::to_string(setup.norm), static_cast<long long>(o.p),
                 static_cast<long long>(o.pc), static_cast<long long>(o.n),
                 static_cast<long long>(m), result.h, result.H, ratio, result.pi, result.alpha,
                 static_cast<long long>(result.n_primal_dofs),
                 static_cast<long long>(result.n_multiplier_dofs), result.seconds});
    io::append_csv_rows(o.csv, row);
  }
  if (!o.mode.empty()) {
    const space::MultiplierSpace multipliers(boundary_mesh, setup.segment_degrees);
    infsup::sample_mode(mesh, multipliers, result.mode).write(o.mode);
  }
  return 0;
}

}  // namespace

void add_infsup_command(CLI::App& app, CommandAction& action) {
  auto* command = app.add_subcommand(
      "infsup", "Inf-sup constant alpha(h, H, p, pC) with SLEPc, Pi of (20), spurious mode");
  auto o = std::make_shared<InfSupOptions>();
  command->add_option("--p", o->p, "Polynomial degree p of S^p(T_h) (>= 1)")->capture_default_str();
  command->add_option("--pc", o->pc, "Multiplier degree p_C (>= 0)")->capture_default_str();
  command->add_option("--n", o->n, "n x n cells on the §7 square, h = 2/n (even)")->capture_default_str();
  command->add_option("--ratio", o->ratio, "h/H: the boundary mesh has m = n * ratio segments")
      ->capture_default_str();
  command->add_option("--norm", o->norm, "H^{-1/2} realization: interp | extension")
      ->capture_default_str();
  command->add_option("--problem", o->problem,
                      "signorini: condition (11); friction: (22) with s = (1-x)^2")
      ->capture_default_str();
  command->add_option("--eigensolver", o->eigensolver,
                      "slepc (EPS, options -infsup_eps_*) | dense (LAPACK-type, Eigen)")
      ->capture_default_str();
  command->add_option("--csv", o->csv, "Append one row to this CSV file");
  command->add_option("--mode", o->mode, "Write the spurious mode as CSV x,mu (20 samples/segment)");
  command->add_option("--reference-subdivisions", o->reference_subdivisions,
                      "interp norm: subdivisions of each common interval for W")
      ->capture_default_str();
  command->add_option("--reference-degree", o->reference_degree,
                      "interp norm: degree of W (0: max pC + 6)")
      ->capture_default_str();
  command->add_option("--reference-refinements", o->reference_refinements,
                      "extension norm: uniform refinements of T_h")
      ->capture_default_str();
  command->add_option("--reference-extra-degree", o->reference_extra_degree,
                      "extension norm: degree added to p")
      ->capture_default_str();
  command->callback([&action, o] { action = [o] { return run_infsup(*o); }; });
}

}  // namespace hpcontact::tools
