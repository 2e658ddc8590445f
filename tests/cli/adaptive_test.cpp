// hp-adaptivity through `hpcontact solve`: studies/adaptive/signorini.toml reaches the reference
// energy of (9) to 1e-9 from a uniform 4 × 4 start, adapt.csv holds its steps (unknowns growing,
// estimate and error falling, effectivity bounded); studies/adaptive/hertz.toml finds the elastic
// Hertz half-width of a hand-graded solve to 1e-5 without grading points; scenes adaptivity does
// not serve are refused by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "support/cli_runner.hpp"

namespace hpcontact::testing {
namespace {

const std::string kScene = std::string(HPCONTACT_SOURCE_DIR) + "/studies/adaptive/signorini.toml";
constexpr double kReferenceEnergy = -0.80373809515;

// `hpcontact solve` of the adaptive scene with `settings` (--set options); its output folder.
std::filesystem::path solve_adaptive(const std::string& name, const std::string& settings) {
  const auto out = scratch("adaptive_" + name) / "out";
  const auto solve = run("solve " + kScene + " " + settings + " --out " + out.string());
  EXPECT_EQ(solve.exit_code, 0) << solve.output;
  return out;
}

}  // namespace

TEST(Adaptive, SignoriniReachesTheReferenceEnergyFromAUniformStart) {
  if (HPCONTACT_SANITIZED) GTEST_SKIP() << "tens of solves up to p = 14: Release builds only";
  const auto out = solve_adaptive("signorini", "");
  const auto table = read_csv(out / "adapt.csv");
  const std::vector<std::string> leading{"step", "unknowns", "multipliers", "estimate", "energy", "alpha", "seconds"};
  ASSERT_GE(table.header.size(), leading.size());
  EXPECT_TRUE(std::equal(leading.begin(), leading.end(), table.header.begin())) << line_of(table.header);
  const auto columns = table.numeric_columns();
  const auto& energy = columns.at("energy");
  const auto& estimate = columns.at("estimate");
  const auto& unknowns = columns.at("unknowns");
  ASSERT_GE(energy.size(), 3u);
  EXPECT_EQ(columns.at("step").front(), 0.0);
  EXPECT_LT(std::abs(energy.back() - kReferenceEnergy), 1e-9) << energy.back();
  EXPECT_LE(estimate.back(), 1e-9);
  EXPECT_GT(estimate.front(), 1e3 * estimate.back());
  for (std::size_t k = 1; k < unknowns.size(); ++k) EXPECT_GE(unknowns[k], unknowns[k - 1]) << k;
  // Step 0 is the scene's own discretization: a plain solve of the same 4 × 4 mesh, p = 2, p_C = 0
  // on the trace of T_h has its unknowns and energy.
  const auto plain_out = out.parent_path() / "plain";
  const auto plain = run("solve " + std::string(HPCONTACT_SOURCE_DIR) +
                         "/studies/paper/figure1_signorini.toml --set domain.n_x=4 --set domain.n_y=4 --set "
                         "discretization.p=2 --set discretization.pC=0 --set contact_mesh.ratio=1 --effects signorini "
                         "--out " +
                         plain_out.string());
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  std::ifstream plain_summary(plain_out / "summary.json");
  const auto plain_json = nlohmann::json::parse(plain_summary);
  EXPECT_EQ(plain_json.at("ndofs").get<double>(), unknowns.front());
  EXPECT_NEAR(plain_json.at("signorini").at("energy").get<double>(), energy.front(), 1e-12);
  // The estimate bounds the error on every step whose error is above the reference's own accuracy
  // (1e-11): effectivity √(estimate / |E − E_ref|) ≥ 1. The discrete energy is no bound on E (the
  // constraint holds at the points only), so |E − E_ref| dips where E crosses E_ref and single
  // effectivities spike there; their median stays bounded.
  const auto& effectivity = columns.at("effectivity");
  const auto& error = columns.at("error_energy");
  std::vector<double> measured;
  for (std::size_t k = 0; k < effectivity.size(); ++k)
    if (error[k] > 1e-11) {
      EXPECT_GE(effectivity[k], 1.0) << "step " << k;
      measured.push_back(effectivity[k]);
    }
  ASSERT_GE(measured.size(), 10u);
  std::nth_element(measured.begin(), measured.begin() + measured.size() / 2, measured.end());
  EXPECT_LE(measured[measured.size() / 2], 10.0);
  // The summary and the effects ran on the last discretization.
  std::ifstream summary(out / "summary.json");
  const std::string text((std::istreambuf_iterator<char>(summary)), {});
  EXPECT_NE(text.find("\"stopped\": \"target\""), std::string::npos) << text;
  EXPECT_TRUE(std::filesystem::exists(out / "boundary_signorini.csv"));
}

namespace {
// The least-squares slope of y against x and their correlation coefficient.
std::pair<double, double> line_fit(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double mx = 0.0, my = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) mx += x[k] / n, my += y[k] / n;
  double sxy = 0.0, sxx = 0.0, syy = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k)
    sxy += (x[k] - mx) * (y[k] - my), sxx += (x[k] - mx) * (x[k] - mx), syy += (y[k] - my) * (y[k] - my);
  return {sxy / sxx, sxy / std::sqrt(sxx * syy)};
}
}  // namespace

TEST(Adaptive, ElasticHertzFindsTheHalfWidthOfAHandGradedSolveWithoutGradingPoints) {
  if (HPCONTACT_SANITIZED) GTEST_SKIP() << "thirty elastic solves up to p = 11: Release builds only";
  const auto out = scratch("adaptive_hertz") / "out";
  const std::string source(HPCONTACT_SOURCE_DIR);
  const auto solve = run("solve " + source + "/studies/adaptive/hertz.toml --out " + out.string());
  ASSERT_EQ(solve.exit_code, 0) << solve.output;
  const auto columns = read_csv(out / "adapt.csv").numeric_columns();
  const double a = columns.at("moment_half_width").back();
  // The independent path: studies/elasticity/hertz.toml graded by hand (12 layers) towards the
  // located ±a, p = 6, p_C = 4 (44 256 unknowns, more than the adaptive run's last step).
  std::ifstream hand_scene(source + "/studies/elasticity/hertz.toml");
  const std::string text((std::istreambuf_iterator<char>(hand_scene)), {});
  const auto graded_scene = out.parent_path() / "graded.toml";
  std::ofstream(graded_scene) << std::regex_replace(
      text, std::regex("grading_points = .*"),
      "grading_points = [[" + std::to_string(-a) + ", 0], [" + std::to_string(a) + ", 0]]");
  const auto graded_out = out.parent_path() / "graded";
  const auto graded = run("solve " + graded_scene.string() +
                          " --set domain.grading_layers=12 --set discretization.p=6 --set discretization.pC=4 --out " +
                          graded_out.string());
  ASSERT_EQ(graded.exit_code, 0) << graded.output;
  std::ifstream summary(graded_out / "summary.json");
  const auto root_json = nlohmann::json::parse(summary);
  const auto& json = root_json.at("frictionless");
  EXPECT_NEAR(a, json.at("moment_half_width").get<double>(), 1e-5);
  EXPECT_NEAR(columns.at("energy").back(), json.at("energy").get<double>(), 2e-8);
  EXPECT_LT(columns.at("unknowns").back(), root_json.at("ndofs").get<double>());
  // The energy error falls exponentially in unknowns^(1/3): log |E − E_ref| on a line of negative
  // slope (down to the reference's own accuracy, 1e-11).
  std::vector<double> root, log_error;
  const auto& error = columns.at("error_energy");
  for (std::size_t k = 0; k < error.size(); ++k)
    if (error[k] > 1e-11) root.push_back(std::cbrt(columns.at("unknowns")[k])), log_error.push_back(std::log(error[k]));
  ASSERT_GE(root.size(), 10u);
  const auto [slope, correlation] = line_fit(root, log_error);
  EXPECT_LT(slope, -0.3);
  EXPECT_LT(correlation, -0.9);
  EXPECT_LT(error.back(), 1e-9);
}

TEST(Adaptive, ScenesItDoesNotServeAreRefusedByName) {
  expect_refused(run("solve " + kScene + " --set 'contact_mesh.ratio=\"1/2\"'"), "contact_mesh");
  expect_refused(run("solve " + kScene + " --set 'discretization.pC=2'"), "discretization.pC");
  expect_refused(run("solve " + kScene + " --set 'run.effects=[\"signorini\", \"friction_s\"]' --set 'data.s=\"1\"'"),
                 "exactly one contact problem");
  expect_refused(run("solve " + kScene + " --set 'solve.fit_free_boundary=true'"), "solve.fit_free_boundary");
  expect_refused(run("solve " + kScene + " --set 'adapt.fraction=0'"), "adapt.fraction");
  expect_refused(run("solve " + kScene + " --set 'adapt.target=0'"), "adapt.target");
  // A key of [adapt] without the target would silently do nothing.
  const auto paper = std::string(HPCONTACT_SOURCE_DIR) + "/studies/paper/figure1_signorini.toml";
  expect_refused(run("solve " + paper + " --set 'adapt.max_steps=3'"), "adapt.max_steps");
}

}  // namespace hpcontact::testing
