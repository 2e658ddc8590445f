// Stage 4, Gmsh reader: MSH 4.0/4.1 quadrilateral meshes, physical curve labels, reorientation,
// and the errors for files it cannot read.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "core/error.hpp"
#include "mesh/gmsh_reader.hpp"

using namespace hpcontact;
using namespace hpcontact::mesh;
using ::testing::HasSubstr;

namespace {

std::string data(const std::string& name) { return std::string(HPCONTACT_TEST_DATA) + "/" + name; }

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Writes `text` to a file named `name` in the temporary directory and returns its path.
std::string write_temp(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("hpcontact_test_04_" + name);
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
std::string label_at(const QuadMesh& mesh, const Point& midpoint) {
  for (int e : mesh.boundary_edges())
    if ((mesh.edge_midpoint(e) - midpoint).norm() < 1e-12) return mesh.edge_label(e);
  return "(none)";
}

std::map<std::string, double> length_by_label(const QuadMesh& mesh) {
  std::map<std::string, double> length;
  for (int e : mesh.boundary_edges()) length[mesh.edge_label(e)] += mesh.edge_length(e);
  return length;
}

}  // namespace

TEST(GmshReader, ReadsSquareWithPhysicalCurves) {
  const QuadMesh mesh = read_gmsh_mesh(data("square_2x2.msh"));
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
  const QuadMesh mesh = read_gmsh_mesh(data("rectangle_msh40_tags_cw.msh"));
  ASSERT_EQ(mesh.n_vertices(), 6);
  ASSERT_EQ(mesh.n_cells(), 2);
  EXPECT_EQ(mesh.vertex(0), Point(0.0, 0.0));  // tag 100
  EXPECT_EQ(mesh.vertex(4), Point(1.0, 0.0));  // tag 7
  EXPECT_EQ(mesh.vertex(5), Point(1.0, 1.0));  // tag 5
  EXPECT_EQ(mesh.cell(0), (std::array<int, 4>{0, 4, 5, 3}));
  // Given clockwise as tags (7, 5, 13, 42); reversed to (7, 42, 13, 5).
  EXPECT_EQ(mesh.cell(1), (std::array<int, 4>{4, 1, 2, 5}));
  for (int e : mesh.boundary_edges()) EXPECT_NEAR(mesh.boundary_normal(e).norm(), 1.0, 1e-14);
  EXPECT_EQ(mesh.boundary_normal(mesh.cell_edge(1, 1)), Point(1.0, 0.0));

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

TEST(GmshReader, TrianglesAreRejected) {
  const auto message = message_of(data("triangles.msh"));
  EXPECT_THAT(message, HasSubstr("triangles.msh:18:"));
  EXPECT_THAT(message, HasSubstr("only 4-node quadrilaterals (type 3) are supported; found type 2"));
}

TEST(GmshReader, NineNodeQuadsAreRejected) {
  const auto path = write_temp("quad9.msh", square_with("2 1 3 4", "2 1 10 4"));
  EXPECT_THAT(message_of(path), HasSubstr("found type 10"));
}

TEST(GmshReader, TruncatedFileIsRejected) {
  const auto message = message_of(data("truncated.msh"));
  EXPECT_THAT(message, HasSubstr("truncated.msh:67:"));
  EXPECT_THAT(message, HasSubstr("ends inside the $Elements section (truncated?)"));
}

TEST(GmshReader, SectionWithFewerEntriesThanAnnouncedIsRejected) {
  const auto path = write_temp("short_nodes.msh", square_with("2 1 0 1\n9\n", "2 1 0 2\n9\n"));
  EXPECT_THAT(message_of(path), HasSubstr("the $Nodes section ends early at '$EndNodes'"));
}

TEST(GmshReader, Version2IsRejected) {
  const auto message = message_of(data("version2.msh"));
  EXPECT_THAT(message, HasSubstr("version2.msh:2:"));
  EXPECT_THAT(message, HasSubstr("MSH version 2.2 is not supported; only 4.0 and 4.1"));
}

TEST(GmshReader, BinaryIsRejected) {
  const auto path = write_temp("binary.msh", square_with("4.1 0 8", "4.1 1 8"));
  EXPECT_THAT(message_of(path), HasSubstr("binary MSH files are not supported"));
}

TEST(GmshReader, MissingFileAndSectionsAreRejected) {
  EXPECT_THAT(message_of(data("no_such_file.msh")), HasSubstr("no_such_file.msh: cannot open the Gmsh mesh file"));
  EXPECT_THAT(message_of(write_temp("no_format.msh", "$Nodes\n0 0 0 0\n$EndNodes\n")),
              HasSubstr("must begin with $MeshFormat"));
  const std::string text = read_text(data("square_2x2.msh"));
  const auto no_elements = write_temp("no_elements.msh", text.substr(0, text.find("$Elements")));
  EXPECT_THAT(message_of(no_elements), HasSubstr("no $Elements section"));
}

TEST(GmshReader, BadNumbersAndUnknownNodesAreRejected) {
  const auto bad_number = write_temp("bad_number.msh", square_with("0 -1 0", "0 -1x 0"));
  EXPECT_THAT(message_of(bad_number), HasSubstr("bad_number.msh:39: field 2 '-1x' is not"));
  const auto unknown_node = write_temp("unknown_node.msh", square_with("9 1 5 9 8", "9 1 5 99 8"));
  EXPECT_THAT(message_of(unknown_node), HasSubstr("element 9 refers to node tag 99, which $Nodes does not define"));
}

TEST(GmshReader, LabelledLineInsideTheDomainIsRejected) {
  // Line element 2 now joins the corner (1,-1) to the centre: an interior diagonal.
  const auto path = write_temp("interior_line.msh", square_with("2 5 2", "2 9 2"));
  const auto message = message_of(path);
  EXPECT_THAT(message, HasSubstr("interior_line.msh:57:"));
  EXPECT_THAT(message, HasSubstr("line element 2 (nodes 9, 2) of physical group 'contact' is not "
                                 "a boundary edge"));
}

TEST(GmshReader, CurveInTwoPhysicalGroupsIsRejected) {
  const auto path = write_temp("two_groups.msh", square_with("0 1 1 2 1 -2", "0 2 1 3 2 1 -2"));
  EXPECT_THAT(message_of(path), HasSubstr("curve 1 belongs to 2 physical groups"));
}
