// Gmsh reader (the Gmsh API): MSH 2.2, 4.0 and 4.1, ASCII and binary, quadrilateral meshes,
// physical curve labels, reorientation, and the errors for files it cannot read.
#include "mesh/gmsh_reader.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include "core/error.hpp"
#include "support/scratch.hpp"

using namespace hpcontact;
using namespace hpcontact::mesh;
using ::testing::HasSubstr;

namespace {

std::string data(const std::string& name) { return std::string(HPCONTACT_TEST_DATA) + "/" + name; }

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Writes `text` to a file named `name` in the scratch folder and returns its path.
std::string write_temp(const std::string& name, const std::string& text) {
  const auto path = hpcontact::testing::scratch_root() / name;
  std::ofstream(path) << text;
  return path.string();
}

/// square_2x2.msh with the first occurrence of `from` replaced by `to`.
std::string square_with(const std::string& from, const std::string& to) {
  std::string text = read_text(data("square_2x2.msh"));
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

std::string message_of(const std::string& path) {
  try {
    read_gmsh_mesh(path);
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no InputError thrown)";
}

/// Label of the boundary edge whose midpoint is `midpoint`; "(none)" if there is no such edge.
std::string label_at(const Mesh& mesh, const Point& midpoint) {
  for (int e : mesh.boundary_edges())
    if ((mesh.edge_midpoint(e) - midpoint).norm() < 1e-12) return mesh.edge_label(e);
  return "(none)";
}

std::map<std::string, double> length_by_label(const Mesh& mesh) {
  std::map<std::string, double> length;
  for (int e : mesh.boundary_edges()) length[mesh.edge_label(e)] += mesh.edge_length(e);
  return length;
}

// Points in lexicographic order (two files may number the same nodes differently).
std::vector<std::pair<double, double>> sorted_points(const std::vector<Point>& points) {
  std::vector<std::pair<double, double>> out;
  for (const auto& p : points) out.emplace_back(p.x(), p.y());
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Point> cell_centres(const Mesh& mesh) {
  std::vector<Point> out;
  for (int c = 0; c < mesh.n_cells(); ++c) {
    Point sum = Point::Zero();
    for (int v : mesh.cell(c)) sum += mesh.vertex(v);
    out.push_back(sum / 4.0);
  }
  return out;
}

}  // namespace

TEST(GmshReader, ReadsSquareWithPhysicalCurves) {
  const Mesh mesh = read_gmsh_mesh(data("square_2x2.msh"));
  EXPECT_EQ(mesh.n_vertices(), 9);
  EXPECT_EQ(mesh.n_cells(), 4);
  EXPECT_EQ(mesh.n_edges(), 12);
  ASSERT_EQ(mesh.boundary_edges().size(), 8u);
  EXPECT_EQ(mesh.vertex(8), Point(0.0, 0.0));

  EXPECT_EQ(label_at(mesh, Point(-0.5, -1.0)), "contact");
  EXPECT_EQ(label_at(mesh, Point(0.5, -1.0)), "contact");
  EXPECT_EQ(label_at(mesh, Point(-0.5, 1.0)), "dirichlet");
  EXPECT_EQ(label_at(mesh, Point(0.5, 1.0)), "dirichlet");
  for (double y : {-0.5, 0.5}) {
    EXPECT_EQ(label_at(mesh, Point(-1.0, y)), "neumann");
    EXPECT_EQ(label_at(mesh, Point(1.0, y)), "neumann");
  }
  const auto length = length_by_label(mesh);
  EXPECT_NEAR(length.at("contact"), 2.0, 1e-14);
  EXPECT_NEAR(length.at("dirichlet"), 2.0, 1e-14);
  EXPECT_NEAR(length.at("neumann"), 4.0, 1e-14);
  EXPECT_EQ(length.count(""), 0u);  // every boundary edge is in a physical group

  // Labels only; the caller decides the boundary condition.
  for (int e : mesh.boundary_edges()) EXPECT_EQ(mesh.edge_part(e), BoundaryPart::neumann);
}

TEST(GmshReader, MapsNodeTagsAndReorientsClockwiseQuads) {
  // MSH 4.0, node tags 100, 42, 13, 900, 77, 7, 5; node 77 belongs to no quadrilateral.
  const Mesh mesh = read_gmsh_mesh(data("rectangle_msh40_tags_cw.msh"));
  ASSERT_EQ(mesh.n_vertices(), 6);
  ASSERT_EQ(mesh.n_cells(), 2);
  EXPECT_EQ(mesh.vertex(0), Point(0.0, 0.0));  // tag 100
  EXPECT_EQ(mesh.vertex(4), Point(1.0, 0.0));  // tag 7
  EXPECT_EQ(mesh.vertex(5), Point(1.0, 1.0));  // tag 5
  EXPECT_EQ(mesh.cells()[0], (std::array<int, 4>{0, 4, 5, 3}));
  // Given clockwise as tags (7, 5, 13, 42); reversed to (7, 42, 13, 5).
  EXPECT_EQ(mesh.cells()[1], (std::array<int, 4>{4, 1, 2, 5}));
  for (int e : mesh.boundary_edges()) EXPECT_NEAR(mesh.boundary_normal(e, 0.0).norm(), 1.0, 1e-14);
  EXPECT_EQ(mesh.boundary_normal(mesh.cell_edge(1, 1), 0.0), Point(1.0, 0.0));

  EXPECT_EQ(label_at(mesh, Point(1.5, 0.0)), "contact");
  EXPECT_EQ(label_at(mesh, Point(2.0, 0.5)), "12");  // unnamed group: its number
  EXPECT_EQ(label_at(mesh, Point(0.0, 0.5)), "12");
  EXPECT_EQ(label_at(mesh, Point(0.5, 1.0)), "");  // curve in no physical group
  const auto length = length_by_label(mesh);
  EXPECT_NEAR(length.at("contact"), 2.0, 1e-14);
  EXPECT_NEAR(length.at("12"), 2.0, 1e-14);
  EXPECT_NEAR(length.at(""), 2.0, 1e-14);
}

TEST(GmshReader, SkipsUnknownSectionsAndParametricCoordinates) {
  const std::string text = square_with("$EndElements\n", "$EndElements\n$NodeData\n1\n\"u\"\n0\n0\n$EndNodeData\n");
  EXPECT_EQ(read_gmsh_mesh(write_temp("node_data.msh", text)).n_cells(), 4);
  const std::string parametric = square_with("1 1 0 1\n5\n0 -1 0\n", "1 1 1 1\n5\n0 -1 0 0.5\n");
  EXPECT_EQ(read_gmsh_mesh(write_temp("parametric.msh", parametric)).vertex(4), Point(0.0, -1.0));
}

TEST(GmshReader, Msh22AndBinaryFilesGiveTheSameMesh) {
  // square_2x2.msh converted by Gmsh 4.8 (gmsh square_2x2.msh -0 -format msh22 / -format msh41 -bin).
  const Mesh ascii = read_gmsh_mesh(data("square_2x2.msh"));
  for (const std::string file : {"square_2x2_msh22.msh", "square_2x2_binary.msh"}) {
    const Mesh other = read_gmsh_mesh(data(file));
    ASSERT_EQ(other.n_cells(), ascii.n_cells()) << file;
    ASSERT_EQ(other.n_vertices(), ascii.n_vertices()) << file;
    EXPECT_EQ(sorted_points(other.vertices()), sorted_points(ascii.vertices())) << file;
    EXPECT_EQ(sorted_points(cell_centres(other)), sorted_points(cell_centres(ascii))) << file;
    EXPECT_EQ(length_by_label(other), length_by_label(ascii)) << file;
  }
  EXPECT_EQ(read_gmsh_mesh(data("version2.msh")).n_cells(), 2);
}

TEST(GmshReader, SecondOrderCellsReadWithTheirCorners) {
  // square_order2.msh: one 9-node quadrilateral (Mesh.ElementOrder = 2), written by Gmsh; its edge
  // nodes lie on the chords, so the cell stays straight (curved ones: curved_geometry_test.cpp).
  const Mesh mesh = read_gmsh_mesh(data("square_order2.msh"));
  EXPECT_EQ(mesh.n_cells(), 1);
  EXPECT_EQ(mesh.n_vertices(), 4);
  EXPECT_FALSE(mesh.has_curved_cells());
}

TEST(GmshReader, UnreadableFilesAreRejectedWithGmshsMessage) {
  EXPECT_THAT(message_of(data("truncated.msh")), HasSubstr("truncated.msh: Gmsh cannot read the file: Could not read"));
  EXPECT_THAT(message_of(write_temp("unknown_node.msh", square_with("9 1 5 9 8", "9 1 5 99 8"))),
              HasSubstr("Unknown node 99 in element 9"));
  EXPECT_THAT(message_of(write_temp("short_nodes.msh", square_with("2 1 0 1\n9\n", "2 1 0 2\n9\n"))),
              HasSubstr("Gmsh cannot read the file"));
  EXPECT_THAT(message_of(data("no_such_file.msh")),
              ::testing::AllOf(HasSubstr("cannot open the Gmsh mesh file"),
                               HasSubstr("no_such_file.msh': No such file or directory")));
  EXPECT_THAT(message_of(write_temp("not_a_mesh.msh", "hello\n")), HasSubstr("not_a_mesh.msh"));
  const std::string text = read_text(data("square_2x2.msh"));
  EXPECT_THAT(message_of(write_temp("no_elements.msh", text.substr(0, text.find("$Elements")))),
              HasSubstr("no_elements.msh: holds no triangles or quadrilaterals"));
}

TEST(GmshReader, AFileAfterAnUnreadableOneReads) {
  // Gmsh ignores later files after an error inside its reader unless it is started afresh.
  EXPECT_THAT(message_of(data("truncated.msh")), HasSubstr("Gmsh cannot read the file"));
  EXPECT_EQ(read_gmsh_mesh(data("square_2x2.msh")).n_cells(), 4);
}

TEST(GmshReader, LabelledLineInsideTheDomainIsRejected) {
  // Line element 2 now joins the corner (1,-1) to the centre: an interior diagonal.
  const auto path = write_temp("interior_line.msh", square_with("2 5 2", "2 9 2"));
  EXPECT_THAT(message_of(path), HasSubstr("interior_line.msh: line element 2 (nodes 9, 2) of physical group "
                                          "'contact' is not a boundary edge"));
}

TEST(GmshReader, CurveInTwoPhysicalGroupsIsRejected) {
  const auto path = write_temp("two_groups.msh", square_with("0 1 1 2 1 -2", "0 2 1 3 2 1 -2"));
  EXPECT_THAT(message_of(path), HasSubstr("curve 1 belongs to the physical groups 'contact' and 'neumann'"));
}

TEST(GmshReader, GeometryFileIsMeshedIntoQuadrilateralsWithItsPhysicalCurves) {
  // The tutorial's block: contact on y = 0 (length 2), clamped on the sloped top, free sides.
  const std::string geo = std::string(HPCONTACT_SOURCE_DIR) + "/studies/tutorial/block.geo";
  const Mesh coarse = read_gmsh_mesh(geo);
  const Mesh fine = read_gmsh_mesh(geo, {0.1});
  EXPECT_GT(fine.n_cells(), 2 * coarse.n_cells());
  for (const Mesh* mesh : {&coarse, &fine}) {
    const auto lengths = length_by_label(*mesh);
    EXPECT_NEAR(lengths.at("contact"), 2.0, 1e-12);
    EXPECT_NEAR(lengths.at("clamped"), std::hypot(2.0, 0.5), 1e-12);
    EXPECT_NEAR(lengths.at("free"), 2.5, 1e-12);
    EXPECT_EQ(lengths.count(""), 0u) << "every boundary edge is labelled";
  }
}

TEST(GmshReader, GeometryFileErrorsNameTheFileAndTheRule) {
  const std::string geo = read_text(std::string(HPCONTACT_SOURCE_DIR) + "/studies/tutorial/block.geo");
  // A .geo's element order does not matter: curved sides come from the geometry itself.
  EXPECT_EQ(read_gmsh_mesh(write_temp("order2.geo", geo + "\nMesh.ElementOrder = 2;\n")).n_cells(),
            read_gmsh_mesh(std::string(HPCONTACT_SOURCE_DIR) + "/studies/tutorial/block.geo").n_cells());
  EXPECT_THAT(message_of(write_temp("broken.geo", "Point(1) = {0, 0, 0;\n")),
              HasSubstr("broken.geo: Gmsh cannot read the file"));
  try {
    read_gmsh_mesh(data("square_2x2.msh"), {0.5});
    ADD_FAILURE() << "a mesh size for a mesh file must be refused";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("square_2x2.msh: a mesh size applies to Gmsh geometry files (.geo) only"));
  }
}
