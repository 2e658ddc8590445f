// `hpcontact solve SCENE.toml --out DIR`: runs the effects the scene's [run] table asks for
// (contact problems, inf-sup constant, convergence) and writes the outputs it asks for; the
// options override the scene so that one file serves a family of pairings (the paper's panels).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "driver/scene_run.hpp"
#include "io/atomic_file.hpp"
#include "io/output_folder.hpp"
#include "linalg/distribution.hpp"
#include "scene/scene_mesh.hpp"
#include "scene/scene_reader.hpp"
#include "scene_set_option.hpp"

namespace hpcontact::tools {
namespace {

struct SolveOptions {
  std::string scene, out = "results/solve";
  std::vector<std::string> effects;  ///< empty: the scene's
  std::optional<int> p, pc, n, constraint_points;
  std::string ratio;
  std::vector<std::string> set;    ///< --set KEY=VALUE
  std::string distributed_solver;  ///< empty: substructuring under mpirun, serial on one rank
};

// " (zones 0.4500 + 0.5000)" when Γ_C has several zones: each zone's contact set length.
std::string zone_lengths(const driver::ContactResult& result) {
  if (result.zones.size() < 2) return "";
  std::vector<std::string> lengths;
  for (const auto& zone : result.zones) lengths.push_back(fmt::format("{:.4f}", zone.contact_set_length));
  return fmt::format(" (zones {})", fmt::join(lengths, " + "));
}

// ", zones alone 0.4800, 0.4800": α of each zone's multipliers when Γ_C has several zones.
std::string zone_alphas(const driver::InfSupSummary& infsup) {
  if (infsup.zone_alpha.empty()) return "";
  std::vector<std::string> alphas;
  for (const double alpha : infsup.zone_alpha)
    alphas.push_back(std::isfinite(alpha) ? fmt::format("{:.10g}", alpha) : "-");
  return fmt::format(", zones alone {}", fmt::join(alphas, ", "));
}

// The pairing's predicted stability, and the alternative when it is predicted unstable.
void print_stability(const driver::StabilityReport& s) {
  if (!s.failure.empty()) {
    fmt::print("stability: not predicted ({})\n", s.failure);
    return;
  }
  // (not "alpha = ": that names the inf-sup constant's line)
  fmt::print("stability: alpha_predicted {:.4g} ({} {}), Pi {:.3g}", s.alpha_predicted,
             s.stable ? "stable: >=" : "UNSTABLE: <", s.threshold, s.pi);
  if (s.alternative) fmt::print("; stable alternative: {}", s.alternative->edit);
  fmt::print("\n");
}

// One line per contact problem: its energy, solver and contact set (and the total force of an
// elastic body).
void print_contact(const driver::ContactResult& result) {
  fmt::print("{}: energy = {:.17g}", result.problem, result.energy);
  if (result.total_force) fmt::print(", total force P = {:.10g}", *result.total_force);
  if (result.solver.trace_operator == "saddle_point")
    fmt::print(", {} {} steps ({} CG iterations on K), KKT residual {:.2e}", result.solver.iterations,
               result.solver.method, result.solver.products, result.solver.kkt_residual);
  else if (result.solver.trace_operator == "products")
    fmt::print(", {} with {} products by S, KKT residual {:.2e}", result.solver.method, result.solver.products,
               result.solver.kkt_residual);
  else
    fmt::print(", {} {} steps, KKT residual {:.2e}", result.solver.iterations, result.solver.method,
               result.solver.kkt_residual);
  if (result.contact_area)
    fmt::print(", contact area {:.4f}", *result.contact_area);
  else
    fmt::print(", contact set length {:.4f}{}", result.contact_set_length, zone_lengths(result));
  if (!result.fixed_point_changes.empty()) fmt::print(", {} fixed-point iterations", result.fixed_point_changes.size());
  // (between the constraint points the bounds are not imposed: how far the multiplier leaves them)
  if (result.bounds && result.bounds->violation > 1e-8)
    fmt::print(", multiplier outside its bounds by {:.2g} of its max at ({:.4g}, {:.4g}){}", result.bounds->violation,
               result.bounds->at.x(), result.bounds->at.y(),
               result.bounds->to_free_boundary
                   ? fmt::format(", {:.3g} from the free boundary", *result.bounds->to_free_boundary)
                   : std::string());
  fmt::print("\n");
  if (result.pair)
    fmt::print("  pair '{}': slave '{}', master '{}'\n", result.pair->name, result.pair->slave, result.pair->master);
  if (result.exact) {
    fmt::print("  against [exact]:");
    if (result.exact->displacement)
      fmt::print(" displacement error {:.3e} (relative, max norm)", *result.exact->displacement);
    if (result.exact->pressure) fmt::print(" pressure error {:.3e} (relative, max norm)", *result.exact->pressure);
    fmt::print("\n");
  }
}

int run_solve(const SolveOptions& o) {
  const std::string where = "hpcontact solve";
  // 1. The scene with the options as overrides, each checked like the scene's own key.
  std::vector<scene::SceneOverride> overrides;
  if (o.p) overrides.push_back({"discretization.p", static_cast<long long>(*o.p), where + " --p"});
  if (o.pc) overrides.push_back({"discretization.pC", static_cast<long long>(*o.pc), where + " --pc"});
  if (!o.ratio.empty()) overrides.push_back({"contact_mesh.ratio", o.ratio, where + " --ratio"});
  if (o.constraint_points)
    overrides.push_back(
        {"solve.constraint_points", static_cast<long long>(*o.constraint_points), where + " --constraint-points"});
  if (o.n) {
    overrides.push_back({"domain.n_x", static_cast<long long>(*o.n), where + " --n"});
    overrides.push_back({"domain.n_y", static_cast<long long>(*o.n), where + " --n"});
  }
  if (!o.effects.empty()) overrides.push_back({"run.effects", o.effects, where + " --effects"});
  for (auto& set : set_overrides(o.set, where)) overrides.push_back(std::move(set));
  const auto scene = scene::read_scene(o.scene, overrides);
  if (scene.effects.empty()) {
    std::vector<std::string> names;
    for (auto effect : scene::all_effects()) names.push_back(scene::to_string(effect));
    throw_bad_input(
        o.scene, "run.effects", "(missing)",
        fmt::format("a [run] table with effects = [...] (any of {}), or the option --effects", fmt::join(names, ", ")));
  }
  const auto distribution =
      linalg::distribution_named(MPI_COMM_WORLD, o.distributed_solver, where, "--distributed-solver");
  io::check_output_folder(o.out);

  // 2. Run; progress goes to stderr so that stdout stays the result. Under mpirun every rank runs
  // the scene, K and A_G are factorized over the ranks, and rank 0 reports and writes.
  const int rank = mpi_rank_and_size().first, ranks = mpi_rank_and_size().second;  // (a lambda captures rank)
  driver::SceneRunOptions options{o.out, [rank](const std::string& line) {
                                    if (rank == 0) fmt::print(stderr, "# {}\n", line);
                                  }};
  options.distribution = distribution;
  const driver::RunResult result = driver::run_scene(scene, options);
  if (rank != 0) return 0;

  // 3. One line per effect, after the pairing's predicted stability.
  if (result.stability) print_stability(*result.stability);
  for (const auto& contact : result.contacts) print_contact(contact);
  if (result.infsup)
    fmt::print("infsup: alpha = {:.10g} ({}){}\n", result.infsup->record.alpha,
               result.infsup->lambda_unique ? "lambda unique" : "singular: lambda not unique",
               zone_alphas(*result.infsup));
  fmt::print("# p {} pC {} m {} ndofs {}: wrote {} in {:.2f} s on {} rank{}\n", result.p, result.pc, result.m,
             result.n_dofs, o.out, result.seconds_total, ranks, ranks > 1 ? "s" : "");
  return 0;
}

}  // namespace

void add_solve_command(CLI::App& app, CommandAction& action) {
  auto* command = app.add_subcommand(
      "solve", "Run a scene's effects (contact problems (9), (13), (15), infsup, convergence) and write its outputs");
  auto o = std::make_shared<SolveOptions>();
  command->add_option("scene", o->scene, "Scene file (TOML); keys in docs/scene_keys.md")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--out", o->out, "Output folder")->capture_default_str();
  command
      ->add_option("--effects", o->effects,
                   "Override the scene's [run] effects: signorini, friction, friction_s, infsup, convergence")
      ->delimiter(',');
  command->add_option("--p", o->p, "Override the scene's p");
  command->add_option("--pc", o->pc, "Override the scene's p_C");
  command->add_option("--n", o->n,
                      "Override the rectangle's cells: n x n (domain.n_x, domain.n_y; a box keeps its domain.n_z)");
  command->add_option("--ratio", o->ratio, "Override the scene's contact mesh: h/H, e.g. 1/2");
  command->add_option("--constraint-points", o->constraint_points,
                      "Override the scene's constraint points per segment (Remark 3; >= p_C + 1)");
  add_set_option(*command, o->set);
  command->add_option("--distributed-solver", o->distributed_solver, kDistributedSolverHelp);
  command->callback([&action, o] { action = [o] { return run_solve(*o); }; });
}

}  // namespace hpcontact::tools
