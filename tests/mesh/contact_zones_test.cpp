// Several contact zones and closed contact curves: Γ_C split into zones (open or closed curves),
// T_{C,H} built and broken per zone, the interpolation-norm Gram matrix block diagonal by zones,
// a two-zone problem equal to two one-zone halves, and a closed curve (a hole around a pin) with
// KKT at the constraint points.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <sstream>

#include "assembly/coupling.hpp"
#include "core/error.hpp"
#include "driver/scene_run.hpp"
#include "mesh/boundary_mesh.hpp"
#include "mesh/contact_boundary.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "norms/interpolation_norm_kernel.hpp"
#include "scene/scene_mesh.hpp"
#include "scene/scene_reader.hpp"
#include "space/multiplier_space.hpp"
#include "support/csv_file.hpp"
#include "support/scratch.hpp"
#include "support/slepc_test_environment.hpp"

using namespace hpcontact;
using mesh::Point;

namespace {

const std::string kZones = std::string(HPCONTACT_SOURCE_DIR) + "/studies/zones/";

driver::RunResult run(const std::string& scene_file, const std::vector<scene::SceneOverride>& overrides,
                      const std::string& name) {
  const auto dir = hpcontact::testing::scratch("zones_" + name);
  driver::SceneRunOptions options;
  options.out = dir;
  return driver::run_scene(scene::read_scene(kZones + scene_file, overrides), options);
}

}  // namespace

TEST(ContactZones, TwoPiecesOfAnEdgeAreTwoOpenZonesInOrder) {
  auto mesh = mesh::make_rectangle_mesh({}, 8, 8);
  // The bottom edge without its middle: [-1, -0.5] and [0.25, 1].
  mesh::assign_boundary_part(mesh, mesh::BoundaryPart::contact,
                             [](const Point& x) { return x.y() < -0.99 && (x.x() < -0.5 || x.x() > 0.25); });
  const mesh::ContactBoundary contact(mesh);
  ASSERT_EQ(contact.zones().size(), 2u);
  EXPECT_NEAR(contact.zones()[0].length(), 0.5, 1e-15);
  EXPECT_NEAR(contact.zones()[1].length(), 0.75, 1e-15);
  EXPECT_FALSE(contact.zones()[0].closed);
  EXPECT_EQ(contact.zone_at(0.3), 0);
  EXPECT_EQ(contact.zone_at(0.6), 1);
  // Within a zone s is arc length from its start; the second zone starts at x = 0.25.
  EXPECT_NEAR(contact.point_at(0.5).x(), -0.5, 1e-15);
  EXPECT_NEAR(contact.point_at(0.5 + 1e-9).x(), 0.25, 1e-8);
  EXPECT_NEAR(contact.point_at(1.25).x(), 1.0, 1e-15);
}

TEST(ContactZones, BoundaryMeshBreaksAtEveryZoneEnd) {
  const std::string two = kZones + "two_zones.toml";
  for (const auto& overrides : std::vector<std::vector<scene::SceneOverride>>{
           {},
           {{"contact_mesh.m", 3LL, "test"}},
           {{"contact_mesh.breakpoints", std::vector<std::string>{"1.5", "2.5", "4"}, "test"}}}) {
    const auto scene = scene::read_scene(two, overrides);
    const auto mesh = scene::build_scene_mesh(scene);
    const mesh::ContactBoundary contact(mesh);
    ASSERT_EQ(contact.zones().size(), 2u);
    const auto boundary = scene::build_scene_boundary_mesh(scene, contact);
    ASSERT_EQ(boundary.zones().size(), 2u);
    const auto& nodes = boundary.nodes();
    EXPECT_NE(std::find(nodes.begin(), nodes.end(), 2.0), nodes.end()) << "the first zone's end";
    for (int k = 0; k < boundary.n_segments(); ++k)
      EXPECT_EQ(boundary.zone_of_segment(k), boundary.segment_end(k) <= 2.0 ? 0 : 1);
    if (overrides.empty()) {
      EXPECT_EQ(boundary.n_segments(), 8);  // h/H = 1/2 on 8 + 8 edges
    }
  }
  // A boundary mesh that ignores the zones is refused where it meets Γ_C.
  const auto scene = scene::read_scene(two);
  const auto mesh = scene::build_scene_mesh(scene);
  const mesh::ContactBoundary contact(mesh);
  EXPECT_THROW(assembly::common_intervals(contact, mesh::BoundaryMesh::uniform(contact.length(), 4)), InputError);
}

TEST(ContactZones, InterpolationGramIsBlockDiagonalWithEachZonesOwnKernel) {
  // Two zones of lengths 1.5 and 1, two segments each, degrees 0..2.
  mesh::BoundaryMesh both({0.0, 0.5, 1.5, 2.0, 2.5});
  both.set_zones({{0.0, 1.5, false}, {1.5, 2.5, false}}, "test");
  const space::MultiplierSpace multipliers(both, std::vector<int>{1, 2, 0, 2});
  const Eigen::MatrixXd gram = norms::interpolation_norm_gram_kernel(multipliers);
  const mesh::BoundaryMesh first({0.0, 0.5, 1.5}), second({0.0, 0.5, 1.0});
  const Eigen::MatrixXd g1 =
      norms::interpolation_norm_gram_kernel(space::MultiplierSpace(first, std::vector<int>{1, 2}));
  const Eigen::MatrixXd g2 =
      norms::interpolation_norm_gram_kernel(space::MultiplierSpace(second, std::vector<int>{0, 2}));
  ASSERT_EQ(gram.rows(), g1.rows() + g2.rows());
  EXPECT_LT((gram.topLeftCorner(g1.rows(), g1.cols()) - g1).norm(), 1e-14 * g1.norm());
  EXPECT_LT((gram.bottomRightCorner(g2.rows(), g2.cols()) - g2).norm(), 1e-14 * g2.norm());
  EXPECT_EQ(gram.topRightCorner(g1.rows(), g2.cols()).norm(), 0.0);
  // One zone of length 2.5 couples the segments: the same space without zones differs.
  const mesh::BoundaryMesh whole({0.0, 0.5, 1.5, 2.0, 2.5});
  const Eigen::MatrixXd coupled =
      norms::interpolation_norm_gram_kernel(space::MultiplierSpace(whole, std::vector<int>{1, 2, 0, 2}));
  EXPECT_GT(coupled.topRightCorner(g1.rows(), g2.cols()).norm(), 1e-3);
  // A closed zone has no interval kernel: the message names the way out.
  mesh::BoundaryMesh closed({0.0, 1.0, 2.0});
  closed.set_zones({{0.0, 2.0, true}}, "test");
  try {
    norms::interpolation_norm_gram_kernel(space::MultiplierSpace(closed, 1));
    ADD_FAILURE() << "a closed zone must be refused";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), ::testing::HasSubstr("[infsup] norm = \"extension\""));
  }
}

TEST(ContactZones, TwoZonesAreTwiceTheHalfProblem) {
  // two_zones.toml is even in y; half.toml is its lower half with the symmetry plane free.
  const auto whole = run("two_zones.toml", {}, "two");
  const auto half = run("half.toml", {}, "half");
  EXPECT_NEAR(whole.contact("signorini").energy, 2 * half.contact("signorini").energy, 1e-13);
  EXPECT_LT(whole.contact("signorini").solver.kkt_residual, 1e-12);
  const auto& zones = whole.contact("signorini").zones;
  ASSERT_EQ(zones.size(), 2u);
  EXPECT_NEAR(zones[0].contact_set_length, zones[1].contact_set_length, 1e-12);
  EXPECT_NEAR(zones[0].contact_set_length, half.contact("signorini").contact_set_length, 1e-12);
  // α of each zone's multipliers alone: equal by symmetry, and at least α of the whole (a
  // smaller multiplier space); the zones couple through Ω, so the whole's α is below both.
  const double alpha = whole.infsup->record.alpha;
  const auto& zone_alpha = whole.infsup->zone_alpha;
  ASSERT_EQ(zone_alpha.size(), 2u);
  EXPECT_NEAR(zone_alpha[0], zone_alpha[1], 1e-10);
  EXPECT_GT(alpha, 0.1);
  EXPECT_LT(alpha, zone_alpha[0] - 1e-4);
  EXPECT_TRUE(half.infsup->zone_alpha.empty());
  // Independently: the same body with only the bottom edge as Γ_C (the top free) has the bottom
  // zone's α, since the primal space and the bottom multipliers are the same.
  const auto bottom = run("two_zones.toml",
                          {{"boundary.contact", std::string("abs(y + 1) < 1e-9"), "test"},
                           {"run.effects", std::vector<std::string>{"infsup"}, "test"}},
                          "bottom");
  EXPECT_NEAR(bottom.infsup->record.alpha, zone_alpha[0], 1e-9);
  // The boundary samples carry their zone.
  const auto samples =
      hpcontact::testing::read_csv(hpcontact::testing::scratch_root() / "zones_two" / "boundary_signorini.csv");
  EXPECT_THAT(samples.header_line(), ::testing::EndsWith(",zone"));
  std::set<std::string> seen;
  for (const auto& row : samples.rows) seen.insert(row.back());
  EXPECT_EQ(seen, (std::set<std::string>{"0", "1"}));
}

TEST(ContactZones, ClosedCurveAroundAPinMeetsKkt) {
  const auto scene = scene::read_scene(kZones + "pin.toml");
  const auto mesh = scene::build_scene_mesh(scene);
  const mesh::ContactBoundary contact(mesh);
  ASSERT_EQ(contact.zones().size(), 1u);
  EXPECT_TRUE(contact.zones()[0].closed);
  EXPECT_NEAR(contact.length(), std::numbers::pi / 2 * 2, 1e-12);  // 2π · 1/2
  // It starts at its lexicographically first vertex and runs with the plate on its left: the
  // outward normal (into the hole) is the tangent turned clockwise.
  EXPECT_LT((contact.point_at(0.0) - Point(-0.5, 0.0)).norm(), 1e-14);
  for (double s : {0.1, 1.0, 2.5}) {
    const Point t = contact.tangent_at(s), n = contact.normal_at(s);
    EXPECT_LT((n - Point(t.y(), -t.x())).norm(), 1e-12) << s;
    EXPECT_LT((n + contact.point_at(s) / 0.5).norm(), 1e-12) << "the normal points into the hole";
  }
  const auto summary = run("pin.toml", {{"run.effects", std::vector<std::string>{"signorini"}, "test"}}, "pin");
  EXPECT_LT(summary.contact("signorini").solver.kkt_residual, 1e-12);
  const double contact_length = summary.contact("signorini").contact_set_length;
  EXPECT_GT(contact_length, 0.3);
  EXPECT_LT(contact_length, 0.8 * std::numbers::pi);
  EXPECT_TRUE(summary.contact("signorini").zones[0].closed);
  // The interpolation norm is refused with the way out; the scene's extension norm gives α.
  try {
    run("pin.toml", {{"infsup.norm", std::string("interp"), "test"}}, "pin_interp");
    ADD_FAILURE() << "the interpolation norm on a closed curve must be refused";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), ::testing::HasSubstr("closed curve"));
  }
}

// Each zone its own T_{C,H}, p_C and constraint points: lists with one value per zone (ratio,
// constraint_points) and a p_C rule by position give the same discrete problem as the equivalent
// explicit breakpoints, and lists of the wrong length or too few points are refused by name.
TEST(ContactZones, EachZoneItsOwnContactMeshDegreeAndConstraintPoints) {
  const std::vector<scene::SceneOverride> per_zone{{"contact_mesh.ratio", std::vector<std::string>{"1/2", "1"}, "test"},
                                                   {"discretization.pC", std::string("1 + 2 * (y > 0)"), "test"},
                                                   {"solve.constraint_points", std::vector<long long>{2, 5}, "test"},
                                                   {"run.effects", std::vector<std::string>{"signorini"}, "test"}};
  const auto lists = run("two_zones.toml", per_zone, "per_zone");
  // Zone 0 (the bottom edge, s ∈ [0, 2]): 4 segments; zone 1 (the top, s ∈ [2, 4]): 8.
  std::vector<double> breakpoints{0.5, 1.0, 1.5, 2.0};
  for (int k = 1; k <= 8; ++k) breakpoints.push_back(2.0 + 0.25 * k);
  auto explicit_overrides = per_zone;
  explicit_overrides[0] = {"contact_mesh.breakpoints", breakpoints, "test"};
  const auto given = run("two_zones.toml", explicit_overrides, "breakpoints");
  const auto& signorini = lists.contact("signorini");
  EXPECT_NEAR(signorini.energy, given.contact("signorini").energy, 1e-14);
  EXPECT_LT(signorini.solver.kkt_residual, 1e-12);
  EXPECT_EQ(signorini.nmult, 4 * 2 + 8 * 4);
  EXPECT_EQ(signorini.constraint_points->total, 4 * 2 + 8 * 5);
  EXPECT_EQ(signorini.constraint_points->max, 5);

  auto expect_refused = [&](const std::vector<scene::SceneOverride>& overrides, const std::string& key,
                            const std::string& rule) {
    try {
      run("two_zones.toml", overrides, "refused");
      ADD_FAILURE() << key << " was accepted";
    } catch (const InputError& error) {
      EXPECT_THAT(error.what(), ::testing::HasSubstr(key));
      EXPECT_THAT(error.what(), ::testing::HasSubstr(rule));
    }
  };
  auto three_ratios = per_zone;
  three_ratios[0] = {"contact_mesh.ratio", std::vector<std::string>{"1/2", "1", "1"}, "test"};
  expect_refused(three_ratios, "contact_mesh.ratio", "one per zone of Γ_C: the scene has 2 zones");
  auto too_few = per_zone;
  too_few[2] = {"solve.constraint_points", std::vector<long long>{2, 3}, "test"};
  expect_refused(too_few, "solve.constraint_points", "at least p_C + 1 = 4 (a segment of zone 1 has p_C = 3)");
}
