// 3-D scenes through `hpcontact solve`: the extruded paper problems against the planar runs (energy
// times the width), the boundary samples (weights summing to |Γ_C|, λ ≤ 0), the VTU of hexahedra,
// and the keys, effects and commands 3-D scenes refuse with a message naming them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <utility>

#include "support/cli_runner.hpp"
#include "support/vtu_arrays.hpp"

namespace hpcontact::testing {
namespace {

const std::string kExtruded = std::string(HPCONTACT_SOURCE_DIR) + "/studies/three_d/extruded_signorini.toml";
const std::string kPlanar = std::string(HPCONTACT_SOURCE_DIR) + "/studies/paper/figure1_signorini.toml";

nlohmann::json summary_of(const std::filesystem::path& out) {
  std::ifstream file(out / "summary.json");
  return nlohmann::json::parse(file);
}

TEST(SolidScene, ExtrudedSignoriniHasThePlanarEnergyTimesTheWidth) {
  const auto dir = scratch("solid_extruded");
  const auto solid = run("solve " + kExtruded + " --out " + (dir / "solid").string());
  ASSERT_EQ(solid.exit_code, 0) << solid.output;
  const auto planar = run("solve " + kPlanar + " --effects signorini --n 8 --out " + (dir / "planar").string());
  ASSERT_EQ(planar.exit_code, 0) << planar.output;
  const auto solid_summary = summary_of(dir / "solid"), planar_summary = summary_of(dir / "planar");
  const double planar_energy = planar_summary.at("signorini").at("energy").get<double>();
  EXPECT_NEAR(solid_summary.at("signorini").at("energy").get<double>(), 0.5 * planar_energy,
              1e-10 * std::abs(planar_energy));
  EXPECT_EQ(solid_summary.at("dimension").get<int>(), 3);
  EXPECT_EQ(solid_summary.at("faces_on_contact").get<int>(), 8 * 2);
  EXPECT_EQ(solid_summary.at("m").get<int>(), 4 * 1);
  EXPECT_NE(solid.output.find("contact area"), std::string::npos) << solid.output;
  // The samples: weights summing to |Γ_C| = 2 · 0.5, λ ≤ 0 (p_C = 1 nodal: exact between the
  // points), the contact set a band x ∈ [−a, a] over the whole width: its area 0.5 times the planar length.
  const CsvFile samples = read_csv(dir / "solid" / "boundary_signorini.csv");
  EXPECT_EQ(samples.header_line(), "x,y,z,w,u,obstacle,lambda");
  const auto columns = samples.numeric_columns();
  double area = 0.0, largest = -INFINITY;
  for (std::size_t k = 0; k < columns.at("w").size(); ++k) {
    area += columns.at("w")[k];
    largest = std::max(largest, columns.at("lambda")[k]);
    EXPECT_NEAR(columns.at("z")[k], -1.0, 1e-14);
  }
  EXPECT_NEAR(area, 1.0, 1e-13);
  EXPECT_LE(largest, 1e-12);
  const double contact_area = solid_summary.at("signorini").at("contact_area").get<double>();
  EXPECT_GT(contact_area, 0.1);
  EXPECT_LT(contact_area, 1.0);
  // The solution file: 8 · 2 · 8 cells of p³ = 8 linear hexahedra each.
  std::ifstream vtu(dir / "solid" / "solution_signorini.vtu");
  const std::string text((std::istreambuf_iterator<char>(vtu)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("NumberOfCells=\"1024\""), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir / "solid" / "boundary_friction_s.csv"));
}

TEST(SolidScene, ExtrudedPlaneStrainHasThePlanarEnergyAndForceTimesTheWidth) {
  // The elastic square with Γ_C its bottom edge, and its extrusion with rollers u_y = 0 on the
  // faces y = 0, 0.5: the 3-D operator, shear terms included, against plane strain.
  const auto dir = scratch("solid_plane_strain");
  const auto solid = run("solve " + std::string(HPCONTACT_SOURCE_DIR) +
                         "/studies/three_d/extruded_frictionless.toml --out " + (dir / "solid").string());
  ASSERT_EQ(solid.exit_code, 0) << solid.output;
  const auto planar = run("solve " + std::string(HPCONTACT_SOURCE_DIR) +
                          "/studies/elasticity/square.toml --effects frictionless --set 'boundary.contact=\"abs(y + "
                          "1) < 1e-9\"' --out " +
                          (dir / "planar").string());
  ASSERT_EQ(planar.exit_code, 0) << planar.output;
  const auto solid_result = summary_of(dir / "solid").at("frictionless");
  const auto planar_result = summary_of(dir / "planar").at("frictionless");
  for (const char* key : {"energy", "total_force"}) {
    const double expected = 0.5 * planar_result.at(key).get<double>();
    EXPECT_NEAR(solid_result.at(key).get<double>(), expected, 1e-10 * std::abs(expected)) << key;
  }
  const CsvFile samples = read_csv(dir / "solid" / "boundary_frictionless.csv");
  EXPECT_EQ(samples.header_line(), "x,y,z,w,gap,pressure,traction_1,traction_2");
  double force = 0.0;
  for (const auto& row : samples.records()) force += std::stod(row.at("w")) * std::stod(row.at("pressure"));
  EXPECT_NEAR(force, solid_result.at("total_force").get<double>(), 1e-12);
}

// The extruded square's 3-D solve of the friction effect `effect` and the planar square's, with the
// same `friction` keys, into dir/solid and dir/planar: their results in summary.json.
std::pair<nlohmann::json, nlohmann::json> extruded_and_planar(const std::filesystem::path& dir, const char* effect,
                                                              const std::string& friction) {
  const auto solid = run("solve " + std::string(HPCONTACT_SOURCE_DIR) +
                         "/studies/three_d/extruded_frictionless.toml --set 'run.effects=[\"" + effect + "\"]'" +
                         friction + "--out " + (dir / "solid").string());
  EXPECT_EQ(solid.exit_code, 0) << solid.output;
  const auto planar =
      run("solve " + std::string(HPCONTACT_SOURCE_DIR) + "/studies/elasticity/square.toml --effects " + effect +
          " --set 'boundary.contact=\"abs(y + 1) < 1e-9\"'" + friction + "--out " + (dir / "planar").string());
  EXPECT_EQ(planar.exit_code, 0) << planar.output;
  if (solid.exit_code != 0 || planar.exit_code != 0) return {};
  return {summary_of(dir / "solid").at(effect), summary_of(dir / "planar").at(effect)};
}

// Tresca in 3-D (a disc |(t₁, t₂)| ≤ s per nodal point) on the plane-strain square extruded in y:
// with y-independent data and rollers u_y = 0 the solution is the planar one at every y, t₂ = 0, and
// the disc acts as the planar bound |t₁| ≤ s: energy and P are the planar ones times the width,
// with stick and slip on Γ_C.
TEST(SolidScene, ExtrudedTrescaHasThePlanarEnergyAndForceTimesTheWidth) {
  const auto dir = scratch("solid_tresca");
  const std::string friction = " --set 'data.f_x=\"0.05\"' --set 'data.s=\"0.1\"' ";
  const auto [solid_result, planar_result] = extruded_and_planar(dir, "tresca", friction);
  if (HasFailure()) return;
  for (const char* key : {"energy", "total_force"}) {
    const double expected = 0.5 * planar_result.at(key).get<double>();
    EXPECT_NEAR(solid_result.at(key).get<double>(), expected, 1e-9 * std::abs(expected)) << key;
  }
  const CsvFile samples = read_csv(dir / "solid" / "boundary_tresca.csv");
  int stick = 0, slip = 0;
  for (const auto& row : samples.records()) {
    const double t1 = std::stod(row.at("traction_1")), t2 = std::stod(row.at("traction_2"));
    EXPECT_LT(std::abs(t2), 1e-10);
    EXPECT_LE(std::abs(t1), 0.1 * (1 + 1e-9));
    (std::abs(t1) > 0.1 * (1 - 1e-6) ? slip : stick) += 1;
  }
  EXPECT_GT(stick, 0);
  EXPECT_GT(slip, 0);
  EXPECT_TRUE(std::filesystem::exists(dir / "solid" / "multiplier_tresca.vtu"));
  const auto no_threshold = run("solve " + std::string(HPCONTACT_SOURCE_DIR) +
                                "/studies/three_d/extruded_frictionless.toml --set 'run.effects=[\"tresca\"]' --out " +
                                (dir / "none").string());
  expect_refused(no_threshold, "data.s");
}

// Coulomb in 3-D (the Tresca discs of radius F P, by the fixed point from s = 0; F = 0.2) on the same
// extruded square: the planar Coulomb solution at every y, so energy and P are the planar ones times
// the width; t₂ = 0, |t₁| ≤ F P with stick and slip; the fixed point's iterations are reported.
TEST(SolidScene, ExtrudedCoulombHasThePlanarEnergyAndForceTimesTheWidth) {
  const auto dir = scratch("solid_coulomb");
  const std::string friction = " --set 'data.f_x=\"0.05\"' --set data.friction_coefficient=0.2 ";
  const auto [solid_result, planar_result] = extruded_and_planar(dir, "coulomb", friction);
  if (HasFailure()) return;
  for (const char* key : {"energy", "total_force"}) {
    const double expected = 0.5 * planar_result.at(key).get<double>();
    EXPECT_NEAR(solid_result.at(key).get<double>(), expected, 1e-8 * std::abs(expected)) << key;
  }
  EXPECT_GT(solid_result.at("fixed_point").at("iterations").get<int>(), 1);
  EXPECT_LE(solid_result.at("fixed_point").at("changes").back().get<double>(), 1e-10);
  EXPECT_DOUBLE_EQ(solid_result.at("friction_coefficient").get<double>(), 0.2);
  const CsvFile samples = read_csv(dir / "solid" / "boundary_coulomb.csv");
  int stick = 0, slip = 0;
  double scale = 0.0;
  for (const auto& row : samples.records()) scale = std::max(scale, 1e-9 * std::abs(std::stod(row.at("pressure"))));
  for (const auto& row : samples.records()) {
    const double t1 = std::stod(row.at("traction_1")), t2 = std::stod(row.at("traction_2"));
    const double bound = 0.2 * std::stod(row.at("pressure"));
    EXPECT_LT(std::abs(t2), 1e-10);
    EXPECT_LE(std::abs(t1), bound + scale);
    if (bound > 1e3 * scale) (std::abs(t1) > bound * (1 - 1e-6) ? slip : stick) += 1;
  }
  EXPECT_GT(stick, 0);
  EXPECT_GT(slip, 0);
}

// A body force along the diagonal of Γ_C's plane pulls every node of T_{C,H} into slip along the
// diagonal: at the nodal points (the lattice of multiplier_tresca.vtu at p_C = 1) |(t₁, t₂)| = s with
// both components well inside (−s, s). A box |t₁|, |t₂| ≤ s holds no such point on its boundary
// and would let |(t₁, t₂)| reach s√2.
TEST(SolidScene, TrescaBoundIsADiscNotABox) {
  const auto dir = scratch("solid_tresca_disc");
  std::ofstream(dir / "scene.toml")
      << "[domain]\nx_min = -1.0\nx_max = 1.0\ny_min = -1.0\ny_max = 1.0\n"
         "z_min = -1.0\nz_max = 1.0\nn_x = 4\nn_y = 4\nn_z = 4\n"
         "[boundary]\ncontact = \"abs(z + 1) < 1e-9\"\ndirichlet = \"abs(z - 1) < 1e-9\"\n"
         "[contact_mesh]\nratio = \"1/2\"\n[discretization]\np = 2\npC = 1\n"
         "[material]\nE = \"1\"\nnu = \"0.3\"\n"
         "[data]\nf_x = \"0.1\"\nf_y = \"0.1\"\nf_z = \"-1\"\n"
         "g = \"0.02 + 0.1 * (x^2 + y^2)\"\ns = \"0.1\"\n[run]\neffects = [\"tresca\"]\n";
  const auto solved = run("solve " + (dir / "scene.toml").string() + " --out " + (dir / "out").string());
  ASSERT_EQ(solved.exit_code, 0) << solved.output;
  std::ifstream stream(dir / "out" / "multiplier_tresca.vtu", std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(stream)), std::istreambuf_iterator<char>());
  const auto t1 = appended_array(text, "traction_1"), t2 = appended_array(text, "traction_2");
  ASSERT_EQ(t1.size(), 16u);
  for (std::size_t k = 0; k < t1.size(); ++k) {
    EXPECT_NEAR(std::hypot(t1[k], t2[k]), 0.1, 1e-9) << k;
    // (both components well inside (−s, s): a box would not hold such a point on its boundary)
    EXPECT_GT(std::min(std::abs(t1[k]), std::abs(t2[k])), 0.03) << k;
    EXPECT_LT(std::max(std::abs(t1[k]), std::abs(t2[k])), 0.097) << k;
  }
}

/// `hpcontact solve` of the extruded scene with one key overridden (--set KEY=VALUE).
Run solve_with(const std::string& name, const std::string& key_value) {
  return run("solve " + kExtruded + " --set '" + key_value + "' --out " + (scratch(name) / "out").string());
}

TEST(SolidScene, KeysEffectsAndCommandsOfPlanarScenesAreRefusedByName) {
  const auto refined = solve_with("solid_refined", "domain.refinements=1");
  expect_refused(refined, "domain.refinements");
  EXPECT_NE(refined.output.find("3-D scene"), std::string::npos) << refined.output;
  // An axis given by its nodes takes none of the keys they replace.
  const auto nodes_and_n = solve_with("solid_nodes", "domain.x_nodes=[-1.0, 0.0, 1.0]");
  expect_refused(nodes_and_n, "not with domain.x_nodes");
  const auto falling = solve_with("solid_falling_nodes", "domain.z_nodes=[0.0, -1.0]");
  expect_refused(falling, "each larger than the one before");
  const auto convergence = solve_with("solid_convergence", "run.effects=[\"signorini\", \"convergence\"]");
  expect_refused(convergence, "or infsup (α of the pairing) in a 3-D scene");
  const auto three_m = solve_with("solid_m", "contact_mesh.m=[2, 2, 2]");
  expect_refused(three_m, "one or two integers");
  const auto odd_ratio = solve_with("solid_ratio", "contact_mesh.ratio=\"1/3\"");
  expect_refused(odd_ratio, "whole cells");
  const auto no_dirichlet = solve_with("solid_no_dirichlet", "boundary.dirichlet=\"z > 5\"");
  expect_refused(no_dirichlet, "boundary.dirichlet");
  const auto two_sides = solve_with("solid_two_sides", "boundary.contact=\"abs(z + 1) < 1e-9 || x < -0.99\"");
  expect_refused(two_sides, "not flat");
  // The planar commands name the 3-D key rather than misreading the box.
  const auto advised = run("advise " + kExtruded + " --out " + (scratch("solid_advise") / "out").string());
  expect_refused(advised, "domain.n_z");
  // z is a variable of 3-D scenes only.
  const auto dir = scratch("planar_z");
  std::ifstream source(kPlanar);
  std::string text((std::istreambuf_iterator<char>(source)), std::istreambuf_iterator<char>());
  text.replace(text.find("g = \"-x^2\""), 10, "g = \"-x^2 + z\"");
  std::ofstream(dir / "scene.toml") << text;
  const auto planar_z = run("solve " + (dir / "scene.toml").string() + " --out " + (dir / "out").string());
  expect_refused(planar_z, "variables: x, y;");
  const auto planar_f_z = run("solve " + kPlanar + " --set data.f_z=1 --out " + (dir / "out").string());
  expect_refused(planar_f_z, "only in a 3-D scene");
}

}  // namespace
}  // namespace hpcontact::testing
