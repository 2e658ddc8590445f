// Curved boundaries: edge curves (Chebyshev interpolation), blended cell maps that reproduce a
// curved domain exactly and nest under refinement, curves from a .geo's exact geometry and from a
// high-order mesh's nodes, arc length and normals along a curved Γ_C, exponential convergence on
// a curved domain where the polygonal one stalls, and contact problems on a curved Γ_C.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <sstream>

#include "basis/quadrature.hpp"
#include "core/byte_buffer.hpp"
#include "core/error.hpp"
#include "driver/scene_run.hpp"
#include "mesh/blended_geometry.hpp"
#include "mesh/cell_map.hpp"
#include "mesh/contact_boundary.hpp"
#include "mesh/edge_curve.hpp"
#include "mesh/gmsh_reader.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "mesh/refine.hpp"
#include "scene/scene_mesh.hpp"
#include "scene/scene_reader.hpp"
#include "studies/convergence_study.hpp"
#include "support/annulus_sector.hpp"
#include "support/csv_file.hpp"
#include "support/curved_convergence_check.hpp"
#include "support/scratch.hpp"

using namespace hpcontact;
using mesh::Point;
using std::numbers::pi;

namespace {

const std::string kCurved = std::string(HPCONTACT_SOURCE_DIR) + "/studies/curved/";

using hpcontact::testing::on_circle;

// The quarter annulus 1 < r < 2, 0 < θ < π/2 with n_r × n_θ cells.
mesh::Mesh quarter_annulus(int n_r, int n_theta) {
  return hpcontact::testing::annulus_sector_mesh(1.0, 2.0, 0.0, pi / 2, n_r, n_theta);
}

double area(const mesh::Mesh& mesh) {
  const auto& rule = basis::gauss_legendre(20);
  double sum = 0.0;
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const mesh::CellMap map(mesh, c);
    for (std::size_t a = 0; a < rule.points.size(); ++a)
      for (std::size_t b = 0; b < rule.points.size(); ++b)
        sum += rule.weights[a] * rule.weights[b] * map.jacobian(rule.points[a], rule.points[b]).determinant();
  }
  return sum;
}

std::map<std::string, double> length_by_label(const mesh::Mesh& mesh) {
  std::map<std::string, double> out;
  for (int e : mesh.boundary_edges()) out[mesh.edge_label(e)] += mesh.edge_length(e);
  return out;
}

}  // namespace

TEST(EdgeCurve, InterpolatesAnArcToRoundOffAndDifferentiatesIt) {
  const auto arc = [](double t) { return on_circle(2.0, 0.5 * (t + 1.0)); };  // 1 rad
  const auto curve = mesh::EdgeCurve::interpolate(arc, 16);
  for (double t = -1.0; t <= 1.0; t += 0.0173) {
    EXPECT_LT((curve.point(t) - arc(t)).norm(), 2e-15) << t;
    const Point slope = 0.5 * 2.0 * Point(-std::sin(0.5 * (t + 1.0)), std::cos(0.5 * (t + 1.0)));
    EXPECT_LT((curve.derivative(t) - slope).norm(), 1e-13) << t;
  }
  EXPECT_GT(curve.relative_deviation_from_chord(), 0.05);
  // Degree 4 is far from round-off: the interpolation error is what the test above measures.
  EXPECT_GT((mesh::EdgeCurve::interpolate(arc, 4).point(0.77) - arc(0.77)).norm(), 1e-7);
}

TEST(EdgeCurve, ThroughEquispacedNodesReproducesPolynomials) {
  const auto parabola = [](double t) { return Point(t, 0.3 * t * t - 0.1 * t * t * t); };
  std::vector<Point> nodes;
  for (int k = 0; k <= 3; ++k) nodes.push_back(parabola(-1.0 + 2.0 * k / 3));
  const auto curve = mesh::EdgeCurve::through_equispaced(nodes);
  for (double t : {-0.9, -0.31, 0.0, 0.42, 0.99}) EXPECT_LT((curve.point(t) - parabola(t)).norm(), 1e-15);
  const auto straight = mesh::EdgeCurve::through_equispaced({Point(0, 0), Point(0.5, 1), Point(1, 2)});
  EXPECT_LT(straight.relative_deviation_from_chord(), 1e-15);
}

// The number of distinct curves the cells' maps follow (children and neighbours share them).
std::size_t distinct_side_curves(const mesh::Mesh& mesh) {
  std::set<const mesh::EdgeCurve*> curves;
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (const auto* geometry = mesh.cell_geometry(c))
      for (int side = 0; side < 4; ++side)
        if (geometry->side_curve(side)) curves.insert(geometry->side_curve(side));
  return curves.size();
}

// A mesh sent between ranks as bytes (a rank builds T_h and sends it, mesh/mesh_bytes.cpp) is the
// sender's to the bit: curved and refined cells (children's maps, sharing their curves as the
// sender's do), labels, boundary parts, and a part's global indices; packing the received mesh
// gives the same bytes; cut bytes are refused.
TEST(BlendedGeometry, MeshSentAsBytesIsTheSameToTheBit) {
  auto whole = mesh::refine_uniformly(mesh::refine_uniformly(quarter_annulus(2, 3)));
  whole.set_edge_label(whole.boundary_edges().front(), "inner");
  mesh::assign_boundary_part(whole, mesh::BoundaryPart::contact, [](const Point& x) { return x.norm() < 1.5; });
  std::vector<int> cells;
  for (int c = 0; c < whole.n_cells(); c += 3) cells.push_back(c);
  const auto part = whole.extract(cells);
  // (Gmsh's curved triangles, refined: their maps also carry the quotient curves φ)
  const auto triangles = mesh::refine_uniformly(
      mesh::read_gmsh_mesh(kCurved + "annulus.geo", {std::nullopt, mesh::GeneratedCells::triangles}));
  ASSERT_EQ(triangles.cell_type(0), mesh::CellType::triangle);
  for (const mesh::Mesh* sent : {static_cast<const mesh::Mesh*>(&whole), &part, &triangles}) {
    ByteWriter out;
    sent->pack(out);
    const std::vector<char> bytes = out.take();
    ByteReader in(bytes);
    const mesh::Mesh received = mesh::Mesh::unpack(in);
    EXPECT_TRUE(in.at_end());
    ByteWriter again;
    received.pack(again);
    EXPECT_EQ(again.take(), bytes);
    ASSERT_EQ(received.n_cells(), sent->n_cells());
    ASSERT_EQ(received.n_edges(), sent->n_edges());
    EXPECT_EQ(received.is_part(), sent->is_part());
    EXPECT_TRUE(received.has_curved_cells());
    EXPECT_EQ(distinct_side_curves(received), distinct_side_curves(*sent));
    EXPECT_LT(distinct_side_curves(received), static_cast<std::size_t>(received.n_cells()));
    for (int c = 0; c < sent->n_cells(); ++c) {
      EXPECT_EQ(received.global_cell(c), sent->global_cell(c));
      const mesh::CellMap a(*sent, c), b(received, c);
      for (double xi : {-1.0, -0.3, 0.6})
        for (double eta : {-0.8, 0.1, 1.0}) {
          EXPECT_EQ(b.map(xi, eta), a.map(xi, eta)) << "cell " << c;
          EXPECT_EQ(b.jacobian(xi, eta), a.jacobian(xi, eta)) << "cell " << c;
        }
    }
    for (int e = 0; e < sent->n_edges(); ++e) {
      EXPECT_EQ(received.edge_label(e), sent->edge_label(e));
      EXPECT_EQ(received.edge_part(e), sent->edge_part(e));
      EXPECT_EQ(received.edge_cells(e), sent->edge_cells(e));
      EXPECT_EQ(received.global_edge(e), sent->global_edge(e));
    }
    const std::vector<char> cut(bytes.begin(), bytes.end() - 3);
    ByteReader short_in(cut);
    EXPECT_THROW(mesh::Mesh::unpack(short_in), std::logic_error);
  }
}

TEST(BlendedGeometry, CoversTheCurvedDomainExactlyAndNestsUnderRefinement) {
  const auto coarse = quarter_annulus(2, 3);
  EXPECT_TRUE(coarse.has_curved_cells());
  EXPECT_NEAR(area(coarse), 3 * pi / 4, 1e-14);
  const auto fine = mesh::refine_uniformly(coarse);
  EXPECT_NEAR(area(fine), 3 * pi / 4, 1e-14);
  // A child's map is its parent's on a quarter of the reference square.
  for (int c = 0; c < coarse.n_cells(); ++c) {
    const mesh::CellMap parent(coarse, c), child(fine, 4 * c + 2);  // the child at ξ, η > 0
    for (double xi : {-1.0, -0.3, 0.6})
      for (double eta : {-0.8, 0.1, 1.0})
        EXPECT_LT((child.map(xi, eta) - parent.map(0.5 * (xi + 1), 0.5 * (eta + 1))).norm(), 4e-15);
  }
  // Jacobian against central differences, and the inverse map.
  const mesh::CellMap map(fine, 5);
  const double d = 1e-6;
  for (double xi : {-0.7, 0.2})
    for (double eta : {-0.4, 0.9}) {
      Eigen::Matrix2d numeric;
      numeric.col(0) = (map.map(xi + d, eta) - map.map(xi - d, eta)) / (2 * d);
      numeric.col(1) = (map.map(xi, eta + d) - map.map(xi, eta - d)) / (2 * d);
      EXPECT_LT((numeric - map.jacobian(xi, eta)).norm(), 1e-8);
      const auto back = map.inverse(map.map(xi, eta));
      ASSERT_TRUE(back.has_value());
      EXPECT_LT((*back - Eigen::Vector2d(xi, eta)).norm(), 1e-13);
    }
  // Arc lengths and normals of the boundary.
  double outer = 0.0;
  for (int e : fine.boundary_edges())
    if (std::abs(fine.vertex(fine.edge(e)[0]).norm() - 2.0) < 1e-12 &&
        std::abs(fine.vertex(fine.edge(e)[1]).norm() - 2.0) < 1e-12) {
      outer += fine.edge_length(e);
      for (double t : {-0.5, 0.25}) {
        const Point x = fine.edge_point(e, t);
        EXPECT_NEAR(x.norm(), 2.0, 1e-15);
        const int local = fine.local_edge_of(e, 0);
        const Eigen::Vector2d ref = mesh::local_edge_point(fine.cell_type(fine.edge_cells(e)[0]), local, t);
        EXPECT_LT(
            (fine.boundary_normal(e, t) - mesh::CellMap(fine, fine.edge_cells(e)[0]).map(ref.x(), ref.y()) / 2).norm(),
            1e-14);
      }
    }
  EXPECT_NEAR(outer, pi, 1e-14);
  EXPECT_THROW(
      {
        auto moved = fine;
        moved.move_vertices(fine.vertices(), "moved");
      },
      InputError);
}

TEST(BlendedGeometry, ACurveThatMissesItsVerticesOrFoldsTheCellIsRefused) {
  auto mesh = quarter_annulus(1, 1);
  const int e = mesh.boundary_edges().front();
  const Point a = mesh.vertex(mesh.edge(e)[0]), b = mesh.vertex(mesh.edge(e)[1]);
  const auto shifted = std::make_shared<mesh::EdgeCurve>(mesh::EdgeCurve::interpolate(
      [&](double t) { return Point(0.5 * (1 - t) * a + 0.5 * (1 + t) * b + Point(0.1, 0)); }, 2));
  EXPECT_THROW(mesh.set_edge_curve(e, shifted, "test"), InputError);
  // A side bulging across the whole cell.
  const Point normal = Point((b - a).y(), -(b - a).x());
  const auto bulge = std::make_shared<mesh::EdgeCurve>(mesh::EdgeCurve::interpolate(
      [&](double t) { return Point(0.5 * (1 - t) * a + 0.5 * (1 + t) * b + 3.0 * (1 - t * t) * normal); }, 2));
  const auto inward = std::make_shared<mesh::EdgeCurve>(mesh::EdgeCurve::interpolate(
      [&](double t) { return Point(0.5 * (1 - t) * a + 0.5 * (1 + t) * b - 3.0 * (1 - t * t) * normal); }, 2));
  bool refused = false;
  for (const auto& curve : {bulge, inward}) try {
      auto copy = quarter_annulus(1, 1);
      copy.set_edge_curve(e, curve, "test");
    } catch (const InputError& error) {
      refused = true;
      EXPECT_THAT(error.what(), ::testing::HasSubstr("folds over with its curved side"));
    }
  EXPECT_TRUE(refused);
}

TEST(GmshCurves, GeometryFileArcsAreFollowedExactly) {
  const auto mesh = mesh::read_gmsh_mesh(kCurved + "annulus.geo");
  EXPECT_TRUE(mesh.has_curved_cells());
  EXPECT_NEAR(area(mesh), 3 * pi / 4, 1e-13);
  const auto lengths = length_by_label(mesh);
  EXPECT_NEAR(lengths.at("outer"), pi, 1e-13);
  EXPECT_NEAR(lengths.at("inner"), pi / 2, 1e-13);
  EXPECT_NEAR(lengths.at("bottom"), 1.0, 1e-14);
  EXPECT_NEAR(lengths.at("left"), 1.0, 1e-14);
  // Γ_C on the outer arc: arc length is the angle times 2, normals are radial.
  auto contact_mesh = mesh::refine_uniformly(mesh);
  for (int e : contact_mesh.boundary_edges())
    if (contact_mesh.edge_label(e) == "outer") contact_mesh.set_edge_part(e, mesh::BoundaryPart::contact);
  const mesh::ContactBoundary contact(contact_mesh);
  EXPECT_TRUE(contact.is_curved());
  EXPECT_NEAR(contact.length(), pi, 1e-13);
  for (double s = 0.0; s <= pi; s += pi / 97) {
    const Point x = contact.point_at(s);
    EXPECT_NEAR(x.norm(), 2.0, 1e-14);
    const double angle = std::atan2(x.y(), x.x());
    EXPECT_NEAR(std::min(std::abs(angle - s / 2), std::abs(angle - (pi / 2 - s / 2))), 0.0, 1e-13) << s;
    EXPECT_LT((contact.normal_at(s) - x / 2).norm(), 1e-13);
    // Differentiating the degree-16 interpolant costs a factor ~n² of round-off.
    EXPECT_NEAR(contact.tangent_at(s).dot(x), 0.0, 5e-13);
  }
}

TEST(GmshCurves, HighOrderNodesGiveCurvedEdgesAndPolygonalDropsThem) {
  // annulus_order2.msh: annulus.geo meshed by gmsh -2 -order 2 (9-node quadrilaterals).
  auto mesh = mesh::read_gmsh_mesh(std::string(HPCONTACT_TEST_DATA) + "/annulus_order2.msh");
  ASSERT_TRUE(mesh.has_curved_cells());
  const double curved_error = std::abs(area(mesh) - 3 * pi / 4);
  mesh.straighten();
  EXPECT_FALSE(mesh.has_curved_cells());
  const double polygonal_error = std::abs(area(mesh) - 3 * pi / 4);
  EXPECT_LT(curved_error, 1e-6);
  EXPECT_GT(polygonal_error, 1e3 * curved_error);
  // A straight 9-node quadrilateral stays a straight cell.
  EXPECT_FALSE(mesh::read_gmsh_mesh(std::string(HPCONTACT_TEST_DATA) + "/square_order2.msh").has_curved_cells());
}

TEST(CurvedConvergence, ExponentialInPWhereThePolygonalDomainStalls) {
  hpcontact::testing::expect_curved_convergence(kCurved + "convergence.toml", 0.1);
}

TEST(CurvedScenes, SignoriniOnACurvedContactEdgeMeetsKkt) {
  const auto dir = hpcontact::testing::scratch("curved_signorini");
  const auto scene =
      scene::read_scene(kCurved + "annulus.toml", {{"run.effects", std::vector<std::string>{"signorini"}, "test"}});
  driver::SceneRunOptions options;
  options.out = dir;
  const driver::RunResult summary = driver::run_scene(scene, options);
  EXPECT_LT(summary.contact("signorini").solver.kkt_residual, 1e-12);
  const double contact_length = summary.contact("signorini").contact_set_length;
  EXPECT_GT(contact_length, 0.5);
  EXPECT_LT(contact_length, 2.5);
  // The samples lie on the outer arc. u ≥ g holds in the mean against the multipliers (and at the
  // constraint points of λ), so between them u may dip below g by the discretization error.
  double deepest = 0.0;
  for (const auto& row : hpcontact::testing::read_csv(dir / "boundary_signorini.csv").numbers()) {
    ASSERT_EQ(row.size(), 7u);
    EXPECT_NEAR(std::hypot(row[0], row[4]), 2.0, 1e-13);
    deepest = std::min(deepest, row[1] - row[2]);
  }
  EXPECT_GT(deepest, -1e-3);
}

TEST(CurvedScenes, ElasticRingHasLamesUniformPressure) {
  const auto dir = hpcontact::testing::scratch("curved_ring");
  driver::SceneRunOptions options;
  options.out = dir;
  const auto result = driver::run_scene(scene::read_scene(kCurved + "ring.toml"), options);
  // λ, μ of E = 1, ν = 0.3; u_r = A r + B/r with u_r(1) = 0.01, u_r(2) = 0.002.
  const double lambda = 0.3 / (1.3 * 0.4), mu = 1 / 2.6, a = (2 * 0.002 - 0.01) / 3, b = 0.01 - a;
  const double pressure = -2 * (lambda + mu) * a + mu * b / 2;  // -σ_rr(2)
  int rows = 0;
  for (const auto& row : hpcontact::testing::read_csv(dir / "boundary_frictionless.csv").numbers()) {
    ++rows;
    EXPECT_NEAR(row[6], pressure, 1e-8 * pressure);
    EXPECT_NEAR(row[5], 0.0, 1e-12) << "gap";
    EXPECT_NEAR(row[4], 0.0, 1e-12) << "u_t: the ring expands radially";
    // The stress of u_h beside the arc: σ_nn = n·σ·n = −p too (measured 5e-8 of p at p = 6).
    const double nx = row[0] / 2, ny = row[1] / 2;
    EXPECT_NEAR(nx * nx * row[8] + 2 * nx * ny * row[11] + ny * ny * row[9], -pressure, 1e-6 * pressure);
  }
  EXPECT_GT(rows, 100);
  // The resultants: P = p·(π/2)·2 along the arc, no tangential force, and the traction −p n on the
  // quarter arc of radius 2 adds up to −2p (1, 1).
  const auto& contact = result.contacts.front();
  EXPECT_NEAR(*contact.total_force, pressure * pi, 1e-8 * pressure);
  EXPECT_NEAR(*contact.tangential_force, 0.0, 1e-12);
  EXPECT_NEAR(contact.contact_force->at(0), -2 * pressure, 1e-8 * pressure);
  EXPECT_NEAR(contact.contact_force->at(1), -2 * pressure, 1e-8 * pressure);
  ASSERT_EQ(contact.zones.size(), 1u);
  EXPECT_EQ(contact.zones[0].contact_force, contact.contact_force);
}

TEST(CurvedScenes, GeometryKeyAndWhatCurvedMeshesRefuse) {
  const auto polygonal = scene::build_scene_mesh(
      scene::read_scene(kCurved + "annulus.toml", {{"domain.geometry", std::string("polygonal"), "test"}}));
  EXPECT_FALSE(polygonal.has_curved_cells());
  EXPECT_LT(area(polygonal), 3 * pi / 4 - 1e-3);
  try {
    scene::build_scene_mesh(scene::read_scene(kCurved + "annulus.toml", {{"domain.perturb", 0.1, "test"}}));
    ADD_FAILURE() << "perturbing a curved mesh must be refused";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), ::testing::HasSubstr("key 'domain.perturb': not available on the curved mesh"));
  }
  EXPECT_THROW(scene::read_scene(kCurved + "annulus.toml", {{"domain.geometry", std::string("round"), "test"}}),
               InputError);
}

TEST(CurvedConvergence, StudyKeysOfTheSquareAndOfASceneDoNotMix) {
  const auto dir = hpcontact::testing::scratch("curved_study");
  std::filesystem::copy(kCurved + "annulus.toml", dir / "annulus.toml",
                        std::filesystem::copy_options::overwrite_existing);
  std::filesystem::copy(kCurved + "annulus.geo", dir / "annulus.geo",
                        std::filesystem::copy_options::overwrite_existing);
  const std::string solution = "[solution]\nu = \"x*y\"\nux = \"y\"\nuy = \"x\"\nf = \"0\"\n";
  const struct {
    std::string rest, expected;
  } cases[] = {
      {"[mesh]\nscene = \"annulus.toml\"\n[[runs]]\np = 2\nn = [4]\n", "runs[0].n"},
      {"[[runs]]\np = 2\nn = [4]\nrefinements = 1\n", "only with [mesh] scene"},
      {"[mesh]\nscene = \"annulus.toml\"\n[[runs]]\np = 2\nrefinements = 1\ngeometry = \"round\"\n",
       "\"curved\" or \"polygonal\""},
      {"[mesh]\nscene = \"annulus.toml\"\nperturb = 0.1\n[[runs]]\np = 2\nrefinements = 1\n", "mesh.perturb"},
      {"[mesh]\nscene = \"missing.toml\"\n[[runs]]\np = 2\nrefinements = 1\n", "an existing scene file"},
      {"[mesh]\nscene = \"annulus.toml\"\n[[runs]]\np = 2\nrefinements = 9\n", "runs[0].refinements"},
  };
  for (const auto& c : cases) {
    std::ofstream(dir / "study.toml") << solution << c.rest;
    try {
      studies::read_convergence_study((dir / "study.toml").string());
      ADD_FAILURE() << "accepted:\n" << c.rest;
    } catch (const InputError& error) {
      EXPECT_THAT(error.what(), ::testing::HasSubstr(c.expected)) << c.rest;
    }
  }
}
