// Rigid obstacles given as geometry ([obstacle]): the gap the run computes along Γ_C's normal
// equals the one derived by hand (data.g) to round-off, so the contact pressure does too: a
// tilted plane against a block, Hertz's parabola, a plane against the curved arc of a ring
// (elastic), and a circle and its distance expression against the scalar model's square. The
// closed forms of each shape and the messages of misses and misplaced keys are checked alone.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "contact/obstacle_gap.hpp"
#include "core/error.hpp"
#include "driver/scene_run.hpp"
#include "scene/scene_reader.hpp"
#include "support/slepc_test_environment.hpp"

using namespace hpcontact;
using ::testing::HasSubstr;

namespace {

// The column `name` of a table the run returned.
std::vector<double> column(const io::CsvTable& table, const std::string& name) {
  const auto at = std::find(table.columns().begin(), table.columns().end(), name) - table.columns().begin();
  std::vector<double> values;
  for (const auto& row : table.rows()) values.push_back(std::get<double>(row[static_cast<std::size_t>(at)]));
  return values;
}

double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double difference = 0.0;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k)
    difference = std::max(difference, std::abs(a[k] - b[k]));
  return difference;
}

double max_abs(const std::vector<double>& a) {
  double m = 0.0;
  for (double v : a) m = std::max(m, std::abs(v));
  return m;
}

// The boundary table of `problem` from a run of the scene text.
io::CsvTable boundary_table(const std::string& text, const std::string& problem,
                            const std::string& path = "scene.toml") {
  std::map<std::string, io::CsvTable> tables;
  driver::SceneRunOptions options;
  options.write_files = false;
  options.tables = &tables;
  driver::run_scene(scene::parse_scene(text, path), options);
  return tables.at("boundary_" + problem);
}

// The pressure (elastic) or λ (scalar) and the gap of the two scenes agree to `tolerance`
// relative to their size, and contact is active (the comparison means something).
void expect_same_contact(const std::string& by_hand, const std::string& by_geometry, const std::string& problem,
                         const std::string& multiplier, const std::string& gap,
                         const std::string& path = "scene.toml") {
  const auto hand = boundary_table(by_hand, problem, path), geometry = boundary_table(by_geometry, problem, path);
  const auto hand_multiplier = column(hand, multiplier), geometry_multiplier = column(geometry, multiplier);
  ASSERT_GT(max_abs(hand_multiplier), 1e-6) << "no contact: the comparison would be empty";
  EXPECT_LE(max_difference(hand_multiplier, geometry_multiplier), 1e-10 * max_abs(hand_multiplier));
  EXPECT_LE(max_difference(column(hand, gap), column(geometry, gap)), 1e-10 * max_abs(column(hand, gap)));
}

std::string block(const std::string& obstacle) {
  return R"toml([domain]
x_min = -1
x_max = 1
y_min = -1
y_max = 0
n_x = 4
n_y = 2
[boundary]
contact = "abs(y) < 1e-9"
dirichlet = "abs(y + 1) < 1e-9"
[contact_mesh]
ratio = 1
[discretization]
p = 3
pC = 1
[material]
E = "1"
nu = "0.3"
[run]
effects = ["frictionless"]
)toml" + obstacle;
}

TEST(ObstacleGeometry, TiltedPlaneAgainstABlockGivesTheHandDerivedPressure) {
  // The plane y = -0.02 + 0.01 x above the block's top y = 0 (normal (0, 1)): g = -0.02 + 0.01 x.
  expect_same_contact(block("[data]\ng = \"-0.02 + 0.01 * x\"\n"),
                      block("[obstacle]\ntype = \"plane\"\npoint = [0, -0.02]\nnormal = [0.01, -1]\n"), "frictionless",
                      "pressure", "gap");
}

TEST(ObstacleGeometry, HertzParabolaGivesTheHandDerivedPressure) {
  // Vertex (0, -d), opening upwards away from the block: g = x²/(2R) - d with R = 2, d = 0.05.
  expect_same_contact(block("[data]\ng = \"x^2 / 4 - 0.05\"\n"),
                      block("[obstacle]\ntype = \"parabola\"\npoint = [0, -0.05]\nnormal = [0, -1]\nradius = 2\n"),
                      "frictionless", "pressure", "gap");
}

TEST(ObstacleGeometry, PlaneAgainstTheCurvedArcOfARingGivesTheHandDerivedPressure) {
  // The outer arc r = 2 of the quarter ring pushed outwards by 0.01, against the line through
  // P = (1.415, 1.415) with normal m = -(1, 1)/√2: along n = (x, y)/r the gap is
  // (P - X)·m / (n·m) = (2.83 - x - y) r / (x + y).
  const std::string ring = std::string(R"toml([domain]
mesh = ")toml") + HPCONTACT_SOURCE_DIR +
                           R"toml(/studies/curved/annulus.geo"
[boundary]
contact_groups = ["outer"]
dirichlet_groups = ["inner"]
fixed_x_groups = ["left"]
fixed_y_groups = ["bottom"]
u_D_x = "0.01 * x / sqrt(x^2 + y^2)"
u_D_y = "0.01 * y / sqrt(x^2 + y^2)"
[contact_mesh]
ratio = 1
[discretization]
p = 3
pC = 1
[material]
E = "1"
nu = "0.3"
[run]
effects = ["frictionless"]
)toml";
  expect_same_contact(ring + "[data]\ng = \"(2.83 - x - y) * sqrt(x^2 + y^2) / (x + y)\"\n",
                      ring + "[obstacle]\ntype = \"plane\"\npoint = [1.415, 1.415]\nnormal = [-1, -1]\n",
                      "frictionless", "pressure", "gap");
}

TEST(ObstacleGeometry, CircleAndItsDistanceExpressionGiveTheHandDerivedScalarSolution) {
  // Γ_C is y = -1 with outward normal (0, -1); the disk of radius 2 about (0, -2.95) pokes 0.05
  // through it: g = 1.95 - sqrt(4 - x²).
  const std::string hand =
      scene::paper_scene_text() + "g = \"1.95 - sqrt(4 - x^2)\"\n[run]\neffects = [\"signorini\"]\n";
  const std::string circle = scene::paper_scene_text() +
                             "[obstacle]\ntype = \"circle\"\npoint = [0, -2.95]\nradius = 2\n[run]\neffects = "
                             "[\"signorini\"]\n";
  const std::string distance = scene::paper_scene_text() +
                               "[obstacle]\ntype = \"distance\"\ndistance = \"sqrt(x^2 + (y + 2.95)^2) - 2\"\n[run]\n"
                               "effects = [\"signorini\"]\n";
  expect_same_contact(hand, circle, "signorini", "lambda", "obstacle");
  expect_same_contact(hand, distance, "signorini", "lambda", "obstacle");
}

TEST(ObstacleGeometry, ShapesGiveTheirClosedFormsAlongTheNormal) {
  const mesh::Point up(0.0, 1.0), x(0.3, 0.0);
  contact::RigidObstacle plane{contact::ObstacleType::plane, {0.0, 0.5}, {0.0, -1.0}, 1.0, "", "test"};
  EXPECT_NEAR(contact::gap_along(plane, x, up), 0.5, 1e-15);
  // Along a slanted normal the distance to the plane y = 0.5 grows as 1/cos.
  EXPECT_NEAR(contact::gap_along(plane, x, mesh::Point(0.6, 0.8)), 0.5 / 0.8, 1e-15);
  contact::RigidObstacle circle{contact::ObstacleType::circle, {0.0, 3.0}, {0.0, 1.0}, 2.0, "", "test"};
  EXPECT_NEAR(contact::gap_along(circle, x, up), 3.0 - std::sqrt(4.0 - 0.09), 1e-15);
  // A point inside the disk: the gap is the (negative) way back out along the normal.
  EXPECT_NEAR(contact::gap_along(circle, mesh::Point(0.3, 1.5), up), 3.0 - std::sqrt(4.0 - 0.09) - 1.5, 1e-15);
  contact::RigidObstacle parabola{contact::ObstacleType::parabola, {0.0, 0.1}, {0.0, -1.0}, 2.0, "", "test"};
  EXPECT_NEAR(contact::gap_along(parabola, x, up), 0.1 + 0.09 / 4.0, 1e-15);
  contact::RigidObstacle distance{contact::ObstacleType::distance, {}, {}, 1.0, "sqrt(x^2 + (y - 3)^2) - 2", "test"};
  EXPECT_NEAR(contact::gap_along(distance, x, up), 3.0 - std::sqrt(4.0 - 0.09), 1e-12);
}

TEST(ObstacleGeometry, ANormalThatMissesTheObstacleIsAnInputErrorNamingThePoint) {
  contact::RigidObstacle circle{contact::ObstacleType::circle, {0.0, 3.0}, {0.0, 1.0}, 1.0, "", "ring.toml"};
  try {
    contact::gap_along(circle, mesh::Point(2.5, 0.0), mesh::Point(0.0, 1.0));
    FAIL() << "a missed obstacle was given a gap";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("ring.toml"));
    EXPECT_THAT(error.what(), HasSubstr("(2.5, 0)"));
    EXPECT_THAT(error.what(), HasSubstr("does not meet the obstacle"));
  }
  contact::RigidObstacle away{contact::ObstacleType::plane, {0.0, 1.0}, {0.0, 1.0}, 1.0, "", "t.toml"};
  EXPECT_THROW(contact::gap_along(away, mesh::Point(0.0, 0.0), mesh::Point(0.0, 1.0)), InputError);
  // The distance expression alike: φ = y is > 0 at (0, 0.5), and the normal (0, 1) runs away from
  // its zero; Newton's root behind the point is no gap.
  contact::RigidObstacle level{contact::ObstacleType::distance, {}, {}, 1.0, "y", "t.toml"};
  EXPECT_THROW(contact::gap_along(level, mesh::Point(0.0, 0.5), mesh::Point(0.0, 1.0)), InputError);
  EXPECT_NEAR(contact::gap_along(level, mesh::Point(0.0, 0.5), mesh::Point(0.0, -1.0)), 0.5, 1e-14);
}

TEST(ObstacleGeometry, NewtonOnADistanceExpressionWorksAtTheProblemsOwnScale) {
  // A disk of radius 1e-7 m above a point 1e-8 m below it: Newton's steps scale with the length
  // given (obstacle_gap gives Γ_C's), not with 1.
  contact::RigidObstacle small{contact::ObstacleType::distance, {}, {}, 1.0, "sqrt(x^2 + (y - 2e-7)^2) - 1e-7", "t"};
  const double exact = 2e-7 - std::sqrt(1e-14 - 0.25e-14);
  EXPECT_NEAR(contact::gap_along(small, mesh::Point(0.5e-7, 0.0), mesh::Point(0.0, 1.0), 1e-6), exact, 1e-12 * exact);
}

std::string error_of(const std::string& text) {
  try {
    scene::parse_scene(text, "scene.toml");
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(ObstacleGeometry, KeysOutOfPlaceAreRefusedNamingTheKey) {
  EXPECT_THAT(error_of(block("[obstacle]\ntype = \"plane\"\npoint = [0, 0]\n")),
              HasSubstr("'obstacle.normal' = (missing)"));
  EXPECT_THAT(error_of(block("[obstacle]\ntype = \"plane\"\npoint = [0, 0]\nnormal = [0, -1]\nradius = 1\n")),
              HasSubstr("obstacle.radius"));
  EXPECT_THAT(error_of(block("[data]\ng = \"0\"\n[obstacle]\ntype = \"plane\"\npoint = [0, 0]\nnormal = [0, -1]\n")),
              HasSubstr("data.g"));
  EXPECT_THAT(error_of(block("[obstacle]\ntype = \"plane\"\npoint = [0, 0]\nnormal = [0, 0]\n")),
              HasSubstr("a non-zero vector"));
  EXPECT_THAT(error_of(block("[obstacle]\ntype = \"cone\"\n")), HasSubstr("must be one of"));
  EXPECT_THAT(error_of(block("[obstacle]\npoint = [0, 0]\n")), HasSubstr("'obstacle.type' = (missing)"));
}

}  // namespace
