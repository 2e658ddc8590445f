// `hpcontact infsup`: the inf-sup constant α(h, H, p, p_C) of (11) / (22) on the paper's §7
// geometry, with Π of (20), optional CSV row (the columns of a sweep's alpha.csv) and
// spurious-mode samples.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "driver/run_stages.hpp"
#include "driver/solid_pairing.hpp"
#include "infsup/infsup_analysis.hpp"
#include "infsup/infsup_record.hpp"
#include "io/atomic_file.hpp"
#include "io/infsup_record_csv.hpp"
#include "linalg/distribution.hpp"
#include "postprocess/mode_samples.hpp"
#include "postprocess/surface_multiplier_vtu.hpp"
#include "scene/scene_mesh.hpp"
#include "scene/scene_reader.hpp"
#include "scene_set_option.hpp"

namespace hpcontact::tools {
namespace {

struct InfSupOptions {
  std::optional<int> p, pc, n;
  std::optional<std::string> ratio, norm, problem, family;
  std::optional<double> alpha_tolerance;
  std::string eigensolver = "slepc", distributed_solver;  ///< empty: substructuring under mpirun
  std::string csv, mode, scene;
  std::vector<std::string> set;
};

// The scene (a file, or the paper's §7 scene) with the options as overrides: each is checked like
// the scene's own key, and messages name the option.
scene::Scene resolve_scene(const InfSupOptions& o) {
  const std::string where = "hpcontact infsup";
  std::vector<scene::SceneOverride> overrides;
  if (o.n) {  // (a 3-D box keeps its domain.n_z)
    overrides.push_back({"domain.n_x", static_cast<long long>(*o.n), where + " --n"});
    overrides.push_back({"domain.n_y", static_cast<long long>(*o.n), where + " --n"});
  }
  if (o.ratio) overrides.push_back({"contact_mesh.ratio", *o.ratio, where + " --ratio"});
  if (o.p) overrides.push_back({"discretization.p", static_cast<long long>(*o.p), where + " --p"});
  if (o.pc) overrides.push_back({"discretization.pC", static_cast<long long>(*o.pc), where + " --pc"});
  if (o.family) overrides.push_back({"contact_mesh.family", *o.family, where + " --family"});
  if (o.norm) overrides.push_back({"infsup.norm", *o.norm, where + " --norm"});
  if (o.problem) overrides.push_back({"infsup.problem", *o.problem, where + " --problem"});
  if (o.alpha_tolerance) overrides.push_back({"infsup.alpha_tol", *o.alpha_tolerance, where + " --alpha-tol"});
  for (auto& set : set_overrides(o.set, where)) overrides.push_back(std::move(set));
  if (o.scene.empty()) return scene::parse_scene(scene::paper_scene_text(), scene::paper_scene_name, overrides);
  return scene::read_scene(o.scene, overrides);
}

// α of a 3-D scene, A_G factorized over the ranks of `distribution` (each rank holds the box and
// gets the same α); rank 0 writes the spurious mode (--mode) as a VTU of T_{C,H}'s cells.
driver::InfSupSummary solid_infsup(const InfSupOptions& o, const scene::Scene& scene, infsup::EigenBackend backend,
                                   const linalg::Distribution& distribution) {
  if (!o.mode.empty() && std::filesystem::path(o.mode).extension() != ".vtu")
    throw InputError(
        fmt::format("hpcontact infsup --mode {}: the spurious mode of a 3-D scene is written as a VTU of "
                    "the cells of T_C,H: give a file name ending in .vtu",
                    o.mode));
  driver::check_solid_scene(scene, false);
  driver::check_solid_pairing(scene);  // (before the box is meshed)
  const auto d = driver::discretize_solid_scene(scene);
  const auto alpha = driver::solid_scene_alpha(scene, *d, backend, nullptr, 1, distribution);
  if (!o.mode.empty() && mpi_rank_and_size().first == 0)
    io::write_file_atomically(o.mode, io::vtu_text(postprocess::surface_multiplier_vtu_grid(
                                          *d->multipliers, alpha.result.mode,
                                          alpha.result.mode.size() == d->multipliers->n_dofs()
                                              ? std::vector<std::string>{"mode"}
                                              : std::vector<std::string>{"mode_normal", "mode_e1", "mode_e2"})));
  return alpha.summary;
}

int run_infsup(const InfSupOptions& o) {
  // 1. Check the input.
  const std::string where = "hpcontact infsup";
  const scene::Scene scene = resolve_scene(o);
  const auto backend = infsup::parse_eigen_backend(o.eigensolver, where);
  const auto distribution =
      linalg::distribution_named(MPI_COMM_WORLD, o.distributed_solver, where, "--distributed-solver");
  for (const auto& file : {o.csv, o.mode})
    if (!file.empty()) io::ensure_writable_directory(std::filesystem::absolute(file).parent_path());

  // 2. Build T_h (planar, under mpirun by rank 0 alone, which sends each rank its part; a 3-D box
  // on every rank) and T_{C,H}, and solve the eigenproblem. Under mpirun A_G is factorized over the
  // ranks, and rank 0 reports and writes.
  const int rank = mpi_rank_and_size().first;
  driver::InfSupSummary summary;
  if (scene.dimension() == 3) {
    summary = solid_infsup(o, scene, backend, distribution);
    if (rank != 0) return 0;
  } else {
    // The run's own stages: an elastic scene pairs the normal (and tangential) multipliers with
    // [S^p(T_h)]². Distributed, the operators hold the rank's part: the whole mesh is kept only
    // for the extension norm's references, which refine it.
    const driver::StageContext context{distribution, {}};
    const auto level = driver::discretize(scene, context);
    driver::build_operators(*level, nullptr, context, scene.norm == infsup::GramNorm::extension);
    const auto setup = level->model->infsup_setup();
    const auto result = infsup::analyse_infsup(setup, backend);
    if (rank != 0) return 0;
    summary = driver::infsup_summary(*level, setup, result);
    if (!o.mode.empty())
      postprocess::sample_mode(*level->d->contact, *level->d->multipliers, result.mode).write(o.mode);
  }

  // 3. Report and save: the α record of the run's stages, the CSV row a sweep's alpha.csv has.
  const auto& record = summary.record;
  fmt::print("alpha = {:.17g}\n", record.alpha);
  for (std::size_t z = 0; z < summary.zone_alpha.size(); ++z)
    fmt::print("# zone {} alone: alpha = {:.17g}\n", z, summary.zone_alpha[z]);
  fmt::print("# alpha_error {:.2e} (reference level {}{})\n", record.alpha_error, summary.reference_level,
             record.alpha_converged.value_or(true)
                 ? ""
                 : fmt::format(", NOT below --alpha-tol {:g}: the H^-1/2 reference ladder ended first, or (extension "
                               "norm) its references could not be graded (breakpoints of T_C,H inside edges of T_h "
                               "refined twice, singular points of the boundary too close to others, curved cells) "
                               "and the estimate is then too low: use --norm interp where it applies",
                               scene.alpha_tolerance));
  fmt::print("# problem {} norm {} p {} pC {} n {} m {} h/H {} Pi {:.6g} ndofs {} nmult {}\n",
             infsup::to_string(record.problem), infsup::to_string(record.norm), record.p, record.pc, record.n, record.m,
             scene.ratio.size() == 1 ? scene.ratio.front().text : fmt::format("{}", record.ratio), record.pi,
             record.ndofs, record.nmult);
  if (std::isnan(record.alpha_predicted))
    fmt::print("# alpha_predicted: none (the local predictor is planar)\n");
  else
    fmt::print("# alpha_predicted {:.6g} (the local predictor, docs/stability.md: stable at >= 0.2)\n",
               record.alpha_predicted);
  fmt::print("# lambda_min {:.6e} lambda_max {:.6e}{} solver {} residual {:.2e} seconds {:.3f}\n", summary.lambda_min,
             summary.lambda_max, summary.lambda_unique ? "" : " (singular to working precision: alpha = 0)",
             summary.eigensolver, summary.residual, record.seconds);
  if (!o.csv.empty()) {
    io::CsvTable row(io::alpha_columns());
    io::add_alpha_row(row, record);
    io::append_csv_rows(o.csv, row);
  }
  return 0;
}

}  // namespace

void add_infsup_command(CLI::App& app, CommandAction& action) {
  auto* command =
      app.add_subcommand("infsup", "Inf-sup constant alpha(h, H, p, pC) with SLEPc, Pi of (20), spurious mode");
  auto o = std::make_shared<InfSupOptions>();
  command->add_option("--scene", o->scene, "Scene file (TOML; keys: docs/scene_keys.md); default: the paper's §7 scene")
      ->check(CLI::ExistingFile);
  command->add_option("--p", o->p, "Polynomial degree p of S^p(T_h) (scene key discretization.p; §7 scene: 1)");
  command->add_option("--pc", o->pc, "Multiplier degree p_C (discretization.pC; §7 scene: 0)");
  command->add_option("--n", o->n,
                      "n x n cells (domain.n_x, domain.n_y; §7 scene: 8, h = 2/n; a box keeps its domain.n_z)");
  command->add_option("--ratio", o->ratio,
                      "h/H, e.g. 1/2: T_{C,H} has m = n * ratio segments (contact_mesh.ratio; §7 scene: 1)");
  command->add_option("--family", o->family,
                      "Multiplier family: discontinuous | standard | standard-modified | dual | dual-modified "
                      "(contact_mesh.family; default discontinuous)");
  command->add_option("--norm", o->norm, "H^{-1/2} realization: interp | extension (infsup.norm; default interp)");
  command->add_option("--problem", o->problem,
                      "signorini: condition (11); friction: (22) with the scene's s, (1-x)^2 on the §7 scene "
                      "(infsup.problem; default signorini)");
  command
      ->add_option("--eigensolver", o->eigensolver, "slepc (EPS, options -infsup_eps_*) | dense (LAPACK-type, Eigen)")
      ->capture_default_str();
  command->add_option("--distributed-solver", o->distributed_solver, kDistributedSolverHelp);
  command->add_option("--csv", o->csv, "Append one row to this CSV file (the columns of a sweep's alpha.csv)");
  command->add_option(
      "--mode", o->mode,
      "Write the spurious mode as CSV x,mu (20 samples/segment); a 3-D scene: as a VTU of T_C,H (FILE.vtu)");
  command->add_option("--alpha-tol", o->alpha_tolerance,
                      "Relative error of alpha: the H^{-1/2} reference is refined until the estimate is below it "
                      "(infsup.alpha_tol; default 1e-4)");
  add_set_option(*command, o->set);
  command->callback([&action, o] { action = [o] { return run_infsup(*o); }; });
}

}  // namespace hpcontact::tools
