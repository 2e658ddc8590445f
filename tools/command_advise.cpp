// `hpcontact advise SCENE --out DIR`: which multiplier discretization to use with a scene's mesh
// and p. Every candidate (p_C, h/H, family) is ranked by its predicted α and the multipliers it
// resolves; the recommended one and its runner-up get the global α; DIR/advice.csv holds them
// all, and the scene edits that apply the recommendation are printed.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <optional>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "driver/run_outputs.hpp"
#include "io/atomic_file.hpp"
#include "io/output_folder.hpp"
#include "scene/scene_reader.hpp"
#include "scene_set_option.hpp"
#include "space/multiplier_family.hpp"
#include "studies/pairing_advice.hpp"

namespace hpcontact::tools {
namespace {

struct AdviseOptions {
  std::string scene, out = "results/advice";
  std::optional<int> p;
  std::optional<double> alpha_min;
  std::vector<std::string> set;
};

void print_candidate(const char* label, const studies::AdviceCandidate& c) {
  fmt::print("{}: p_C = {}, h/H = {}, family {}: predicted alpha {:.4g}, alpha {}, {} multipliers\n", label, c.pc,
             c.ratio.text, space::to_string(c.family), c.alpha_predicted,
             c.alpha ? fmt::format("{:.6g}", *c.alpha) : std::string("-"), c.nmult);
}

int run_advise(const AdviseOptions& o) {
  // 1. Check the input: the scene, the options, the output folder (written only at the end).
  const std::string where = "hpcontact advise";
  if (mpi_rank_and_size().second > 1)
    throw InputError(where + ": runs on one rank (its candidates are small eigenproblems); start it without mpirun");
  std::vector<scene::SceneOverride> overrides;
  if (o.p) overrides.push_back({"discretization.p", static_cast<long long>(*o.p), where + " --p"});
  for (auto& set : set_overrides(o.set, where)) overrides.push_back(std::move(set));
  const auto scene = scene::read_scene(o.scene, overrides);
  io::check_output_folder(o.out);

  // 2. Predict every candidate, the global α of the best two.
  const auto advice = studies::advise_pairing(
      scene,
      {.alpha_min = o.alpha_min, .progress = [](const std::string& line) { fmt::print(stderr, "# {}\n", line); }});

  // 3. Report and write advice.csv.
  fmt::print("{} candidates for p = {}; admitted: predicted alpha >= {:.3g}\n", advice.candidates.size(), advice.p,
             advice.alpha_min);
  if (!advice.recommended) {
    fmt::print("no candidate reaches alpha_min: lower --alpha-min, or refine T_h (a larger p or smaller h)\n");
  } else {
    const auto& best = advice.candidates[*advice.recommended];
    print_candidate("recommended", best);
    if (advice.runner_up) print_candidate("runner-up", advice.candidates[*advice.runner_up]);
    fmt::print("scene edits: {}\n", best.edits.empty() ? std::string("none (the scene's own pairing)")
                                                       : fmt::format("{}", fmt::join(best.edits, "; ")));
  }
  const auto table = studies::advice_table(advice);
  driver::write_run_outputs(o.out, {}, {},
                            [&](const std::filesystem::path& folder) { table.write(folder / "advice.csv"); });
  fmt::print("# wrote {}/advice.csv in {:.2f} s\n", o.out, advice.seconds);
  return 0;
}

}  // namespace

void add_advise_command(CLI::App& app, CommandAction& action) {
  auto* command = app.add_subcommand(
      "advise",
      "Which p_C, T_{C,H} and multiplier family to use with a scene's mesh and p: candidates ranked by the "
      "predicted inf-sup constant and the multipliers they resolve");
  auto o = std::make_shared<AdviseOptions>();
  command->add_option("scene", o->scene, "Scene file (TOML); keys in docs/scene_keys.md")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--out", o->out, "Output folder (advice.csv)")->capture_default_str();
  command->add_option("--p", o->p, "Override the scene's p");
  add_set_option(*command, o->set);
  command->add_option("--alpha-min", o->alpha_min,
                      "Admit candidates whose predicted alpha is at least this, in (0, 1]; default 0.1 times the best "
                      "candidate's and at least 0.2 (the predictor's threshold)");
  command->callback([&action, o] { action = [o] { return run_advise(*o); }; });
}

}  // namespace hpcontact::tools
