// The benchmark's kinds "three_d_scene" and "three_d_scene_saddle_point" through `hpcontact
// benchmark`: a 3-D elastic scene file's contact solve (by products; on the saddle point) against
// one linear solve of its K (CHOLMOD; GAMG), on the unknowns `hpcontact solve` reports for the same
// scene; and the refusals of benchmark.scene.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "support/cli_runner.hpp"

namespace hpcontact::testing {
namespace {

const std::string kElastic = std::string(HPCONTACT_SOURCE_DIR) + "/studies/three_d/extruded_frictionless.toml";

TEST(SolidBenchmark, SceneKindTimesTheContactSolveAgainstOneLinearSolve) {
  const auto dir = scratch("solid_benchmark");
  std::ofstream(dir / "bench.toml") << "[benchmark]\np = 2\npC = 1\nscene = \"" << kElastic
                                    << "\"\nkinds = [\"three_d_scene\"]\n";
  const auto result = run("benchmark " + (dir / "bench.toml").string() + " --out " + (dir / "out").string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto csv = read_csv(dir / "out" / "benchmark.csv");
  ASSERT_EQ(csv.rows.size(), 2u) << result.output;
  EXPECT_EQ(csv.rows[0][0], "linear_A_3d_scene");
  EXPECT_EQ(csv.rows[1][0], "three_d_scene_products");

  const auto solved =
      run("solve " + kElastic + " --set 'solve.trace_operator=\"products\"' --out " + (dir / "solve").string());
  ASSERT_EQ(solved.exit_code, 0) << solved.output;
  const auto summary = nlohmann::json::parse(std::ifstream(dir / "solve" / "summary.json"));
  for (const auto& row : csv.rows) {
    const std::string line = line_of(row);
    // columns kind,p,pC,n,m,ndofs,nmult,n_trace,seconds_assembly,seconds_baseline,seconds,ratio,peak_rss_mb,
    // products
    EXPECT_EQ(std::stoll(row[5]), summary.at("ndofs").get<long long>()) << line;
    EXPECT_EQ(std::stoll(row[6]), summary.at("nmult").get<long long>()) << line;
    const double baseline = std::stod(row[9]), seconds = std::stod(row[10]), ratio = std::stod(row[11]);
    EXPECT_GT(baseline, 0.0) << line;
    EXPECT_NEAR(ratio, seconds / baseline, 1e-12 * ratio) << line;
    EXPECT_GT(std::stod(row[12]), 0.0) << line;
  }
  EXPECT_GT(std::stoll(csv.rows[1][7]), 0) << "n_trace of the contact row";
  // (the products the solve reports for the same scene on the same path)
  EXPECT_EQ(std::stoll(csv.rows[1][13]), summary.at("frictionless").at("solver").at("products").get<long long>());
  EXPECT_GT(std::stoll(csv.rows[1][13]), 0);
  EXPECT_EQ(std::stoll(csv.rows[0][13]), 0);
}

// Kind three_d_scene_saddle_point: one GAMG-CG solve with the contact's load (the same u, which
// the benchmark checks), then the contact on the saddle point, whose CG iterations are those that
// `hpcontact solve` reports on the same path.
TEST(SolidBenchmark, SaddlePointKindTimesTheContactAgainstOneGamgSolve) {
  const auto dir = scratch("solid_benchmark_saddle_point");
  std::ofstream(dir / "bench.toml") << "[benchmark]\np = 2\npC = 1\nscene = \"" << kElastic
                                    << "\"\nkinds = [\"three_d_scene_saddle_point\"]\n";
  const auto result = run("benchmark " + (dir / "bench.toml").string() + " --out " + (dir / "out").string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto csv = read_csv(dir / "out" / "benchmark.csv");
  ASSERT_EQ(csv.rows.size(), 2u) << result.output;
  EXPECT_EQ(csv.rows[0][0], "linear_A_3d_scene_gamg");
  EXPECT_EQ(csv.rows[1][0], "three_d_scene_saddle_point");
  const auto solved =
      run("solve " + kElastic + " --set 'solve.trace_operator=\"saddle_point\"' --distributed-solver gamg --out " +
          (dir / "solve").string());
  ASSERT_EQ(solved.exit_code, 0) << solved.output;
  const auto summary = nlohmann::json::parse(std::ifstream(dir / "solve" / "summary.json"));
  for (const auto& row : csv.rows) {
    const std::string line = line_of(row);
    EXPECT_EQ(std::stoll(row[5]), summary.at("ndofs").get<long long>()) << line;
    const double baseline = std::stod(row[9]), seconds = std::stod(row[10]), ratio = std::stod(row[11]);
    EXPECT_GT(baseline, 0.0) << line;
    EXPECT_NEAR(ratio, seconds / baseline, 1e-12 * ratio) << line;
    EXPECT_GT(std::stod(row[12]), 0.0) << line;
    EXPECT_GT(std::stoll(row[13]), 0) << line;  // CG iterations
  }
  EXPECT_EQ(std::stoll(csv.rows[1][13]), summary.at("frictionless").at("solver").at("cg_iterations").get<long long>());
}

TEST(SolidBenchmark, SceneKeyRefusedWithoutItsKindOrItsFileOrA3dElasticScene) {
  const auto dir = scratch("solid_benchmark_bad");
  const std::string planar = std::string(HPCONTACT_SOURCE_DIR) + "/studies/elasticity/hertz.toml";
  const std::vector<std::pair<std::string, std::string>> cases{
      {"missing", "kinds = [\"three_d_scene\"]\n"},
      {"absent", "scene = \"no_such_scene.toml\"\nkinds = [\"three_d_scene\"]\n"},
      {"other_kind", "scene = \"" + kElastic + "\"\nn = [4]\nkinds = [\"signorini\"]\n"},
      {"planar", "scene = \"" + planar + "\"\nkinds = [\"three_d_scene\"]\n"}};
  for (const auto& [name, keys] : cases) {
    std::ofstream(dir / (name + ".toml")) << "[benchmark]\np = 2\npC = 1\n" << keys;
    const auto bad = run("benchmark " + (dir / (name + ".toml")).string() + " --out " + (dir / name).string());
    EXPECT_EQ(bad.exit_code, 2) << name << ": " << bad.output;
    EXPECT_NE(bad.output.find("benchmark.scene"), std::string::npos) << name << ": " << bad.output;
    EXPECT_FALSE(std::filesystem::exists(dir / name)) << name;
  }
}

}  // namespace
}  // namespace hpcontact::testing
