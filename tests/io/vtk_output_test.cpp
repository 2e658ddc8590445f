// The ParaView writers: VTK's Lagrange node order on both reference cells (every lattice point
// once, entities as expected), the VTU of a mixed mesh with random degrees (points shared by
// entity, so the count follows from vertices, edges and cells; a continuous field read back from
// the binary block equals the function at every point), the polyline VTP and the PVD collection.
// Readers of other programs (meshio, VTK) check the same files in tests/python/test_vtk_output.py.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <regex>
#include <set>

#include "io/line_samples_vtu.hpp"
#include "io/vtk_lagrange_nodes.hpp"
#include "io/vtk_xml_document.hpp"
#include "io/vtu_writer.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "mesh/refine.hpp"
#include "support/vtu_arrays.hpp"

using namespace hpcontact;
using hpcontact::testing::appended_array;

namespace {

int attribute(const std::string& file, const std::string& name) {
  std::smatch m;
  EXPECT_TRUE(std::regex_search(file, m, std::regex(name + "=\"(\\d+)\"")));
  return std::stoi(m[1]);
}

}  // namespace

TEST(VtkLagrangeNodes, EveryLatticePointOnceWithItsEntity) {
  for (auto type : {mesh::CellType::quadrilateral, mesh::CellType::triangle})
    for (int k = 1; k <= 9; ++k) {
      const auto lattice = io::vtk_lagrange_lattice(type, k);
      const std::set<std::array<int, 2>> distinct(lattice.begin(), lattice.end());
      const int expected = type == mesh::CellType::quadrilateral ? (k + 1) * (k + 1) : (k + 1) * (k + 2) / 2;
      ASSERT_EQ(static_cast<int>(lattice.size()), expected);
      ASSERT_EQ(distinct.size(), lattice.size());
      const int n_vertices = mesh::cell_vertex_count(type);
      std::map<int, std::set<int>> steps_of_edge;
      for (std::size_t n = 0; n < lattice.size(); ++n) {
        const auto [i, j] = lattice[n];
        ASSERT_TRUE(i >= 0 && j >= 0 && i <= k && j <= k && (type == mesh::CellType::quadrilateral || i + j <= k));
        const auto entity = io::lattice_entity(type, lattice[n], k);
        // VTK's order: vertices first, then edge nodes, then interior nodes.
        const auto n_int = static_cast<int>(n);
        if (n_int < n_vertices) {
          EXPECT_EQ(entity.kind, io::LatticeEntity::Kind::vertex);
        } else if (n_int < n_vertices * k) {
          ASSERT_EQ(entity.kind, io::LatticeEntity::Kind::edge);
          EXPECT_TRUE(steps_of_edge[entity.local].insert(entity.step).second);
          // The step counts from the edge's start vertex (mesh/reference_cell.hpp).
          const auto point = mesh::local_edge_point(type, entity.local, -1.0 + 2.0 * entity.step / k);
          EXPECT_NEAR(point.x(), -1.0 + 2.0 * i / k, 1e-14);
          EXPECT_NEAR(point.y(), -1.0 + 2.0 * j / k, 1e-14);
        } else {
          EXPECT_EQ(entity.kind, io::LatticeEntity::Kind::interior);
        }
      }
      for (int e = 0; e < n_vertices; ++e) EXPECT_EQ(static_cast<int>(steps_of_edge[e].size()), k - 1);
    }
}

TEST(VtuWriter, MixedMeshSharesPointsByEntityAndCarriesTheField) {
  auto m = mesh::split_into_triangles(mesh::make_paper_square_mesh(4), [](int c) { return c % 3 != 0; });
  mesh::perturb_interior_vertices(m, 0.15, 3);
  std::mt19937 generator(5);
  std::vector<int> degrees(m.n_cells());
  for (int& p : degrees) p = std::uniform_int_distribution<int>(1, 6)(generator);
  const space::H1Space space(m, degrees);
  const int k = *std::max_element(degrees.begin(), degrees.end());
  auto f = [](double x, double y) { return std::sin(3 * x) + x * y * y; };
  const io::VtuGrid grid = io::vtu_grid(space, {{"f", 1, [&](int, const assembly::CellValues& values) {
                                                   Eigen::MatrixXd out(values.points.rows(), 1);
                                                   for (Eigen::Index q = 0; q < out.rows(); ++q)
                                                     out(q, 0) = f(values.points(q, 0), values.points(q, 1));
                                                   return out;
                                                 }}});
  const std::string file = io::vtu_text(grid);
  // The linear triangles through the nodes tile the square: k² per triangle, 2k² per
  // quadrilateral, their areas (all of one orientation) adding up to the square's 4.
  std::size_t triangles = 0;
  for (int c = 0; c < m.n_cells(); ++c) triangles += (m.cell_type(c) == mesh::CellType::quadrilateral ? 2 : 1) * k * k;
  EXPECT_EQ(grid.triangles.size(), triangles);
  double area = 0.0;
  for (const auto& [a, b, c] : grid.triangles) {
    const auto x = [&](std::int64_t p, int d) { return grid.xyz[static_cast<std::size_t>(3 * p + d)]; };
    const double signed_area =
        0.5 * ((x(b, 0) - x(a, 0)) * (x(c, 1) - x(a, 1)) - (x(c, 0) - x(a, 0)) * (x(b, 1) - x(a, 1)));
    EXPECT_GT(signed_area, 0.0);
    area += signed_area;
  }
  EXPECT_NEAR(area, 4.0, 1e-12);
  int interior = 0;
  for (int c = 0; c < m.n_cells(); ++c)
    interior += m.cell_type(c) == mesh::CellType::quadrilateral ? (k - 1) * (k - 1) : (k - 1) * (k - 2) / 2;
  const int n_points = attribute(file, "NumberOfPoints");
  EXPECT_EQ(n_points, m.n_vertices() + m.n_edges() * (k - 1) + interior);
  EXPECT_EQ(attribute(file, "NumberOfCells"), m.n_cells());
  const auto points = appended_array(file, "Points"), values = appended_array(file, "f");
  ASSERT_EQ(static_cast<int>(points.size()), 3 * n_points);
  ASSERT_EQ(static_cast<int>(values.size()), n_points);
  for (int p = 0; p < n_points; ++p) ASSERT_NEAR(values[p], f(points[3 * p], points[3 * p + 1]), 1e-13);
  const auto p = appended_array(file, "p"), types = appended_array(file, "types");
  for (int c = 0; c < m.n_cells(); ++c) {
    EXPECT_EQ(p[c], degrees[c]);
    EXPECT_EQ(types[c], m.cell_type(c) == mesh::CellType::quadrilateral ? 70 : 69);
  }
  const auto connectivity = appended_array(file, "connectivity");
  EXPECT_EQ(*std::max_element(connectivity.begin(), connectivity.end()), n_points - 1);
}

TEST(LineSamplesVtu, LinesJoinTheSamplesOfEachZoneWithTheNumericColumns) {
  io::CsvTable table({"x", "y", "lambda", "zone", "label"});
  for (int zone = 0; zone < 2; ++zone)
    for (int i = 0; i < 5; ++i) table.add_row({0.1 * i, 1.0 * zone, -0.5 * i, static_cast<long long>(zone), "text"});
  const std::string file = io::line_samples_vtu_text(table);
  // 4 lines per zone of 5 samples, none across the zones (samples 4 and 5).
  EXPECT_EQ(attribute(file, "NumberOfCells"), 8);
  EXPECT_EQ(appended_array(file, "connectivity"),
            (std::vector<double>{0, 1, 1, 2, 2, 3, 3, 4, 5, 6, 6, 7, 7, 8, 8, 9}));
  EXPECT_EQ(appended_array(file, "types"), std::vector<double>(8, 3.0));
  EXPECT_EQ(appended_array(file, "lambda")[4], -2.0);
  EXPECT_EQ(file.find("Name=\"label\""), std::string::npos);  // text columns are left out
}

TEST(PvdWriter, ListsTheFilesWithTheirTimes) {
  const std::string text = io::pvd_text({{0.0, "a_level0.vtu"}, {1.0, "a_level1.vtu"}});
  EXPECT_NE(text.find("<DataSet timestep=\"1\" part=\"0\" file=\"a_level1.vtu\"/>"), std::string::npos);
  EXPECT_NE(text.find("type=\"Collection\""), std::string::npos);
}
