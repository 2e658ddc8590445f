// Mesh: rectangle topology, boundary parts, perturbation, validity checks, cell maps and
// point location.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "mesh/cell_map.hpp"
#include "mesh/point_grading.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "postprocess/point_locator.hpp"

using namespace hpcontact;
using mesh::BoundaryPart;

namespace {
double part_length(const mesh::Mesh& m, BoundaryPart part) {
  double length = 0.0;
  for (int e : m.boundary_edges())
    if (m.edge_part(e) == part) length += m.edge_length(e);
  return length;
}
}  // namespace

TEST(RectangleMesh, CountsAndTopology) {
  const auto m = mesh::make_rectangle_mesh({0.0, 3.0, 0.0, 2.0}, 3, 2);
  EXPECT_EQ(m.n_vertices(), 12);
  EXPECT_EQ(m.n_cells(), 6);
  EXPECT_EQ(m.n_edges(), 3 * 3 + 4 * 2);
  EXPECT_EQ(m.boundary_edges().size(), 10u);
  int interior = 0;
  for (int e = 0; e < m.n_edges(); ++e) interior += m.is_boundary_edge(e) ? 0 : 1;
  EXPECT_EQ(interior, 7);
  EXPECT_DOUBLE_EQ(m.longest_edge(), 1.0);
}

TEST(RectangleMesh, OutwardNormalsAndLabels) {
  const auto m = mesh::make_rectangle_mesh({}, 2, 2);
  for (int e : m.boundary_edges()) {
    const auto mid = m.edge_midpoint(e), n = m.boundary_normal(e, 0.0);
    // On the square (-1,1)², the outward normal points along the midpoint's largest coordinate.
    EXPECT_NEAR(n.dot(mid), std::max(std::abs(mid.x()), std::abs(mid.y())), 1e-14);
    if (m.edge_label(e) == "bottom") {
      EXPECT_DOUBLE_EQ(n.y(), -1.0);
    }
    if (m.edge_label(e) == "left") {
      EXPECT_DOUBLE_EQ(n.x(), -1.0);
    }
  }
}

TEST(PaperSquare, BoundaryPartsAsInSection7) {
  const auto m = mesh::make_paper_square_mesh(8);
  EXPECT_NEAR(part_length(m, BoundaryPart::contact), 2.0, 1e-14);
  EXPECT_NEAR(part_length(m, BoundaryPart::dirichlet), 3.0, 1e-14);
  EXPECT_NEAR(part_length(m, BoundaryPart::neumann), 3.0, 1e-14);
  EXPECT_THROW(mesh::make_paper_square_mesh(7), InputError);
}

TEST(Mesh, ClockwiseOrDegenerateCellsAreRejected) {
  std::vector<mesh::Point> v{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_NO_THROW(mesh::Mesh(v, {{0, 1, 2, 3}}));
  EXPECT_THROW(mesh::Mesh(v, {{0, 3, 2, 1}}), InputError);
  std::vector<mesh::Point> collapsed{{0, 0}, {1, 0}, {2, 0}, {0, 1}};
  EXPECT_THROW(mesh::Mesh(collapsed, {{0, 1, 2, 3}}), InputError);
  EXPECT_THROW(mesh::Mesh(v, {{0, 1, 2, 7}}), InputError);
}

TEST(Mesh, PerturbationKeepsBoundaryAndValidity) {
  auto m = mesh::make_paper_square_mesh(8);
  const auto before = m.vertices();
  mesh::perturb_interior_vertices(m, 0.2, 42);
  int moved = 0;
  for (int v = 0; v < m.n_vertices(); ++v) {
    const bool boundary =
        std::abs(std::abs(before[v].x()) - 1) < 1e-14 || std::abs(std::abs(before[v].y()) - 1) < 1e-14;
    if (boundary) {
      EXPECT_EQ(m.vertex(v), before[v]);
    }
    if ((m.vertex(v) - before[v]).norm() > 1e-3) ++moved;
  }
  EXPECT_GT(moved, 40);
  EXPECT_THROW(mesh::perturb_interior_vertices(m, 0.3, 1), InputError);
}

TEST(CellMap, InverseRoundTripAndLocator) {
  auto m = mesh::make_paper_square_mesh(6);
  mesh::perturb_interior_vertices(m, 0.2, 7);
  const postprocess::PointLocator locator(m);
  for (int c = 0; c < m.n_cells(); ++c) {
    const mesh::CellMap map(m, c);
    const mesh::Point x = map.map(0.31, -0.77);
    const auto ref = map.inverse(x);
    ASSERT_TRUE(ref.has_value());
    EXPECT_NEAR(ref->x(), 0.31, 1e-12);
    EXPECT_NEAR(ref->y(), -0.77, 1e-12);
    const auto found = locator.locate(x);
    ASSERT_TRUE(found.has_value());
    EXPECT_EQ(found->cell, c);
  }
  EXPECT_FALSE(locator.locate({1.5, 0.0}).has_value());
  EXPECT_TRUE(locator.locate({1.0, 1.0}).has_value());
}

// Geometric grading towards points (the hp meshes of the work–precision study): the point becomes
// a node, the cells next to it shrink by the ratio per layer, and bad requests are refused.
TEST(GradedNodes, ShrinkGeometricallyTowardsEachPoint) {
  const double ratio = 0.2;
  const int layers = 4;
  const auto nodes = mesh::graded_nodes(-1.0, 1.0, 8, {0.59, 1.0}, ratio, layers, "test");
  // 8 cells, +2 layers sets at the interior point, +1 at the end point x = 1.
  ASSERT_EQ(nodes.size(), 9u + 3 * layers);
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i) EXPECT_LT(nodes[i], nodes[i + 1]);
  EXPECT_EQ(nodes.front(), -1.0);
  EXPECT_EQ(nodes.back(), 1.0);
  const auto at = std::find(nodes.begin(), nodes.end(), 0.59);
  ASSERT_NE(at, nodes.end());
  const auto i = static_cast<std::size_t>(at - nodes.begin());
  // The snapped node's neighbours were 0.25 and 0.75; the layers sit at distances
  // (neighbour distance) · ratio^k, k = 1..layers, on both sides.
  for (int k = 1; k <= layers; ++k) {
    EXPECT_NEAR(nodes[i] - nodes[i - k], 0.34 * std::pow(ratio, layers + 1 - k), 1e-14) << k;
    EXPECT_NEAR(nodes[i + k] - nodes[i], 0.16 * std::pow(ratio, layers + 1 - k), 1e-14) << k;
  }
  EXPECT_NEAR(nodes[i] - nodes[i - layers - 1], 0.34, 1e-14);
  EXPECT_NEAR(nodes.back() - nodes[nodes.size() - 2], 0.25 * std::pow(ratio, layers), 1e-14);
  EXPECT_THROW(mesh::graded_nodes(-1.0, 1.0, 8, {1.5}, ratio, layers, "test"), InputError);
  EXPECT_THROW(mesh::graded_nodes(-1.0, 1.0, 8, {0.01, 0.02}, ratio, layers, "test"), InputError);
  EXPECT_THROW(mesh::graded_nodes(-1.0, 1.0, 8, {0.0}, 1.5, layers, "test"), InputError);
}

namespace {
double cell_area(const mesh::Mesh& m, int c) {
  double area = 0.0;  // shoelace
  for (int k = 0; k < 4; ++k) {
    const auto &a = m.vertex(m.cell(c)[k]), &b = m.vertex(m.cell(c)[(k + 1) % 4]);
    area += 0.5 * (a.x() * b.y() - b.x() * a.y());
  }
  return area;
}
}  // namespace

// Local geometric refinement towards vertices: on an edge (two cells), at a corner (one) and
// inside (four). The result must tile the same square without hanging nodes (a hanging node would
// leave an interior edge with one cell, lengthening the boundary), keep the boundary labels, and
// shrink the cells at each centre by ratio^layers.
TEST(PointGrading, StarsBecomeConformingGeometricLayers) {
  const auto coarse = mesh::make_rectangle_mesh({}, 4, 4);  // h = 0.5
  const std::vector<mesh::Point> points{{0.0, -1.0}, {1.0, 1.0}, {0.0, 0.0}};
  std::vector<int> centres;
  for (const auto& point : points) centres.push_back(mesh::vertex_at(coarse, point, "test"));
  const double ratio = 0.2;
  for (int layers : {0, 1, 5}) {
    const auto graded = mesh::grade_towards_vertices(coarse, centres, ratio, layers, "test");
    // 7 star cells, each replaced by 2 trapezoids per layer and its scaled copy.
    EXPECT_EQ(graded.n_cells(), 16 - 7 + 7 * (2 * layers + 1)) << layers;
    double area = 0.0, boundary = 0.0;
    for (int c = 0; c < graded.n_cells(); ++c) {
      EXPECT_GT(cell_area(graded, c), 0.0);
      area += cell_area(graded, c);
    }
    EXPECT_NEAR(area, 4.0, 1e-13);
    for (int e : graded.boundary_edges()) {
      boundary += graded.edge_length(e);
      const auto mid = graded.edge_midpoint(e);
      const std::string expected = std::abs(mid.y() + 1) < 1e-12   ? "bottom"
                                   : std::abs(mid.x() - 1) < 1e-12 ? "right"
                                   : std::abs(mid.y() - 1) < 1e-12 ? "top"
                                                                   : "left";
      EXPECT_EQ(graded.edge_label(e), expected) << mid.transpose();
    }
    EXPECT_NEAR(boundary, 8.0, 1e-13) << "a hanging node or a gap";
    for (std::size_t k = 0; k < points.size(); ++k) {
      double shortest = INFINITY;
      for (int e = 0; e < graded.n_edges(); ++e)
        for (int v : graded.edge(e))
          if (v == centres[k]) shortest = std::min(shortest, graded.edge_length(e));
      EXPECT_NEAR(shortest, 0.5 * std::pow(ratio, layers), 1e-14) << k;  // input vertex indices are kept
    }
  }
}

TEST(PointGrading, OverlappingStarsNonVerticesAndTooDeepLayersAreRefused) {
  const auto coarse = mesh::make_rectangle_mesh({}, 4, 4);
  const int a = mesh::vertex_at(coarse, {0.0, -1.0}, "test"), b = mesh::vertex_at(coarse, {0.5, -1.0}, "test");
  EXPECT_THROW(mesh::grade_towards_vertices(coarse, {a, b}, 0.2, 3, "test"), InputError);  // neighbours share a cell
  EXPECT_THROW(mesh::vertex_at(coarse, {0.1, -1.0}, "test"), InputError);
  EXPECT_THROW(mesh::grade_towards_vertices(coarse, {a}, 1.0, 3, "test"), InputError);
  EXPECT_NO_THROW(mesh::grade_towards_vertices(coarse, {a}, 0.2, 12, "test"));
  EXPECT_THROW(mesh::grade_towards_vertices(coarse, {a}, 0.2, 14, "test"), InputError);  // cells of 4e-11: round-off
}
