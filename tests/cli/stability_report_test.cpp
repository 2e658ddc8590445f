// Every solve reports its pairing's predicted stability: the §7 scene at p = 4, p_C = 3 on T_h's
// edges warns and names a stable alternative, which then runs without a warning;
// `[solve] stability = "refuse"` exits 2 before solving and writes nothing; "ignore" is silent.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/cli_runner.hpp"

namespace {

using hpcontact::testing::run;
using hpcontact::testing::scratch;

const std::string kFigure1 = HPCONTACT_SOURCE_DIR "/studies/paper/figure1_signorini.toml";

// The §7 Signorini scene with `[solve] stability = policy`, written into `dir`.
std::string scene_with_policy(const std::filesystem::path& dir, const std::string& policy) {
  std::ifstream in(kFigure1);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text += "[solve]\nstability = \"" + policy + "\"\n";
  const auto path = dir / ("figure1_" + policy + ".toml");
  std::ofstream(path) << text;
  return path.string();
}

}  // namespace

TEST(StabilityReport, AnUnstablePairingWarnsAndNamesAStableAlternative) {
  const auto dir = scratch("stability_warn");
  const auto unstable = run("solve " + kFigure1 + " --p 4 --pc 3 --ratio 1 --out " + (dir / "unstable").string());
  ASSERT_EQ(unstable.exit_code, 0) << unstable.output;
  EXPECT_NE(unstable.output.find("warning: the pairing p = 4, p_C = 3, h/H = 1"), std::string::npos) << unstable.output;
  EXPECT_NE(unstable.output.find("predicted unstable"), std::string::npos) << unstable.output;
  EXPECT_NE(unstable.output.find("Stable alternative: [discretization] pC = 2"), std::string::npos) << unstable.output;
  std::ifstream summary_file(dir / "unstable" / "summary.json");
  const auto summary = nlohmann::json::parse(summary_file);
  const auto& stability = summary.at("stability");
  EXPECT_FALSE(stability.at("stable").get<bool>());
  EXPECT_LT(stability.at("alpha_predicted").get<double>(), stability.at("threshold").get<double>());
  EXPECT_EQ(stability.at("alternative").at("edit"), "[discretization] pC = 2");
  // The global α of the run agrees: the pairing is unstable (α ~ h).
  EXPECT_LT(summary.at("infsup").at("alpha").get<double>(), 0.1);

  const auto stable = run("solve " + kFigure1 + " --p 4 --pc 2 --ratio 1 --out " + (dir / "stable").string());
  ASSERT_EQ(stable.exit_code, 0) << stable.output;
  EXPECT_EQ(stable.output.find("warning"), std::string::npos) << stable.output;
  EXPECT_NE(stable.output.find("stability: alpha_predicted"), std::string::npos) << stable.output;
  std::ifstream stable_summary(dir / "stable" / "summary.json");
  EXPECT_GT(nlohmann::json::parse(stable_summary).at("infsup").at("alpha").get<double>(), 0.5);
}

TEST(StabilityReport, RefuseExitsTwoBeforeSolvingAndIgnoreIsSilent) {
  const auto dir = scratch("stability_policy");
  const auto refused =
      run("solve " + scene_with_policy(dir, "refuse") + " --p 4 --pc 3 --ratio 1 --out " + (dir / "refused").string());
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_NE(refused.output.find("refused: solve.stability = \"refuse\""), std::string::npos) << refused.output;
  EXPECT_NE(refused.output.find("[discretization] pC = 2"), std::string::npos) << refused.output;
  EXPECT_EQ(refused.output.find("solving"), std::string::npos) << refused.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "refused"));
  const auto allowed =
      run("solve " + scene_with_policy(dir, "refuse") + " --p 4 --pc 2 --ratio 1 --out " + (dir / "allowed").string());
  EXPECT_EQ(allowed.exit_code, 0) << allowed.output;

  const auto ignored =
      run("solve " + scene_with_policy(dir, "ignore") + " --p 4 --pc 3 --ratio 1 --out " + (dir / "ignored").string());
  EXPECT_EQ(ignored.exit_code, 0) << ignored.output;
  EXPECT_EQ(ignored.output.find("warning"), std::string::npos) << ignored.output;
  EXPECT_NE(ignored.output.find("UNSTABLE"), std::string::npos) << ignored.output;  // still in the report
}

// λ ≤ 0 holds at the constraint points only: summary.json says how far λ leaves it between them.
// The unstable pairing's wrong-sign lobe is twice the stable one's, both beside the free
// boundary; five constraint points per segment instead of p_C + 1 = 3 shrink it tenfold.
TEST(StabilityReport, SaysHowFarTheMultiplierLeavesItsBoundsBetweenTheConstraintPoints) {
  const auto dir = scratch("stability_bounds");
  const auto violation = [&](const std::string& options, const std::string& name) {
    const auto solved = run("solve " + kFigure1 + " --effects signorini --p 4 --ratio 1 " + options + " --out " +
                            (dir / name).string());
    EXPECT_EQ(solved.exit_code, 0) << solved.output;
    EXPECT_NE(solved.output.find("multiplier outside its bounds by"), std::string::npos) << solved.output;
    std::ifstream file(dir / name / "summary.json");
    const auto bounds = nlohmann::json::parse(file).at("signorini").at("multiplier_bounds");
    EXPECT_LT(bounds.at("distance_to_free_boundary").get<double>(), 0.1) << name;  // beside the free boundary
    return bounds.at("violation").get<double>();
  };
  const double unstable = violation("--pc 3", "unstable"), stable = violation("--pc 2", "stable");
  const double five_points = violation("--pc 2 --constraint-points 5", "five_points");
  EXPECT_GT(unstable, 1.5 * stable);
  EXPECT_LT(five_points, 0.2 * stable);
  EXPECT_GT(five_points, 0.0);
}
