// `hpcontact infsup`: the inf-sup constant α(h, H, p, p_C) of (11) / (22) on the paper's §7
// geometry, with Π of (20), optional CSV row and spurious-mode samples.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/expression.hpp"
#include "core/petsc_session.hpp"
#include "infsup/infsup_analysis.hpp"
#include "linalg/distribution.hpp"
#include "norms/primal_operators.hpp"
#include "io/atomic_file.hpp"
#include "io/scene.hpp"
#include "studies/stability_sweep.hpp"
#include "mesh/rectangle_mesh.hpp"

namespace hpcontact::tools {
namespace {

struct InfSupOptions {
  int p = 1, pc = 0, n = 8;
  std::string ratio = "1";
  std::string norm = "interp", problem = "signorini", eigensolver = "slepc", distributed_solver = "substructuring";
  std::string csv, mode, scene;
  bool p_given = false, pc_given = false, n_given = false, ratio_given = false, norm_given = false,
       problem_given = false, alpha_tolerance_given = false;
  double alpha_tolerance = 1e-4;
};

// The §7 geometry from --n and --ratio, or a scene file; command-line degrees, norm and problem
// override the scene's.
struct Geometry {
  mesh::QuadMesh mesh;
  mesh::BoundaryMesh boundary_mesh;
  InfSupOptions options;  ///< with the scene's values filled in
  assembly::BoundaryFunction friction_bound;
  std::vector<int> cell_degrees, segment_degrees;  ///< from a scene's rules; empty: uniform
};

Geometry build_geometry(const InfSupOptions& given) {
  const std::string where = "hpcontact infsup";
  InfSupOptions o = given;
  if (o.scene.empty()) {
    const double ratio = studies::parse_ratio(o.ratio, where);
    const double m_real = o.n * ratio;
    const int m = static_cast<int>(std::lround(m_real));
    if (m < 1 || std::abs(m_real - m) > 1e-9 * m_real)
      throw_bad_input(where, "--ratio", o.ratio,
                      fmt::format("n · ratio = {} must be a whole number of segments m", m_real));
    return {mesh::make_paper_square_mesh(o.n), mesh::BoundaryMesh::uniform(2.0, m), o,
            [](const mesh::Point& x) { return (1.0 - x.x()) * (1.0 - x.x()); }, {}, {}};
  }
  if (o.n_given || o.ratio_given)
    throw_bad_input(where, o.n_given ? "--n" : "--ratio", "(given with --scene)",
                    "the scene sets the meshes: use its [domain] and [contact_mesh]");
  const auto scene = io::read_scene(o.scene);
  if (!o.p_given) o.p = scene.p;
  if (!o.pc_given) o.pc = scene.pc;
  if (!o.norm_given) o.norm = scene.norm;
  if (!o.problem_given) o.problem = scene.problem;
  if (!o.alpha_tolerance_given) o.alpha_tolerance = scene.alpha_tolerance;
  auto mesh = io::build_scene_mesh(scene);
  const mesh::ContactBoundary contact(mesh);
  auto boundary_mesh = io::build_scene_boundary_mesh(scene, contact);
  o.n = static_cast<int>(contact.edges().size());
  o.ratio = fmt::format("{}", static_cast<double>(boundary_mesh.n_segments()) / o.n);
  assembly::BoundaryFunction s;
  if (!scene.friction_bound.empty()) {
    const Expression bound(scene.friction_bound, o.scene + ": key 'data.s'");
    s = [bound](const mesh::Point& x) { return bound(x.x(), x.y()); };
  }
  // Degree rules of the scene, unless the command line sets uniform degrees.
  std::vector<int> cell_degrees, segment_degrees;
  if (!o.p_given && !scene.p_rule.empty()) cell_degrees = io::scene_cell_degrees(scene, mesh);
  if (!o.pc_given && !scene.pc_rule.empty())
    segment_degrees = io::scene_segment_degrees(scene, contact, boundary_mesh);
  // Reported p and p_C of a distribution: the worst case, as in Π (smallest p, largest p_C).
  if (!cell_degrees.empty()) o.p = *std::min_element(cell_degrees.begin(), cell_degrees.end());
  if (!segment_degrees.empty()) o.pc = *std::max_element(segment_degrees.begin(), segment_degrees.end());
  return {std::move(mesh), std::move(boundary_mesh), o, s, cell_degrees, segment_degrees};
}

int run_infsup(const InfSupOptions& given) {
  // 1. Check the input and build T_h and T_{C,H}.
  const std::string where = given.scene.empty() ? "hpcontact infsup" : given.scene;
  const Geometry geometry = build_geometry(given);
  const InfSupOptions& o = geometry.options;
  if (o.p < 1) throw_bad_input(where, "p", std::to_string(o.p), "must be >= 1");
  if (o.pc < 0) throw_bad_input(where, "pC", std::to_string(o.pc), "must be >= 0");
  infsup::InfSupSetup setup;
  setup.norm = infsup::parse_gram_norm(o.norm, where);
  setup.problem = infsup::parse_pairing_problem(o.problem, where);
  const auto backend = infsup::parse_eigen_backend(o.eigensolver, where);
  const auto distributed_solver = linalg::parse_distributed_solver(o.distributed_solver, where, "--distributed-solver");
  for (const auto& file : {o.csv, o.mode})
    if (!file.empty())
      io::ensure_writable_directory(std::filesystem::absolute(file).parent_path());

  // 2. Discretization on T_h and T_{C,H}.
  const auto& mesh = geometry.mesh;
  const auto& boundary_mesh = geometry.boundary_mesh;
  const int m = boundary_mesh.n_segments();
  const double ratio = studies::parse_ratio(o.ratio, where);
  setup.mesh = &mesh;
  setup.cell_degrees = geometry.cell_degrees.empty() ? std::vector<int>(mesh.n_cells(), o.p)
                                                      : geometry.cell_degrees;
  setup.boundary_mesh = &boundary_mesh;
  setup.segment_degrees = geometry.segment_degrees.empty() ? std::vector<int>(m, o.pc)
                                                            : geometry.segment_degrees;
  setup.friction_bound = geometry.friction_bound;
  setup.alpha_tolerance = o.alpha_tolerance;

  // 3. Solve the eigenproblem. Under mpirun A_G is factorized over the ranks, and rank 0 reports
  // and writes.
  const auto [rank, ranks] = mpi_rank_and_size();
  const norms::PrimalOperators primal(mesh, setup.cell_degrees, nullptr,
                                      linalg::distribution_over(ranks, distributed_solver));
  setup.primal = &primal;
  const auto result = infsup::analyse_infsup(setup, backend);
  if (rank != 0) return 0;

  // 4. Report and save.
  fmt::print("alpha = {:.17g}\n", result.alpha);
  fmt::print("# alpha_error {:.2e} (reference level {}{})\n", result.alpha_error, result.reference_level,
             result.alpha_converged
                 ? ""
                 : fmt::format(", NOT below --alpha-tol {:g}: the H^-1/2 reference could not be refined far enough; "
                               "with the extension norm, breakpoints of T_C,H that are not vertices of T_h (h/H > 1) "
                               "leave it ungraded and the estimate is then too low: use --norm interp",
                               o.alpha_tolerance));
  fmt::print("# problem {} norm {} p {} pC {} n {} m {} h/H {} Pi {:.6g} ndofs {} nmult {}\n",
             o.problem, infsup::to_string(setup.norm), o.p, o.pc, o.n, m, o.ratio, result.pi,
             result.n_primal_dofs, result.n_multiplier_dofs);
  fmt::print("# lambda_min {:.6e} lambda_max {:.6e}{} solver {} residual {:.2e} seconds {:.3f}\n",
             result.lambda_min, result.lambda_max,
             result.singular ? " (singular to working precision: alpha = 0)" : "", result.method,
             result.residual, result.seconds);
  if (!o.csv.empty()) {
    io::CsvTable row({"problem", "norm", "p", "pC", "n", "m", "h", "H", "ratio", "Pi", "alpha",
                      "alpha_error", "ndofs", "nmult", "seconds"});
    row.add_row({o.problem, infsup::to_string(setup.norm), static_cast<long long>(o.p),
                 static_cast<long long>(o.pc), static_cast<long long>(o.n),
                 static_cast<long long>(m), result.h, result.H, ratio, result.pi, result.alpha, result.alpha_error,
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
  command->add_option("--scene", o->scene, "Scene file (TOML) with another geometry (keys: studies/README.md)")
      ->check(CLI::ExistingFile);
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
  command->add_option("--distributed-solver", o->distributed_solver,
                      "Under mpirun: substructuring (CHOLMOD per rank, dense interface) | mumps (MPIAIJ + MUMPS)")
      ->capture_default_str();
  command->add_option("--csv", o->csv, "Append one row to this CSV file");
  command->add_option("--mode", o->mode, "Write the spurious mode as CSV x,mu (20 samples/segment)");
  command->add_option("--alpha-tol", o->alpha_tolerance,
                      "Relative error of alpha: the H^{-1/2} reference is refined until the estimate is below it "
                      "(0 < tol <= 0.1; default: the scene's infsup.alpha_tol, else 1e-4)")
      ->capture_default_str();
  command->callback([&action, o, command] {
    o->p_given = command->count("--p") > 0;
    o->pc_given = command->count("--pc") > 0;
    o->n_given = command->count("--n") > 0;
    o->ratio_given = command->count("--ratio") > 0;
    o->norm_given = command->count("--norm") > 0;
    o->problem_given = command->count("--problem") > 0;
    o->alpha_tolerance_given = command->count("--alpha-tol") > 0;
    action = [o] { return run_infsup(*o); };
  });
}

}  // namespace hpcontact::tools
