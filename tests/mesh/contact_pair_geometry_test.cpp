// The geometry of a contact pair: Φ, the closest point on the master's Γ_C, the gap along the
// slave's normal, the slave breakpoints where Φ passes a master vertex and the mortar segments,
// on flat non-matching interfaces (fully and partly covered), on concentric arcs and on a concave
// master where Φ jumps.
#include "mesh/contact_pair_geometry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "support/annulus_sector.hpp"
#include "support/input_error_message.hpp"

using namespace hpcontact;
using mesh::Point;

namespace {

// A rectangle mesh whose Γ_C is the part of its boundary where `on_contact` holds at the edge's
// midpoint.
mesh::Mesh body(const mesh::Rectangle& rectangle, int n_x, int n_y,
                const std::function<bool(const Point&)>& on_contact) {
  auto mesh = mesh::make_rectangle_mesh(rectangle, n_x, n_y);
  mesh::assign_boundary_part(mesh, mesh::BoundaryPart::contact, on_contact);
  return mesh;
}

// The master's top y = −1 on (x_min, x_max) in n cells; the slave's bottom y = −0.99 on
// (−0.8, 0.8) in 3 cells: a gap of 0.01, the meshes non-matching.
struct FlatPair {
  FlatPair(double x_min, double x_max, int n)
      : master_mesh(body({x_min, x_max, -2.0, -1.0}, n, 2, [](const Point& p) { return p.y() > -1.0 - 1e-12; })),
        slave_mesh(body({-0.8, 0.8, -0.99, 0.0}, 3, 2, [](const Point& p) { return p.y() < -0.99 + 1e-12; })),
        master(master_mesh),
        slave(slave_mesh),
        projection(master) {}
  mesh::Mesh master_mesh, slave_mesh;
  mesh::ContactBoundary master, slave;
  mesh::MasterProjection projection;
};

// The slave x of each breakpoint.
std::vector<double> breakpoint_x(const FlatPair& pair) {
  std::vector<double> x;
  for (double s : pair.projection.slave_breakpoints(pair.slave)) x.push_back(pair.slave.point_at(s).x());
  return x;
}

}  // namespace

TEST(ContactPairGeometry, FlatNonMatchingInterfaceProjectsStraightDown) {
  const FlatPair pair(-1.0, 1.0, 5);
  for (double s = 0.0; s <= pair.slave.length(); s += 0.05) {
    const Point x = pair.slave.point_at(s);
    const auto phi = pair.projection.project(x);
    EXPECT_NEAR((phi.point - Point(x.x(), -1.0)).norm(), 0.0, 1e-15) << "s = " << s;
    EXPECT_NEAR(phi.distance, 0.01, 1e-15);
    EXPECT_TRUE(phi.covered);
    EXPECT_NEAR(pair.master.point_at(phi.s).x(), x.x(), 1e-15);
    EXPECT_NEAR(pair.projection.gap(pair.slave, s), 0.01, 1e-15);  // the slave above the master
  }
  // The master's inner vertices −0.6, −0.2, 0.2, 0.6 cut the slave's 3 edges into 7 segments;
  // its ends ±1 lie beyond the slave.
  const std::vector<double> expected{-0.6, -0.2, 0.2, 0.6};
  const auto x = breakpoint_x(pair);
  ASSERT_EQ(x.size(), expected.size());
  for (std::size_t k = 0; k < x.size(); ++k) EXPECT_NEAR(x[k], expected[k], 1e-14);
  const auto segments = pair.projection.mortar_segments(pair.slave);
  ASSERT_EQ(segments.size(), 7u);
  double length = 0.0;
  for (const auto& segment : segments) {
    length += segment.s_end - segment.s_begin;
    EXPECT_TRUE(segment.covered);
    // Both ends of the segment land on its master edge.
    const auto& image = pair.master.edges()[segment.master_edge];
    for (double s : {segment.s_begin, segment.s_end}) {
      const double master_s = pair.projection.project(pair.slave.point_at(s)).s;
      EXPECT_GE(master_s, image.s_begin - 1e-14);
      EXPECT_LE(master_s, image.s_end + 1e-14);
    }
  }
  EXPECT_NEAR(length, pair.slave.length(), 1e-14);
}

// A master shorter than the slave: beyond its ends the slave is not covered, Φ is the end, and
// the coverage boundaries x = ±0.5 are breakpoints.
TEST(ContactPairGeometry, PartlyCoveredSlaveKnowsWhereTheMasterEnds) {
  const FlatPair pair(-0.5, 0.5, 5);
  for (double x : {-0.75, -0.6, -0.5, -0.2, 0.0, 0.45, 0.5, 0.55, 0.79}) {
    const auto phi = pair.projection.project({x, -0.99});
    const bool inside = std::abs(x) <= 0.5;
    EXPECT_EQ(phi.covered, inside) << "x = " << x;
    EXPECT_NEAR(phi.point.x(), std::clamp(x, -0.5, 0.5), 1e-15);
    EXPECT_NEAR(phi.point.y(), -1.0, 1e-15);
  }
  const std::vector<double> expected{-0.5, -0.3, -0.1, 0.1, 0.3, 0.5};
  const auto x = breakpoint_x(pair);
  ASSERT_EQ(x.size(), expected.size());
  for (std::size_t k = 0; k < x.size(); ++k) EXPECT_NEAR(x[k], expected[k], 1e-14);
  for (const auto& segment : pair.projection.mortar_segments(pair.slave)) {
    const double middle = pair.slave.point_at(0.5 * (segment.s_begin + segment.s_end)).x();
    EXPECT_EQ(segment.covered, std::abs(middle) < 0.5) << "segment around x = " << middle;
  }
}

// Concentric arcs, non-matching: the master r = 2 (θ ∈ (0, π/2), 5 cells), the slave r = 2.05
// (θ ∈ (0.1, 1.4), 3 cells). Φ(x) = 2 x/|x|, the gap 0.05, and the breakpoints lie on the rays
// through the master's vertices.
TEST(ContactPairGeometry, ConcentricArcsProjectAlongTheRadius) {
  using std::numbers::pi;
  auto master_mesh = hpcontact::testing::annulus_sector_mesh(1.0, 2.0, 0.0, pi / 2, 2, 5);
  mesh::assign_boundary_part(master_mesh, mesh::BoundaryPart::contact, [](const Point& p) { return p.norm() > 1.99; });
  auto slave_mesh = hpcontact::testing::annulus_sector_mesh(2.05, 3.0, 0.1, 1.4, 2, 3);
  mesh::assign_boundary_part(slave_mesh, mesh::BoundaryPart::contact, [](const Point& p) { return p.norm() < 2.06; });
  const mesh::ContactBoundary master(master_mesh), slave(slave_mesh);
  ASSERT_TRUE(master.is_curved() && slave.is_curved());
  const mesh::MasterProjection projection(master);
  for (int k = 0; k <= 20; ++k) {
    const double s = slave.length() * k / 20;
    const Point x = slave.point_at(s);
    const auto phi = projection.project(x);
    EXPECT_NEAR((phi.point - 2.0 * x.normalized()).norm(), 0.0, 1e-13) << "s = " << s;
    EXPECT_TRUE(phi.covered);
    EXPECT_NEAR(projection.gap(slave, s), 0.05, 1e-13);
  }
  const auto beyond = projection.project(hpcontact::testing::on_circle(2.5, -0.2));
  EXPECT_FALSE(beyond.covered);
  EXPECT_NEAR((beyond.point - Point(2.0, 0.0)).norm(), 0.0, 1e-13);

  const auto breakpoints = projection.slave_breakpoints(slave);
  ASSERT_EQ(breakpoints.size(), 4u);
  std::vector<double> angles;
  for (double s : breakpoints) {
    const Point x = slave.point_at(s);
    angles.push_back(std::atan2(x.y(), x.x()));
  }
  std::sort(angles.begin(), angles.end());
  for (int k = 1; k <= 4; ++k) EXPECT_NEAR(angles[k - 1], pi / 2 * k / 5, 1e-12);
  EXPECT_EQ(projection.mortar_segments(slave).size(), 7u);
}

// A V-shaped master seen from above: points over the valley are equally near both flanks, and Φ
// jumps from one to the other inside the slave's edge. Refused with the place named.
TEST(ContactPairGeometry, AJumpOfTheClosestPointIsRefused) {
  const std::vector<Point> vertices{{-1.0, -2.0}, {0.0, -2.0}, {1.0, -2.0}, {-1.0, 0.0}, {0.0, -0.5}, {1.0, 0.0}};
  mesh::Mesh valley(vertices, {{0, 1, 4, 3}, {1, 2, 5, 4}}, "valley");
  mesh::assign_boundary_part(valley, mesh::BoundaryPart::contact, [](const Point& p) { return p.y() > -1.0; });
  const auto slave_mesh = body({-0.5, 0.5, 0.2, 1.0}, 1, 1, [](const Point& p) { return p.y() < 0.2 + 1e-12; });
  const mesh::ContactBoundary master(valley), slave(slave_mesh);
  const mesh::MasterProjection projection(master);
  const auto message = hpcontact::testing::message_of([&] { projection.mortar_segments(slave); });
  EXPECT_NE(message.find("jumps near the slave point"), std::string::npos) << message;
  EXPECT_NE(message.find("concave master"), std::string::npos) << message;
}
