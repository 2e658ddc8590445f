// AdaptiveMesh: red refinement stays conforming after its closure, 1-irregular, inherits labels and
// parts, maps new leaves to old ones, and refuses what it cannot refine.
#include "mesh/adaptive_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "mesh/cell_map.hpp"
#include "mesh/edge_curve.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "mesh/refine.hpp"

using namespace hpcontact;
using mesh::BoundaryPart;

namespace {

// The coarse 4 × 4 square (-1, 1)² with Γ_C the bottom, Γ_D the top.
mesh::Mesh labelled_square(bool triangles) {
  auto square = mesh::make_rectangle_mesh({}, 4, 4);
  if (triangles) square = mesh::split_into_triangles(square);
  for (const int e : square.boundary_edges()) {
    if (square.edge_label(e) == "bottom") square.set_edge_part(e, BoundaryPart::contact);
    if (square.edge_label(e) == "top") square.set_edge_part(e, BoundaryPart::dirichlet);
  }
  return square;
}

double part_length(const mesh::Mesh& m, BoundaryPart part) {
  double length = 0.0;
  for (const int e : m.boundary_edges())
    if (m.edge_part(e) == part) length += m.edge_length(e);
  return length;
}

double area(const mesh::Mesh& m) {
  double sum = 0.0;
  for (int c = 0; c < m.n_cells(); ++c) {
    const auto v = m.cell(c);
    for (std::size_t k = 0; k < v.size(); ++k) {
      const auto& a = m.vertex(v[k]);
      const auto& b = m.vertex(v[(k + 1) % v.size()]);
      sum += 0.5 * (a.x() * b.y() - a.y() * b.x());
    }
  }
  return sum;
}

// The leaf holding the point x, by the cell of the closed mesh around it.
int leaf_at(const mesh::AdaptiveMesh& adaptive, const mesh::Point& x) {
  std::vector<int> leaf_of_cell;
  const auto m = adaptive.conforming_mesh(&leaf_of_cell);
  for (int c = 0; c < m.n_cells(); ++c) {
    const mesh::CellMap map(m, c);
    const auto reference = map.inverse(x);
    if (reference && mesh::reference_contains(m.cell_type(c), *reference, 1e-12)) return leaf_of_cell[c];
  }
  return -1;
}

// Refines the leaf at `corner` `times` times and checks the closed mesh every time.
void refine_towards(bool triangles, const mesh::Point& corner, int times) {
  const auto coarse = labelled_square(triangles);
  mesh::AdaptiveMesh adaptive(coarse, "test square");
  for (int step = 0; step < times; ++step) {
    const int leaf = leaf_at(adaptive, corner + mesh::Point(1e-9, 1e-9));
    ASSERT_GE(leaf, 0);
    const int before = adaptive.n_leaves();
    const auto parent = adaptive.refine({leaf});
    ASSERT_EQ(static_cast<int>(parent.size()), adaptive.n_leaves());
    for (const int p : parent) ASSERT_TRUE(p >= 0 && p < before);
    std::vector<int> leaf_of_cell;
    const auto m = adaptive.conforming_mesh(&leaf_of_cell);
    // Conforming: no hanging node leaves an interior edge with one cell, which would count as
    // boundary; the parts keep their lengths and the cells tile the square.
    EXPECT_NEAR(part_length(m, BoundaryPart::contact), 2.0, 1e-12);
    EXPECT_NEAR(part_length(m, BoundaryPart::dirichlet), 2.0, 1e-12);
    EXPECT_NEAR(part_length(m, BoundaryPart::neumann), 4.0, 1e-12);
    EXPECT_NEAR(area(m), 4.0, 1e-12);
    // 1-irregular: cells sharing an edge lie in leaves at most one level apart.
    for (int e = 0; e < m.n_edges(); ++e)
      if (!m.is_boundary_edge(e)) {
        const auto& cells = m.edge_cells(e);
        EXPECT_LE(std::abs(adaptive.level(leaf_of_cell[cells[0]]) - adaptive.level(leaf_of_cell[cells[1]])), 1);
      }
  }
  // The leaf at the corner has been split `times` times: its cells are 2^-times of a coarse cell.
  EXPECT_EQ(adaptive.level(leaf_at(adaptive, corner + mesh::Point(1e-9, 1e-9))), times);
}

}  // namespace

TEST(AdaptiveMesh, QuadrilateralsStayConformingAndOneIrregularTowardsACorner) {
  refine_towards(false, {-1.0, -1.0}, 6);
  refine_towards(false, {0.5, -1.0}, 5);
}

TEST(AdaptiveMesh, TrianglesStayConformingAndOneIrregular) { refine_towards(true, {0.5, -1.0}, 5); }

TEST(AdaptiveMesh, UnmarkedMeshIsTheCoarseOneAndRefiningAllIsUniform) {
  const auto coarse = labelled_square(false);
  mesh::AdaptiveMesh adaptive(coarse, "test square");
  const auto same = adaptive.conforming_mesh();
  EXPECT_EQ(same.n_cells(), coarse.n_cells());
  std::vector<int> all(adaptive.n_leaves());
  for (int k = 0; k < adaptive.n_leaves(); ++k) all[k] = k;
  adaptive.refine(all);
  const auto fine = adaptive.conforming_mesh();
  EXPECT_EQ(fine.n_cells(), 4 * coarse.n_cells());
  EXPECT_FALSE(fine.has_triangles());
  EXPECT_DOUBLE_EQ(fine.longest_edge(), 0.5 * coarse.longest_edge());
}

TEST(AdaptiveMesh, OneSplitCellClosesItsNeighboursByTriangles) {
  const auto coarse = labelled_square(false);
  mesh::AdaptiveMesh adaptive(coarse, "test square");
  // An interior cell of the 4 × 4 mesh: its four edge neighbours each get one hanging side,
  // closed by three triangles.
  const int centre = leaf_at(adaptive, {-0.25, -0.25});
  adaptive.refine({centre});
  const auto m = adaptive.conforming_mesh();
  EXPECT_EQ(m.n_cells(), 16 - 1 + 4 + 4 * (3 - 1));
  int triangles = 0;
  for (int c = 0; c < m.n_cells(); ++c) triangles += m.cell_type(c) == mesh::CellType::triangle;
  EXPECT_EQ(triangles, 12);
}

TEST(AdaptiveMesh, RefusesCurvedCellsAndMarksThatAreNoLeaves) {
  const auto coarse = labelled_square(false);
  mesh::AdaptiveMesh adaptive(coarse, "test square");
  EXPECT_THROW(adaptive.refine({16}), InputError);
  EXPECT_THROW(adaptive.refine({-1}), InputError);
  auto curved = mesh::make_rectangle_mesh({}, 1, 1);
  const int bottom = curved.boundary_edges().front();
  const auto& ends = curved.edge(bottom);
  const mesh::Point a = curved.vertex(ends[0]), b = curved.vertex(ends[1]);
  const auto bulge = mesh::EdgeCurve::interpolate(
      [a, b](double t) -> mesh::Point {
        return 0.5 * (1 - t) * a + 0.5 * (1 + t) * b + mesh::Point(0, -0.1 * (1 - t * t));
      },
      4);
  curved.set_edge_curve(bottom, std::make_shared<mesh::EdgeCurve>(bulge), "test");
  EXPECT_THROW(mesh::AdaptiveMesh(curved, "curved square"), InputError);
}
