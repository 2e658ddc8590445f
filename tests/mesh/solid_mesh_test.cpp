// Solid meshes: counts and labels of box meshes of hexahedra and tetrahedra, shared faces seen
// alike from both cells under every orientation, and the errors for inverted or degenerate cells.
#include "mesh/solid_mesh.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.hpp"
#include "support/solid_meshes.hpp"

namespace hpcontact::mesh {
namespace {

TEST(SolidMesh, BoxCountsAndLabels) {
  const SolidMesh mesh = make_box_mesh(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 1, 1), {3, 2, 4});
  EXPECT_EQ(mesh.n_cells(), 24);
  EXPECT_EQ(mesh.n_vertices(), 4 * 3 * 5);
  EXPECT_EQ(mesh.n_edges(), 3 * 3 * 5 + 4 * 2 * 5 + 4 * 3 * 4);
  EXPECT_EQ(mesh.n_faces(), 4 * 2 * 4 + 3 * 3 * 4 + 3 * 2 * 5);
  std::map<std::string, int> count;
  for (const auto& face : mesh.boundary_faces()) ++count[face.label];
  EXPECT_EQ(count["x_min"], 8);
  EXPECT_EQ(count["x_max"], 8);
  EXPECT_EQ(count["y_min"], 12);
  EXPECT_EQ(count["z_max"], 6);
  EXPECT_EQ(static_cast<int>(mesh.boundary_faces().size()), 2 * (8 + 12 + 6));
  for (const auto& face : mesh.boundary_faces()) {
    const int f = mesh.cell_face(face.cell, face.local_face);
    const int axis = face.local_face / 2;
    const double side = face.local_face % 2 == 0 ? 0.0 : Eigen::Vector3d(2, 1, 1)(axis);
    EXPECT_DOUBLE_EQ(mesh.face_centre(f)(axis), side) << face.label;
  }
}

/// The cell's local coordinates ξ of the face point with face coordinates (S, T).
Eigen::Vector3d local_point(const SolidMesh& mesh, int cell, int local_face, double s, double t) {
  const auto orientation = mesh.face_orientation(cell, local_face);
  // S = sign_s · (swapped ? v : u), T = sign_t · (swapped ? u : v).
  const double along_s = orientation.sign_s * s, along_t = orientation.sign_t * t;
  const double u = orientation.swapped ? along_t : along_s, v = orientation.swapped ? along_s : along_t;
  Eigen::Vector3d xi;
  xi(local_face / 2) = local_face % 2 == 0 ? -1.0 : 1.0;
  xi(kHexFaceAxes[local_face][0]) = u;
  xi(kHexFaceAxes[local_face][1]) = v;
  return xi;
}

TEST(SolidMesh, SharedFacesAndEdgesAgreeUnderEveryOrientation) {
  const SolidMesh mesh =
      testing::shuffled(make_box_mesh(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), {3, 3, 3}), 7);
  int shared = 0;
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (int f = 0; f < 6; ++f) {
      const int face = mesh.cell_face(c, f);
      const auto& cells = mesh.face_cells(face);
      if (cells[1] < 0 || cells[0] != c) continue;
      const int other = cells[1];
      int other_local = 0;
      while (mesh.cell_face(other, other_local) != face) ++other_local;
      for (const auto& [s, t] : {std::pair{0.3, -0.7}, std::pair{-0.9, 0.2}, std::pair{1.0, 1.0}}) {
        const SolidPoint a = mesh.map(c, local_point(mesh, c, f, s, t));
        const SolidPoint b = mesh.map(other, local_point(mesh, other, other_local, s, t));
        EXPECT_LT((a - b).norm(), 1e-14) << "face " << face;
      }
      ++shared;
    }
  EXPECT_EQ(shared, 3 * 3 * 2 * 3);
  // Each local edge runs along its global edge when edge_sign says so.
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (int e = 0; e < 12; ++e) {
      const auto& edge = mesh.edge(mesh.cell_edge(c, e));
      const int from = mesh.cell(c)[kHexEdgeVertices[e][mesh.edge_sign(c, e) > 0 ? 0 : 1]];
      EXPECT_EQ(from, edge[0]);
    }
}

TEST(SolidMesh, AffineCellsAreRecognised) {
  const SolidMesh box = make_box_mesh(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), {2, 2, 2});
  for (int c = 0; c < box.n_cells(); ++c) EXPECT_TRUE(box.is_affine(c));
  const SolidMesh distorted = testing::distorted_unit_cube(2, 0.1);
  int affine = 0;
  for (int c = 0; c < distorted.n_cells(); ++c) affine += distorted.is_affine(c);
  EXPECT_EQ(affine, 0);
}

TEST(SolidMesh, InvertedOrDegenerateCellsAreInputErrors) {
  std::vector<SolidPoint> vertices;
  for (int v = 0; v < 8; ++v) vertices.emplace_back(v & 1, (v >> 1) & 1, (v >> 2) & 1);
  // Mirrored: the first two vertices swapped.
  EXPECT_THROW(SolidMesh(vertices, {{1, 0, 2, 3, 4, 5, 6, 7}}, "t.msh"), InputError);
  // Flattened: the top face on the bottom one.
  EXPECT_THROW(SolidMesh(vertices, {{0, 1, 2, 3, 0, 1, 2, 3}}, "t.msh"), InputError);
  EXPECT_THROW(SolidMesh(vertices, {{0, 1, 2, 3, 4, 5, 6, 8}}, "t.msh"), InputError);
  try {
    SolidMesh(vertices, {{1, 0, 2, 3, 4, 5, 6, 7}}, "t.msh");
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("t.msh: hexahedron 0 is inverted"), std::string::npos) << error.what();
  }
  EXPECT_THROW(make_box_mesh(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), {2, 0, 2}), InputError);
  EXPECT_NO_THROW(SolidMesh(vertices, {{0, 1, 2, 3, 4, 5, 6, 7}}, "t.msh"));
}

TEST(SolidMesh, TetrahedralBoxCountsLabelsAndVolume) {
  const std::array<std::vector<double>, 3> nodes{{{0.0, 0.5, 2.0}, {0.0, 1.0}, {0.0, 0.25, 0.5, 1.0}}};
  const SolidMesh mesh = make_tetrahedral_box_mesh(nodes, "box");
  EXPECT_TRUE(mesh.is_tetrahedral());
  EXPECT_EQ(mesh.n_cells(), 6 * 2 * 1 * 3);
  EXPECT_EQ(mesh.n_vertices(), 3 * 2 * 4);
  // Euler: V − E + F − C = 1 for a ball.
  EXPECT_EQ(mesh.n_vertices() - mesh.n_edges() + mesh.n_faces() - mesh.n_cells(), 1);
  std::map<std::string, int> count;
  for (const auto& face : mesh.boundary_faces()) ++count[face.label];
  EXPECT_EQ(count["x_min"], 2 * 1 * 3);
  EXPECT_EQ(count["y_max"], 2 * 2 * 3);
  EXPECT_EQ(count["z_min"], 2 * 2 * 1);
  EXPECT_EQ(count[""], 0);
  EXPECT_EQ(static_cast<int>(mesh.boundary_faces().size()), 2 * 2 * (3 + 6 + 2));
  double volume = 0.0;
  for (int c = 0; c < mesh.n_cells(); ++c) {
    EXPECT_TRUE(mesh.is_affine(c));
    volume += std::abs(mesh.jacobian(c, Eigen::Vector3d::Zero()).determinant()) * 4.0 / 3.0;
    const auto v = mesh.cell_vertices(c);
    EXPECT_TRUE(std::is_sorted(v.begin(), v.end()));
    // The map sends the reference vertices to the cell's.
    EXPECT_LT((mesh.map(c, Eigen::Vector3d(1, -1, -1)) - mesh.vertex(v[1])).norm(), 1e-15);
    EXPECT_LT((mesh.map(c, Eigen::Vector3d(-1, -1, 1)) - mesh.vertex(v[3])).norm(), 1e-15);
  }
  EXPECT_NEAR(volume, 2.0, 1e-14);
  // Every interior triangle has two cells, every local edge runs along its global edge.
  for (int f = 0; f < mesh.n_faces(); ++f) EXPECT_EQ(mesh.face(f)[3], -1);
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (int e = 0; e < 6; ++e) EXPECT_EQ(mesh.edge_sign(c, e), 1);
}

TEST(SolidMesh, DegenerateTetrahedraAreInputErrors) {
  const std::vector<SolidPoint> vertices{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
  EXPECT_NO_THROW(SolidMesh::tetrahedra(vertices, {{3, 1, 0, 2}}, "t.msh"));
  try {
    SolidMesh::tetrahedra(vertices, {{0, 1, 2, 4}}, "t.msh");  // four points in z = 0
    ADD_FAILURE() << "a flat tetrahedron was accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("t.msh: the tetrahedron of vertices 0, 1, 2, 4 is degenerate"),
              std::string::npos)
        << error.what();
  }
  EXPECT_THROW(SolidMesh::tetrahedra(vertices, {{0, 1, 1, 3}}, "t.msh"), InputError);
  EXPECT_THROW(SolidMesh::tetrahedra(vertices, {{0, 1, 2, 5}}, "t.msh"), InputError);
  EXPECT_THROW(SolidMesh::tetrahedra(vertices, {}, "t.msh"), InputError);
}

}  // namespace
}  // namespace hpcontact::mesh
