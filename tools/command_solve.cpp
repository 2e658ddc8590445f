// `hpcontact solve SCENE.toml --out DIR`: the discrete contact problem (9), (13) or (15) of the
// scene; writes DIR/boundary.csv, DIR/solution.vtu and DIR/summary.json.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "contact/contact_output.hpp"
#include "core/error.hpp"
#include "core/expression.hpp"
#include "core/operator_log.hpp"
#include "core/timer.hpp"
#include "infsup/infsup_analysis.hpp"
#include "io/atomic_file.hpp"
#include "io/scene.hpp"
#include "io/vtu_writer.hpp"
#include "norms/primal_operators.hpp"

namespace hpcontact::tools {
namespace {

struct SolveOptions {
  std::string scene, out = "results/solve";
  bool alpha = true;
  std::optional<int> p, pc;  ///< overrides of the scene's degrees when given
  std::string ratio;    ///< override of the scene's contact mesh (h/H) when given
  std::optional<int> constraint_points;  ///< override of the scene's |𝒞| per segment
};

contact::PointFunction function_of(const std::string& text, const std::string& origin) {
  if (text.empty()) return {};
  const Expression expression(text, origin);
  return [expression](const mesh::Point& x) { return expression(x.x(), x.y()); };
}

int run_solve(const SolveOptions& o) {
  Stopwatch clock;
  // 1. Read the scene and build T_h and T_{C,H}.
  auto scene = io::read_scene(o.scene);
  // Command-line overrides, so that one scene serves a family of pairings (the paper's panels).
  if (o.p) {
    if (*o.p < 1) throw_bad_input("hpcontact solve", "--p", std::to_string(*o.p), "must be >= 1");
    scene.p = *o.p;
    scene.p_rule.clear();
  }
  if (o.pc) {
    if (*o.pc < 0) throw_bad_input("hpcontact solve", "--pc", std::to_string(*o.pc), "must be >= 0");
    scene.pc = *o.pc;
    scene.pc_rule.clear();
  }
  if (!o.ratio.empty()) {
    scene.ratio = o.ratio;
    scene.m = 0;
    scene.breakpoints.clear();
  }
  if (scene.contact_problem == "signorini" && scene.obstacle.empty())
    throw_bad_input(o.scene, "data.g", "(missing)", "the Signorini problem needs the obstacle g");
  if (scene.contact_problem != "signorini" && scene.friction_bound.empty())
    throw_bad_input(o.scene, "data.s", "(missing)", "the friction problems need the bound s");
  const auto mesh = io::build_scene_mesh(scene);
  const mesh::ContactBoundary contact(mesh);
  const auto boundary_mesh = io::build_scene_boundary_mesh(scene, contact);

  // 2. Set up the problem the scene asks for.
  contact::ContactSetup setup;
  setup.mesh = &mesh;
  setup.cell_degrees = io::scene_cell_degrees(scene, mesh);
  setup.boundary_mesh = &boundary_mesh;
  setup.segment_degrees = io::scene_segment_degrees(scene, contact, boundary_mesh);
  setup.problem = scene.contact_problem == "signorini" ? contact::ContactProblem::signorini
                  : scene.contact_problem == "friction" ? contact::ContactProblem::friction
                                                        : contact::ContactProblem::friction_s;
  setup.constraint_points = o.constraint_points ? o.constraint_points : scene.constraint_points;
  for (int pc : setup.segment_degrees) {
    try {
      contact::segment_constraint_points(setup.problem, pc, setup.constraint_points);
    } catch (const InputError& error) {
      throw_bad_input(o.constraint_points ? std::string("hpcontact solve") : o.scene,
                      o.constraint_points ? "--constraint-points" : "solve.constraint_points",
                      std::to_string(*setup.constraint_points),
                      fmt::format("at least p_C + 1 = {} (the largest p_C of the scene's segments is {})",
                                  pc + 1, *std::max_element(setup.segment_degrees.begin(), setup.segment_degrees.end())));
    }
  }
  setup.f = function_of(scene.load, o.scene + ": key 'data.f'");
  setup.obstacle = function_of(scene.obstacle, o.scene + ": key 'data.g'");
  setup.bound = function_of(scene.friction_bound, o.scene + ": key 'data.s'");
  if (setup.bound)  // s ≥ 0 is part of the data's contract: report it against the scene's key
    setup.bound = [bound = setup.bound, file = o.scene, text = scene.friction_bound](const mesh::Point& x) {
      const double value = bound(x);
      if (value < 0)
        throw_bad_input(file, "data.s", fmt::format("\"{}\" = {} at (x, y) = ({}, {})", text, value, x.x(), x.y()),
                        "the friction bound must be >= 0 on Γ_C");
      return value;
    };

  io::check_output_directory(o.out);

  // 3. Solve. The operators of S^p(T_h) are shared with α below, and every one built is logged.
  OperatorLog operators;
  const norms::PrimalOperators primal(mesh, setup.cell_degrees, &operators);
  setup.primal = &primal;
  const auto solution = contact::solve_contact(setup);
  const auto samples = contact::sample_boundary(setup, solution);

  // 4. The inf-sup constant of the pairing tells whether λ is unique.
  nlohmann::json summary;
  if (o.alpha) {
    infsup::InfSupSetup infsup_setup;
    infsup_setup.mesh = &mesh;
    infsup_setup.cell_degrees = setup.cell_degrees;
    infsup_setup.boundary_mesh = &boundary_mesh;
    infsup_setup.segment_degrees = setup.segment_degrees;
    infsup_setup.problem = setup.problem == contact::ContactProblem::friction
                               ? infsup::PairingProblem::friction
                               : infsup::PairingProblem::signorini;
    infsup_setup.friction_bound = setup.bound;
    infsup_setup.primal = &primal;
    const auto alpha = infsup::analyse_infsup(infsup_setup, infsup::EigenBackend::slepc);
    summary["alpha"] = alpha.alpha;
    summary["lambda_unique"] = !alpha.singular;
    summary["alpha_seconds"] = alpha.seconds;
  } else {
    summary["lambda_unique"] = "unknown (run without --no-alpha)";
  }

  // 5. Save: everything computed, now write the three files.
  for (const auto& record : operators.records())
    summary["operators"].push_back(
        {{"name", record.name}, {"rows", record.rows}, {"cols", record.cols}, {"seconds", record.seconds}});
  summary["scene"] = o.scene;
  summary["problem"] = scene.contact_problem;
  summary["p"] = scene.p_rule.empty() ? nlohmann::json(scene.p) : nlohmann::json(scene.p_rule);
  summary["pC"] = scene.pc_rule.empty() ? nlohmann::json(scene.pc) : nlohmann::json(scene.pc_rule);
  summary["edges_on_contact"] = contact.edges().size();
  summary["m"] = boundary_mesh.n_segments();
  summary["ndofs"] = solution.u.size();
  summary["nmult"] = solution.lambda.size();
  summary["energy"] = solution.energy;
  summary["contact_set_length"] = samples.contact_set_length;
  const auto& q = solution.constraint_points;
  summary["constraint_points_per_segment"] = {{"min", *std::min_element(q.begin(), q.end())},
                                              {"max", *std::max_element(q.begin(), q.end())},
                                              {"total", solution.constraint_s.size()}};
  summary["solver"] = {{"method", solution.qp.method},
                       {"converged", solution.qp.converged},
                       {"kkt_residual", solution.qp.kkt_residual},
                       {"iterations", solution.qp.iterations},
                       {"proximal_steps", solution.qp.proximal_steps}};
  if (!solution.qp.fallback_reason.empty()) summary["solver"]["fallback_reason"] = solution.qp.fallback_reason;
  for (const auto& step : solution.qp.log)
    summary["solver"]["log"].push_back({{"iteration", step.iteration},
                                        {"active_set_changes", step.active_set_changes},
                                        {"kkt_residual", step.kkt_residual}});
  summary["n_trace"] = solution.n_trace;
  summary["seconds"] = {{"assembly", solution.seconds.assembly},
                        {"factorization", solution.seconds.factorization},
                        {"condensation", solution.seconds.condensation},
                        {"contact_qp", solution.seconds.qp},
                        {"recovery", solution.seconds.recovery},
                        {"total", clock.seconds()}};
  const std::filesystem::path out(o.out);
  io::ensure_writable_directory(out);
  samples.table.write(out / "boundary.csv");
  io::write_vtu(out / "solution.vtu", primal.space(), solution.u);
  io::write_file_atomically(out / "summary.json", summary.dump(2) + "\n");
  fmt::print("energy = {:.17g}\n# {} p {} pC {} m {}: {} {} steps, KKT residual {:.2e}, "
             "contact set length {:.4f}{}\nwrote {}/boundary.csv, solution.vtu, summary.json\n",
             solution.energy, scene.contact_problem, scene.p_rule.empty() ? std::to_string(scene.p) : scene.p_rule,
             scene.pc_rule.empty() ? std::to_string(scene.pc) : scene.pc_rule, boundary_mesh.n_segments(),
             solution.qp.iterations, solution.qp.method, solution.qp.kkt_residual, samples.contact_set_length,
             o.alpha ? fmt::format(", alpha {:.4g}", summary["alpha"].get<double>()) : "", o.out);
  return 0;
}

}  // namespace

void add_solve_command(CLI::App& app, CommandAction& action) {
  auto* command = app.add_subcommand(
      "solve", "Contact problem (9), (13) or (15) of a scene: boundary.csv, solution.vtu, summary.json");
  auto o = std::make_shared<SolveOptions>();
  command->add_option("scene", o->scene, "Scene file (TOML); keys in studies/README.md")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--out", o->out, "Output folder")->capture_default_str();
  command->add_flag("!--no-alpha", o->alpha, "Skip the inf-sup constant (uniqueness of lambda)");
  command->add_option("--p", o->p, "Override the scene's p");
  command->add_option("--pc", o->pc, "Override the scene's p_C");
  command->add_option("--ratio", o->ratio, "Override the scene's contact mesh: h/H, e.g. 1/2");
  command->add_option("--constraint-points", o->constraint_points,
                      "Override the scene's constraint points per segment (Remark 3; >= p_C + 1)");
  command->callback([&action, o] { action = [o] { return run_solve(*o); }; });
}

}  // namespace hpcontact::tools
