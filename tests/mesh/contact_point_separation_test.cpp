// separate_contact_points: points of Γ_C one edge apart or inside edges become vertices with
// disjoint stars, by cuts of the cells on Γ_C only; the mesh still tiles the domain, without
// hanging nodes, with its boundary labels and parts.
#include "mesh/contact_point_separation.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "mesh/point_grading.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "mesh/refine.hpp"

using namespace hpcontact;

namespace {

double cell_area(const mesh::Mesh& m, int c) {
  double area = 0.0;  // shoelace
  const auto cell = m.cell(c);
  for (std::size_t k = 0; k < cell.size(); ++k) {
    const auto &a = m.vertex(cell[k]), &b = m.vertex(cell[(k + 1) % cell.size()]);
    area += 0.5 * (a.x() * b.y() - b.x() * a.y());
  }
  return area;
}

double part_length(const mesh::Mesh& m, mesh::BoundaryPart part) {
  double length = 0.0;
  for (int e : m.boundary_edges())
    if (m.edge_part(e) == part) length += m.edge_length(e);
  return length;
}

// The cut mesh tiles the paper square (area 4, boundary 8: a hanging node would leave an interior
// edge with one cell), keeps Γ_C's length, and the points (arc lengths s = x + 1 on y = −1) are
// vertices that grade_towards_vertices accepts as centres (it refuses stars that share a cell).
void expect_separated(const mesh::Mesh& input, const mesh::SeparatedMesh& cut, const std::vector<double>& points) {
  const auto& out = cut.mesh;
  ASSERT_EQ(cut.parents.size(), static_cast<std::size_t>(out.n_cells()));
  double area = 0.0, boundary = 0.0;
  for (int c = 0; c < out.n_cells(); ++c) {
    EXPECT_GT(cell_area(out, c), 0.0);
    area += cell_area(out, c);
  }
  for (int e : out.boundary_edges()) boundary += out.edge_length(e);
  EXPECT_NEAR(area, 4.0, 1e-13);
  EXPECT_NEAR(boundary, 8.0, 1e-13);
  EXPECT_NEAR(part_length(out, mesh::BoundaryPart::contact), part_length(input, mesh::BoundaryPart::contact), 1e-13);
  EXPECT_NEAR(part_length(out, mesh::BoundaryPart::dirichlet), part_length(input, mesh::BoundaryPart::dirichlet),
              1e-13);
  std::vector<int> centres;
  for (double s : points) centres.push_back(mesh::vertex_at(out, {s - 1.0, -1.0}, "test"));
  EXPECT_NO_THROW(mesh::grade_towards_vertices(out, centres, 0.2, 3, "test"));
}

}  // namespace

// Points at every vertex of Γ_C (h/H = 1): each of the 4 cells on Γ_C becomes 3 triangles, the
// other 12 cells stay; without the cuts the stars of neighbouring points share a cell.
TEST(ContactPointSeparation, NeighbouringVerticesOfGammaC) {
  const auto square = mesh::make_paper_square_mesh(4);
  const std::vector<double> points{0.0, 0.5, 1.0, 1.5, 2.0};
  std::vector<int> centres;
  for (double s : points) centres.push_back(mesh::vertex_at(square, {s - 1.0, -1.0}, "test"));
  EXPECT_THROW(mesh::grade_towards_vertices(square, centres, 0.2, 3, "test"), InputError);
  const auto cut = mesh::separate_contact_points(square, points);
  ASSERT_TRUE(cut.has_value());
  EXPECT_EQ(cut->mesh.n_cells(), 12 + 4 * 3);
  for (int c = 0; c < 12; ++c) EXPECT_EQ(cut->mesh.cells()[c], square.cells()[cut->parents[c]]);  // kept first
  expect_separated(square, *cut, points);
}

// Points inside edges (s = 0.25 and 1.75) and at a vertex (s = 1): only the two cells with a point
// inside their Γ_C edge are cut; a triangle mesh is cut into two triangles per such cell.
TEST(ContactPointSeparation, PointsInsideEdgesOnQuadrilateralsAndTriangles) {
  const std::vector<double> points{0.25, 1.0, 1.75};
  const auto square = mesh::make_paper_square_mesh(4);
  const auto cut = mesh::separate_contact_points(square, points);
  ASSERT_TRUE(cut.has_value());
  EXPECT_EQ(cut->mesh.n_cells(), 14 + 2 * 3);
  expect_separated(square, *cut, points);

  const auto triangles = mesh::split_into_triangles(square, nullptr, "test");
  const auto cut_triangles = mesh::separate_contact_points(triangles, points);
  ASSERT_TRUE(cut_triangles.has_value());
  EXPECT_EQ(cut_triangles->mesh.n_cells(), 32 + 2);
  expect_separated(triangles, *cut_triangles, points);
}

// Nothing to cut where every point is a vertex with its own star.
TEST(ContactPointSeparation, NoCutsWhereNoneAreNeeded) {
  const auto square = mesh::make_paper_square_mesh(4);
  const auto cut = mesh::separate_contact_points(square, {0.0, 1.0, 2.0});
  ASSERT_TRUE(cut.has_value());
  EXPECT_EQ(cut->mesh.n_cells(), square.n_cells());
  EXPECT_EQ(cut->mesh.n_vertices(), square.n_vertices());
}
