// α of 3-D scenes through the command line: `hpcontact infsup --scene` of the extruded §7 scene
// against the planar scene's α, the effect infsup of a 3-D solve, a 3-D stability sweep (rows,
// verdicts, resumed without recomputing), and what α of a 3-D scene refuses by name.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "support/cli_runner.hpp"
#include "support/csv_file.hpp"
#include "support/vtu_arrays.hpp"

namespace hpcontact::testing {
namespace {

const std::string kExtruded = std::string(HPCONTACT_SOURCE_DIR) + "/studies/three_d/extruded_signorini.toml";
const std::string kPlanar = std::string(HPCONTACT_SOURCE_DIR) + "/studies/paper/figure1_signorini.toml";
const std::string kCube = std::string(HPCONTACT_SOURCE_DIR) + "/studies/three_d/cube.toml";
const std::string kHertz = std::string(HPCONTACT_SOURCE_DIR) + "/studies/three_d/hertz_grid.toml";

double alpha_printed(const Run& run) {
  std::smatch match;
  const std::regex line("alpha = ([-+0-9.eE]+)");
  if (!std::regex_search(run.output, match, line)) ADD_FAILURE() << run.output;
  return match.empty() ? NAN : std::stod(match[1]);
}

// p_C = 0 on a T_{C,H} with one cell across the width: the multipliers are constant in y, and α is
// the planar α of the same n, p and h/H (tests/infsup/solid_infsup_test.cpp says why).
TEST(SolidStability, ExtrudedSceneHasThePlanarAlpha) {
  const auto solid = run("infsup --scene " + kExtruded + " --set discretization.pC=0 --set infsup.alpha_tol=1e-6");
  ASSERT_EQ(solid.exit_code, 0) << solid.output;
  const auto planar = run("infsup --scene " + kPlanar + " --n 8 --p 2 --pc 0 --ratio 1/2 --alpha-tol 1e-6");
  ASSERT_EQ(planar.exit_code, 0) << planar.output;
  const double expected = alpha_printed(planar);
  EXPECT_NEAR(alpha_printed(solid), expected, 1e-5 * expected) << solid.output << planar.output;
  EXPECT_NE(solid.output.find("n 16 m 4"), std::string::npos) << solid.output;  // trace faces, cells of T_{C,H}
  EXPECT_NE(solid.output.find("alpha_predicted: none"), std::string::npos) << solid.output;
}

// The elastic pairing (normal multiplier, vector H¹ norm) of the plane-strain square extruded in y
// (studies/three_d/extruded_frictionless.toml) with p_C = 0 and one cell of T_{C,H} across the width:
// the planar elastic α of the square in the same norm.
TEST(SolidStability, ExtrudedElasticSceneHasThePlanarAlpha) {
  const std::string source = HPCONTACT_SOURCE_DIR;
  const auto solid = run("infsup --scene " + source + "/studies/three_d/extruded_frictionless.toml" +
                         " --pc 0 --ratio 1/2 --alpha-tol 1e-6");
  ASSERT_EQ(solid.exit_code, 0) << solid.output;
  const auto planar = run("infsup --scene " + source +
                          "/studies/elasticity/square.toml --set 'boundary.contact=\"abs(y + 1) < 1e-9\"' --set "
                          "'infsup.primal_norm=\"h1\"' --pc 0 --ratio 1/2 --alpha-tol 1e-6");
  ASSERT_EQ(planar.exit_code, 0) << planar.output;
  const double expected = alpha_printed(planar);
  EXPECT_NEAR(alpha_printed(solid), expected, 1e-5 * expected) << solid.output << planar.output;
}

TEST(SolidStability, SolveReportsAlphaOfItsPairing) {
  const auto dir = scratch("solid_solve_infsup");
  const auto solved = run("solve " + kCube + " --set 'run.effects=[\"signorini\", \"infsup\"]' --out " + dir.string());
  ASSERT_EQ(solved.exit_code, 0) << solved.output;
  const auto analysed = run("infsup --scene " + kCube);
  ASSERT_EQ(analysed.exit_code, 0) << analysed.output;
  std::ifstream file(dir / "summary.json");
  const auto summary = nlohmann::json::parse(file);
  EXPECT_NEAR(summary.at("infsup").at("alpha").get<double>(), alpha_printed(analysed), 1e-12);
  EXPECT_TRUE(summary.contains("signorini"));
}

// Two levels, p ≤ 2, p_C < p, h/H ∈ {1, 1/2}: 3 pairings × 2 ratios × 2 levels. The unstable
// pairings at h/H = 1 (p_C = p − 1) lose α with h; the others keep it.
TEST(SolidStability, SweepWritesTheMapAndResumes) {
  const auto dir = scratch("solid_sweep");
  std::ofstream(dir / "cube.toml") << std::ifstream(kCube).rdbuf();
  std::ofstream(dir / "sweep.toml") << "[sweep]\nscene = \"cube.toml\"\n"
                                       "levels = { \"domain.n_x\" = [2, 4], \"domain.n_y\" = [2, 4], "
                                       "\"domain.n_z\" = [2, 4] }\n"
                                       "p = \"1..2\"\npC = \"0..1\"\nratio = [1, \"1/2\"]\nfit_levels = 2\n"
                                       "alpha_tol = 1e-3\n";
  const auto swept = run("sweep " + (dir / "sweep.toml").string() + " --out " + (dir / "out").string());
  ASSERT_EQ(swept.exit_code, 0) << swept.output;
  const CsvFile alpha = read_csv(dir / "out" / "alpha.csv");
  ASSERT_EQ(alpha.records().size(), 12u);
  const CsvFile verdicts = read_csv(dir / "out" / "verdicts.csv");
  ASSERT_EQ(verdicts.records().size(), 6u);
  for (const auto& row : verdicts.records()) {
    const bool unstable = row.at("ratio") == "1" && std::stoi(row.at("pC")) == std::stoi(row.at("p")) - 1;
    EXPECT_EQ(row.at("verdict"), unstable ? "decaying" : "stable") << row.at("p") << " " << row.at("pC");
  }
  // One point against `hpcontact infsup` of its scene: the same α.
  int found = 0;
  for (const auto& row : alpha.records())
    if (row.at("p") == "2" && row.at("pC") == "1" && row.at("level") == "2" && row.at("ratio") == "0.5") {
      ++found;
      const auto point = run("infsup --scene " + kCube +
                             " --p 2 --pc 1 --ratio 1/2 --alpha-tol 1e-3 --set domain.n_x=4 --set domain.n_y=4");
      ASSERT_EQ(point.exit_code, 0) << point.output;
      EXPECT_NEAR(std::stod(row.at("alpha")), alpha_printed(point), 1e-12);
    }
  EXPECT_EQ(found, 1);
  // Under mpirun each rank takes whole groups, or both ranks factorize each group's A_G together
  // (--ranks-per-unit 2): the serial α to round-off either way.
  for (const char* per_unit : {"1", "2"}) {
    const auto out = dir / (std::string("ranks_") + per_unit);
    const auto ranks =
        run_command(kMpiEnvironment + "timeout 300 mpirun -n 2 --oversubscribe " HPCONTACT_CLI " sweep " +
                    (dir / "sweep.toml").string() + " --out " + out.string() + " --ranks-per-unit " + per_unit);
    ASSERT_EQ(ranks.exit_code, 0) << ranks.output;
    const CsvFile parallel = read_csv(out / "alpha.csv");
    ASSERT_EQ(parallel.records().size(), alpha.records().size()) << per_unit;
    for (std::size_t r = 0; r < alpha.records().size(); ++r) {
      const double expected = std::stod(alpha.records()[r].at("alpha"));
      EXPECT_NEAR(std::stod(parallel.records()[r].at("alpha")), expected, 1e-10 * std::max(expected, 1e-3))
          << per_unit << ", row " << r;
    }
  }
  const std::string before = without_seconds(dir / "out" / "alpha.csv");
  const auto resumed = run("sweep " + (dir / "sweep.toml").string() + " --out " + (dir / "out").string());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_EQ(without_seconds(dir / "out" / "alpha.csv"), before);
}

// The spurious mode of p = 1, p_C = 0 with H = h on 8 × 8 × 8 cells (--mode FILE.vtu, one quadrilateral
// per cell of T_{C,H} at p_C = 0): a checkerboard, μ_ij (−1)^{i+j} of one sign on every cell, under an
// envelope largest at the centre of Γ_C and smallest at its corners, where alone the checkerboard
// meets Bᵀ (why α decays faster than h in 3-D).
TEST(SolidStability, SpuriousModeOfTheUnstablePairingIsACheckerboard) {
  const auto file = scratch("solid_mode") / "mode.vtu";
  const auto analysed =
      run("infsup --scene " + kCube +
          " --p 1 --pc 0 --ratio 1 --set domain.n_x=8 --set domain.n_y=8 --set domain.n_z=8 --mode " + file.string());
  ASSERT_EQ(analysed.exit_code, 0) << analysed.output;
  std::ifstream stream(file, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(stream)), std::istreambuf_iterator<char>());
  const auto mode = appended_array(text, "mode"), points = appended_array(text, "Points");
  ASSERT_EQ(mode.size(), 64u * 4u);
  double centre = 0.0, corner = INFINITY;
  int sign = 0;
  for (std::size_t c = 0; c < 64; ++c) {
    // (the cell's four points: its value, constant, and its centre's grid indices)
    double x = 0.0, y = 0.0;
    for (std::size_t k = 4 * c; k < 4 * c + 4; ++k) {
      EXPECT_NEAR(mode[k], mode[4 * c], 1e-12);
      x += points[3 * k] / 4.0, y += points[3 * k + 1] / 4.0;
    }
    const int i = static_cast<int>(std::floor((x + 1.0) * 4.0)), j = static_cast<int>(std::floor((y + 1.0) * 4.0));
    const int here = (mode[4 * c] * ((i + j) % 2 == 0 ? 1.0 : -1.0)) > 0.0 ? 1 : -1;
    if (sign == 0) sign = here;
    EXPECT_EQ(here, sign) << "cell " << i << ", " << j;
    if ((i == 3 || i == 4) && (j == 3 || j == 4)) centre = std::max(centre, std::abs(mode[4 * c]));
    if ((i == 0 || i == 7) && (j == 0 || j == 7)) corner = std::min(corner, std::abs(mode[4 * c]));
  }
  EXPECT_GT(centre, 10.0 * corner);
}

TEST(SolidStability, SolveWritesTheMultiplierOnItsSurfaceMesh) {
  const auto dir = scratch("solid_multiplier_vtu");
  const auto solved = run("solve " + kCube + " --out " + dir.string());
  ASSERT_EQ(solved.exit_code, 0) << solved.output;
  std::ifstream stream(dir / "multiplier_signorini.vtu", std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(stream)), std::istreambuf_iterator<char>());
  const auto lambda = appended_array(text, "lambda"), points = appended_array(text, "Points");
  // cube.toml: 4 × 4 faces on Γ_C, h/H = 1/2, p_C = 1: 2 × 2 cells of 2 × 2 points each.
  ASSERT_EQ(lambda.size(), 16u);
  double smallest = INFINITY;
  for (std::size_t k = 0; k < lambda.size(); ++k) {
    EXPECT_LE(lambda[k], 1e-12);  // λ ≤ 0 at the nodal points (the corners of the lattice at p_C = 1)
    EXPECT_NEAR(points[3 * k + 2], -1.0, 1e-14);
    smallest = std::min(smallest, lambda[k]);
  }
  EXPECT_LT(smallest, 0.0);
}

TEST(SolidStability, WhatThreeDimensionalAlphaDoesNotTakeIsRefusedByName) {
  const auto extension = run("infsup --scene " + kCube + " --norm extension");
  expect_refused(extension, "infsup.norm");
  const auto mode = run("infsup --scene " + kCube + " --mode " + (scratch("solid_mode") / "mode.csv").string());
  expect_refused(mode, "ending in .vtu");
  const auto energy = run("infsup --scene " + kHertz + " --set 'infsup.primal_norm=\"energy\"'");
  expect_refused(energy, "infsup.primal_norm");
  const auto dir = scratch("solid_sweep_family");
  std::ofstream(dir / "cube.toml") << std::ifstream(kCube).rdbuf();
  std::ofstream(dir / "sweep.toml") << "[sweep]\nscene = \"cube.toml\"\nlevels = { \"domain.n_z\" = [2, 4] }\n"
                                       "family = [\"standard\"]\n";
  const auto family = run("sweep " + (dir / "sweep.toml").string() + " --out " + (dir / "out").string());
  expect_refused(family, "sweep.family");
}

}  // namespace
}  // namespace hpcontact::testing
