// Gmsh meshes of hexahedra and tetrahedra: an extruded block equal to the box mesh, tetrahedra
// subdivided into valid hexahedra that fill the cube, tetrahedra that fill it, physical surfaces as
// face labels, and the errors for files that hold other cells (prisms), high-order ones, volumes
// meshed apart, or a mesh size that would not fit.
#include "mesh/gmsh_solid_reader.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <fstream>
#include <map>

#include "basis/quadrature.hpp"
#include "core/error.hpp"
#include "support/scratch.hpp"

using namespace hpcontact;
using namespace hpcontact::mesh;
using ::testing::HasSubstr;

namespace {

const std::string kBlock = std::string(HPCONTACT_SOURCE_DIR) + "/studies/three_d/extruded_block.geo";

std::string write_temp(const std::string& name, const std::string& text) {
  const auto path = hpcontact::testing::scratch_root() / name;
  std::ofstream(path) << text;
  return path.string();
}

/// The unit cube (OpenCASCADE), its six faces the physical surface "wall", with extra options.
std::string unit_cube(const std::string& name, const std::string& options) {
  return write_temp(name, "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n" + options +
                              "\nPhysical Surface(\"wall\") = {1, 2, 3, 4, 5, 6};\nPhysical Volume(\"cube\") = {1};\n");
}

/// Σ over cells of ∫ det ∂x/∂ξ by the 2-point Gauss rule per axis (exact: det of a trilinear map
/// has degree at most 2 in each variable).
double volume(const SolidMesh& mesh) {
  const auto rule = basis::gauss_legendre(2);
  double sum = 0.0;
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (std::size_t i = 0; i < rule.points.size(); ++i)
      for (std::size_t j = 0; j < rule.points.size(); ++j)
        for (std::size_t k = 0; k < rule.points.size(); ++k)
          sum += rule.weights[i] * rule.weights[j] * rule.weights[k] *
                 mesh.jacobian(c, Eigen::Vector3d(rule.points[i], rule.points[j], rule.points[k])).determinant();
  return sum;
}

std::map<std::string, int> label_counts(const SolidMesh& mesh) {
  std::map<std::string, int> counts;
  for (const auto& face : mesh.boundary_faces()) ++counts[face.label];
  return counts;
}

std::string message_of(const std::string& path, const GeoMeshing& geo = {}) {
  try {
    read_gmsh_solid_mesh(path, geo);
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(GmshSolidReader, ExtrudedBlockIsTheBoxWithItsPhysicalSurfaces) {
  EXPECT_EQ(gmsh_file_dimension(kBlock), 3);
  const SolidMesh mesh = read_gmsh_solid_mesh(kBlock);
  EXPECT_EQ(mesh.n_cells(), 8 * 2 * 8);
  EXPECT_EQ(mesh.n_vertices(), 9 * 3 * 9);
  EXPECT_EQ(mesh.boundary_faces().size(), 2u * (8 * 2 + 8 * 8 + 2 * 8));
  for (int c = 0; c < mesh.n_cells(); ++c) EXPECT_TRUE(mesh.is_affine(c)) << c;
  EXPECT_NEAR(volume(mesh), 2.0, 1e-13);
  const auto counts = label_counts(mesh);
  EXPECT_EQ(counts.at("bottom"), 16);
  EXPECT_EQ(counts.at("top"), 16);
  for (const auto& face : mesh.boundary_faces()) {
    const SolidPoint x = mesh.face_centre(mesh.cell_face(face.cell, face.local_face));
    if (face.label == "bottom") EXPECT_NEAR(x.z(), -1.0, 1e-14);
    if (face.label == "top") EXPECT_NEAR(x.z(), 1.0, 1e-14);
  }
}

TEST(GmshSolidReader, SubdividedTetrahedraAreValidHexahedraThatFillTheCube) {
  const std::string path =
      unit_cube("cube_subdivided.geo", "Mesh.SubdivisionAlgorithm = 2;\nMeshSize{ PointsOf{ Volume{1}; } } = 0.6;");
  GeoMeshing geo;
  geo.mesh_size = 0.4;                                     // (Mesh.MeshSizeMax: finer than the points' 0.6)
  const SolidMesh mesh = read_gmsh_solid_mesh(path, geo);  // (positive Jacobians: the constructor checks)
  EXPECT_GT(mesh.n_cells(), read_gmsh_solid_mesh(path).n_cells());
  int non_affine = 0;
  for (int c = 0; c < mesh.n_cells(); ++c) non_affine += !mesh.is_affine(c);
  EXPECT_GT(non_affine, mesh.n_cells() / 2);
  EXPECT_NEAR(volume(mesh), 1.0, 1e-12);
  const auto counts = label_counts(mesh);
  ASSERT_EQ(counts.size(), 1u);
  EXPECT_EQ(counts.begin()->first, "wall");
  // The cube's surface area: the boundary faces are flat quadrilaterals on its six faces.
  double area = 0.0;
  for (const auto& face : mesh.boundary_faces()) {
    const auto& q = mesh.face(mesh.cell_face(face.cell, face.local_face));  // (tensor order)
    const SolidPoint a = mesh.vertex(q[0]), b = mesh.vertex(q[1]), c = mesh.vertex(q[2]), d = mesh.vertex(q[3]);
    area += 0.5 * (d - a).cross(c - b).norm();
  }
  EXPECT_NEAR(area, 6.0, 1e-12);
}

TEST(GmshSolidReader, TetrahedraFillTheCubeAndTheirTrianglesCarryTheLabels) {
  const SolidMesh mesh =
      read_gmsh_solid_mesh(unit_cube("cube_tetrahedra.geo", "MeshSize{ PointsOf{ Volume{1}; } } = 0.4;"));
  ASSERT_TRUE(mesh.is_tetrahedral());
  EXPECT_GT(mesh.n_cells(), 24);
  double volume = 0.0;
  for (int c = 0; c < mesh.n_cells(); ++c)
    volume += std::abs(mesh.jacobian(c, Eigen::Vector3d::Zero()).determinant()) * 4.0 / 3.0;
  EXPECT_NEAR(volume, 1.0, 1e-12);
  const auto counts = label_counts(mesh);
  ASSERT_EQ(counts.size(), 1u);
  EXPECT_EQ(counts.begin()->first, "wall");
  double area = 0.0;
  for (const auto& face : mesh.boundary_faces()) {
    const auto& t = mesh.face(mesh.cell_face(face.cell, face.local_face));
    area += 0.5 * (mesh.vertex(t[1]) - mesh.vertex(t[0])).cross(mesh.vertex(t[2]) - mesh.vertex(t[0])).norm();
  }
  EXPECT_NEAR(area, 6.0, 1e-12);
}

TEST(GmshSolidReader, FilesWithoutHexahedraOrTetrahedraAreRefusedWithWhatToChange) {
  // Triangles extruded in recombined layers give prisms.
  const std::string prisms = write_temp(
      "prisms.geo",
      "SetFactory(\"OpenCASCADE\");\nRectangle(1) = {0, 0, 0, 1, 1};\n"
      "Extrude {0, 0, 1} { Surface{1}; Layers{2}; Recombine; }\nMeshSize{ PointsOf{ Surface{1}; } } = 0.5;\n");
  EXPECT_THAT(message_of(prisms),
              ::testing::AllOf(HasSubstr("prisms.geo"), HasSubstr("Prism"), HasSubstr("hexahedra or tetrahedra")));
  EXPECT_THAT(message_of(unit_cube("cube_order2.geo", "Mesh.SubdivisionAlgorithm = 2;\nMesh.ElementOrder = 2;")),
              ::testing::AllOf(HasSubstr("of order 2"), HasSubstr("Mesh.ElementOrder = 1")));
  EXPECT_THAT(message_of(std::string(HPCONTACT_TEST_DATA) + "/extruded_contact.geo"), HasSubstr("holds no 3-D mesh"));
  EXPECT_THAT(message_of("/nonexistent/block.geo"), HasSubstr("cannot open"));
  // Two boxes meshed apart: their common face would be a crack.
  const std::string apart =
      write_temp("two_boxes.geo",
                 "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\nBox(2) = {1, 0, 0, 1, 1, 1};\n"
                 "Mesh.SubdivisionAlgorithm = 2;\nMeshSize{ PointsOf{ Volume{1, 2}; } } = 0.6;\n");
  EXPECT_THAT(message_of(apart),
              ::testing::AllOf(HasSubstr("two boundary faces lie at"), HasSubstr("BooleanFragments")));
  GeoMeshing tiny;
  tiny.mesh_size = 1e-3;
  tiny.max_cells = 1e6;
  tiny.size_key = "domain.mesh_size";
  EXPECT_THAT(message_of(kBlock, tiny),
              ::testing::AllOf(HasSubstr("domain.mesh_size"), HasSubstr("hexahedra"), HasSubstr("at least")));
}

}  // namespace
