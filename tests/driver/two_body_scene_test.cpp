// Two-body scenes through `hpcontact solve`: the contact patch test of studies/two_bodies/patch.toml
// against its [exact] solution, the two-body Hertz problem of studies/two_bodies/hertz.toml against
// Hertz's solution from its boundary CSV, and the messages of malformed two-body scenes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "scene/scene_reader.hpp"
#include "support/cli_runner.hpp"
#include "support/csv_file.hpp"
#include "support/input_error_message.hpp"
#include "support/scratch.hpp"

using namespace hpcontact;

namespace {

const std::string kStudies = std::string(HPCONTACT_SOURCE_DIR) + "/studies/two_bodies/";

nlohmann::json summary_of(const std::filesystem::path& folder) {
  std::ifstream in(folder / "summary.json");
  return nlohmann::json::parse(in);
}

}  // namespace

TEST(TwoBodyScene, PatchTestPassesToRoundOffThroughTheCommandLine) {
  for (const std::string degrees : {"--p 1 --pc 0", "--p 2 --pc 1", "--p 4 --pc 2"}) {
    const auto out = hpcontact::testing::scratch("patch");
    const auto run = hpcontact::testing::run("solve " + kStudies + "patch.toml " + degrees + " --out " + out.string());
    ASSERT_EQ(run.exit_code, 0) << run.output;
    EXPECT_NE(run.output.find("against [exact]"), std::string::npos) << run.output;
    const auto summary = summary_of(out)["frictionless"];
    EXPECT_LT(summary["exact_errors"]["displacement"].get<double>(), 1e-10) << degrees;
    EXPECT_LT(summary["exact_errors"]["pressure"].get<double>(), 1e-10) << degrees;
    EXPECT_EQ(summary["pair"]["name"], "interface");
    for (const char* file : {"boundary_interface_frictionless.csv", "solution_interface_frictionless_top.vtu",
                             "solution_interface_frictionless_bottom.vtu", "contact_interface_frictionless.vtu"})
      EXPECT_TRUE(std::filesystem::exists(out / file)) << file;
    const auto csv = hpcontact::testing::read_csv(out / "boundary_interface_frictionless.csv");
    EXPECT_EQ(csv.header_line(), "x,y,s_arc,gap,pressure,traction_t,u_n_slave,u_n_master,zone");
  }
}

TEST(TwoBodyScene, HertzPressureMatchesTheTwoBodyHertzSolution) {
  const auto out = hpcontact::testing::scratch("hertz");
  const auto run = hpcontact::testing::run("solve " + kStudies + "hertz.toml --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const double force = summary_of(out)["frictionless"]["total_force"].get<double>();
  // 1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂ with E₁ = 1, E₂ = 2, ν = 0.3; R = 1.
  const double modulus = 1.0 / (0.91 / 1.0 + 0.91 / 2.0);
  const double a = std::sqrt(4.0 * force / (std::numbers::pi * modulus));
  const auto hertz = [&](double x) {
    return 2.0 * force / (std::numbers::pi * a * a) * std::sqrt(std::max(a * a - x * x, 0.0));
  };
  const auto columns = hpcontact::testing::read_csv(out / "boundary_punch_frictionless.csv").numeric_columns();
  std::vector<std::pair<double, double>> samples;
  for (std::size_t k = 0; k < columns.at("x").size(); ++k)
    samples.emplace_back(columns.at("x")[k], columns.at("pressure")[k]);
  std::sort(samples.begin(), samples.end());
  // The half-width: half the extent of {p > 1e-2 max p}; the profile error in L² by the trapezoid
  // rule on the samples (20 per interval of the graded mesh).
  double peak = 0.0, lowest = 1e300, highest = -1e300, error = 0.0, norm = 0.0;
  for (const auto& [x, p] : samples) peak = std::max(peak, p);
  for (const auto& [x, p] : samples)
    if (p > 1e-2 * peak) {
      lowest = std::min(lowest, x);
      highest = std::max(highest, x);
    }
  for (std::size_t k = 0; k + 1 < samples.size(); ++k) {
    const auto [x0, p0] = samples[k];
    const auto [x1, p1] = samples[k + 1];
    error += 0.5 * (x1 - x0) * (std::pow(p0 - hertz(x0), 2) + std::pow(p1 - hertz(x1), 2));
    norm += 0.5 * (x1 - x0) * (std::pow(hertz(x0), 2) + std::pow(hertz(x1), 2));
  }
  EXPECT_NEAR(a, 0.1, 0.002) << "the scene's indentation gives a ≈ 0.1";
  // The issue asks 1 % and 1.5 %; the scene gives 0.02 % and 0.5 % (docs/two_bodies.md).
  EXPECT_NEAR(0.5 * (highest - lowest) / a, 1.0, 0.002) << "half-width " << 0.5 * (highest - lowest) << ", a " << a;
  EXPECT_LT(std::sqrt(error / norm), 0.008);
}

namespace {

// Two blocks and a pair between them, for the reader's tests.
const std::string kBodies = R"toml(
[[body]]
name = "top"
[body.domain]
x_min = -1
x_max = 1
y_min = 0
y_max = 1
n_x = 2
n_y = 2
[body.boundary]
contact = "abs(y) < 1e-9"
dirichlet = "abs(y - 1) < 1e-9"
[[body]]
name = "bottom"
[body.domain]
x_min = -1
x_max = 1
y_min = -1
y_max = 0
n_x = 3
n_y = 2
[body.boundary]
contact = "abs(y) < 1e-9"
dirichlet = "abs(y + 1) < 1e-9"
[contact_mesh]
m = 2
[discretization]
p = 2
pC = 1
[run]
effects = ["frictionless"]
)toml";
const std::string kPair = "[[pair]]\nslave = \"top\"\nmaster = \"bottom\"\n";

std::string message(const std::string& text) {
  return hpcontact::testing::message_of([&] { scene::parse_scene(text, "pair.toml"); });
}

}  // namespace

TEST(TwoBodyScene, MalformedScenesAreRefusedWithTheKeyAndTheBody) {
  const std::string& body = kBodies;
  const std::string& pair = kPair;
  // A well-formed scene: the slave's, carrying the master's.
  const auto scene = scene::parse_scene(body + pair, "pair.toml");
  ASSERT_TRUE(scene.pair);
  EXPECT_EQ(scene.body, "top");
  EXPECT_EQ(scene.pair->master.body, "bottom");
  EXPECT_EQ(scene.pair->name, "contact");
  EXPECT_EQ(scene.pair->master.n_x, 3);

  EXPECT_NE(message(body + "[[pair]]\nslave = \"top\"\nmaster = \"botom\"\n")
                .find("the name of a [[body]]: 'top', "
                      "'bottom'"),
            std::string::npos);
  EXPECT_NE(message(body + "[[pair]]\nslave = \"top\"\nmaster = \"top\"\n").find("another body than the slave"),
            std::string::npos);
  EXPECT_NE(message(body + pair + "[domain]\nn_x = 2\n").find("belongs in each [[body]]"), std::string::npos);
  EXPECT_NE(message(body + pair + pair).find("exactly one contact pair"), std::string::npos);
  // The multiplier's data given for the master would do nothing.
  std::string master_bound = body + pair;
  master_bound.replace(master_bound.find("[contact_mesh]"), 0, "[body.data]\ns = \"0.1\"\n");
  const auto bound_message = message(master_bound);
  EXPECT_NE(bound_message.find("([[body]] 'bottom')"), std::string::npos) << bound_message;
  EXPECT_NE(bound_message.find("give it for the slave ('top')"), std::string::npos) << bound_message;
  std::string with_gap = body + pair;
  with_gap.replace(with_gap.find("[[body]]\nname = \"bottom\""), 0, "[body.data]\ng = \"0.1\"\n");
  const auto gap_message = message(with_gap);
  EXPECT_NE(gap_message.find("([[body]] 'top')"), std::string::npos) << gap_message;
  EXPECT_NE(gap_message.find("data.g"), std::string::npos) << gap_message;
  std::string with_convergence = body + pair;
  const std::string effects = "effects = [\"frictionless\"]";
  with_convergence.replace(with_convergence.find(effects), effects.size(),
                           "effects = [\"frictionless\", \"convergence\"]");
  EXPECT_NE(message(with_convergence).find("not available yet"), std::string::npos) << message(with_convergence);
  std::string only_infsup = body + pair;
  only_infsup.replace(only_infsup.find(effects), effects.size(), "effects = [\"infsup\"]");
  EXPECT_NE(message(only_infsup).find("the bodies of a pair are elastic"), std::string::npos) << message(only_infsup);
}

TEST(TwoBodyScene, OverridesReachBothBodiesOrOne) {
  const std::string& body = kBodies;
  const std::string& pair = kPair;
  std::string twice = body + pair;
  twice.replace(twice.find("[[body]]\nname = \"bottom\""), 0, "[body.discretization]\np = 3\n");
  EXPECT_NE(message(twice).find("one place"), std::string::npos) << message(twice);
  // An override of a shared key replaces the bodies' own.
  const auto raised = scene::parse_scene(twice, "pair.toml", {{"discretization.p", 4LL, "test --p"}});
  EXPECT_EQ(raised.p.value, 4);
  EXPECT_EQ(raised.pair->master.p.value, 4);
  // One body's key: body.<name>.section.key.
  const auto finer = scene::parse_scene(body + pair, "pair.toml", {{"body.bottom.domain.n_x", 7LL, "test --set"}});
  EXPECT_EQ(finer.pair->master.n_x, 7);
  EXPECT_EQ(finer.n_x, 2);
  const auto no_such_body = hpcontact::testing::message_of([&] {
    scene::parse_scene(body + pair, "pair.toml", {{"body.middle.domain.n_x", 7LL, "test --set"}});
  });
  EXPECT_NE(no_such_body.find("the scene has: 'top', 'bottom'"), std::string::npos) << no_such_body;
}

TEST(TwoBodyScene, SweepOfAPairAgreesWithTheSolvesAlpha) {
  // Two levels of blocks.toml (body keys varied per body), p ≤ 2: the sweep's α (the Gram ladder
  // of the sweep's envelope space, restricted) against α of the same configuration from
  // hpcontact solve --effects infsup (its own Gram matrix).
  const auto out = hpcontact::testing::scratch("pair_sweep");
  const auto study = out / "study.toml";
  {
    std::ofstream file(study);
    file << "[sweep]\nscene = \"" << kStudies << "blocks.toml\"\n"
         << "levels = { \"body.upper.domain.n_x\" = [4, 8], \"body.upper.domain.n_y\" = [4, 8], "
            "\"body.lower.domain.n_x\" = [6, 12], \"body.lower.domain.n_y\" = [6, 12] }\n"
         << "p = \"1..2\"\npC = \"0..1\"\nratio = [1]\nnorm = [\"interp\"]\nproblem = [\"signorini\"]\n"
         << "fit_levels = 2\n";
  }
  const auto run = hpcontact::testing::run("sweep " + study.string() + " --out " + (out / "sweep").string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto rows = hpcontact::testing::read_csv(out / "sweep" / "alpha.csv").records();
  ASSERT_EQ(rows.size(), 6u) << "levels × (p, p_C < p): 2 × 3";
  // p = 1, not the scene's own p = 2: the sweep must set it in both bodies.
  const auto solve = hpcontact::testing::run("solve " + kStudies + "blocks.toml --effects infsup --p 1 --pc 0 --out " +
                                             (out / "solve").string());
  ASSERT_EQ(solve.exit_code, 0) << solve.output;
  const double alpha = summary_of(out / "solve")["infsup"]["alpha"].get<double>();
  bool found = false;
  for (const auto& row : rows)
    if (row.at("p") == "1" && row.at("pC") == "0" && row.at("level") == "1") {
      found = true;
      EXPECT_NEAR(std::stod(row.at("alpha")), alpha, 1e-8 * alpha);
    }
  EXPECT_TRUE(found);
}
