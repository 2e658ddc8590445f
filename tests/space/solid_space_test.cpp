// The hexahedral space's traces: on every face shared by two cells, each global dof has the same
// trace from both sides, under every orientation of the cells and with mixed degrees.
#include "space/solid_space.hpp"

#include <gtest/gtest.h>

#include <map>
#include <random>

#include "basis/lobatto.hpp"
#include "support/solid_meshes.hpp"

namespace hpcontact::space {
namespace {

/// The cell's local coordinates of the point (S, T) of its local face (face_orientation's frame).
Eigen::Vector3d local_point(const mesh::SolidMesh& mesh, int cell, int local_face, double s, double t) {
  const auto orientation = mesh.face_orientation(cell, local_face);
  const double along_s = orientation.sign_s * s, along_t = orientation.sign_t * t;
  Eigen::Vector3d xi;
  xi(local_face / 2) = local_face % 2 == 0 ? -1.0 : 1.0;
  xi(mesh::kHexFaceAxes[local_face][0]) = orientation.swapped ? along_t : along_s;
  xi(mesh::kHexFaceAxes[local_face][1]) = orientation.swapped ? along_s : along_t;
  return xi;
}

/// Σ over the cell's shapes of sign · shape(ξ), per global dof (the dofs' basis functions at ξ).
std::map<int, double> dof_values(const SolidH1Space& space, int cell, const Eigen::Vector3d& xi) {
  const int p = space.cell_degree(cell);
  std::array<Eigen::VectorXd, 3> values;
  Eigen::VectorXd slopes(p + 1);
  for (int d = 0; d < 3; ++d) {
    values[d].resize(p + 1);
    basis::lobatto_values(p, xi(d), values[d], slopes);
  }
  std::map<int, double> out;
  for (const auto& shape : space.cell_shapes(cell)) {
    const double value = shape.sign * values[0](shape.index[0]) * values[1](shape.index[1]) * values[2](shape.index[2]);
    if (shape.dof >= 0 && value != 0.0) out[shape.dof] += value;
  }
  return out;
}

TEST(SolidH1Space, SharedFacesHaveOneTrace) {
  const mesh::SolidMesh mesh =
      testing::shuffled(mesh::make_box_mesh(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), {3, 3, 3}), 3);
  std::mt19937 random(2);
  std::vector<int> degrees(mesh.n_cells());
  for (int& degree : degrees) degree = 1 + static_cast<int>(random() % 5);
  const SolidH1Space space(mesh, degrees, {});
  int compared = 0;
  for (int f = 0; f < mesh.n_faces(); ++f) {
    const auto& cells = mesh.face_cells(f);
    if (cells[1] < 0) continue;
    std::array<int, 2> local{};
    for (int k = 0; k < 2; ++k)
      while (mesh.cell_face(cells[k], local[k]) != f) ++local[k];
    for (const auto& [s, t] : {std::pair{0.31, -0.47}, std::pair{-0.83, 0.66}}) {
      auto a = dof_values(space, cells[0], local_point(mesh, cells[0], local[0], s, t));
      auto b = dof_values(space, cells[1], local_point(mesh, cells[1], local[1], s, t));
      for (const auto& [dof, value] : a) {
        EXPECT_NEAR(b[dof], value, 1e-13) << "face " << f << ", dof " << dof;
        ++compared;
      }
      for (const auto& [dof, value] : b) EXPECT_NEAR(a[dof], value, 1e-13) << "face " << f << ", dof " << dof;
    }
  }
  EXPECT_GT(compared, 500);
}

TEST(SolidH1Space, CountsFollowTheMinimumRule) {
  const mesh::SolidMesh mesh = mesh::make_box_mesh(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), {2, 1, 1});
  const SolidH1Space space(mesh, {2, 4}, {});
  // 12 vertices; cell 0's 12 edges and the shared face's 4 of degree 2 (one mode each), cell 1's
  // other 8 edges of degree 4 (three modes); cell 0's 6 faces of degree 2 (one mode), cell 1's
  // other 5 of degree 4 (nine modes); interiors 1 + 27.
  EXPECT_EQ(space.n_skeleton_dofs(), 12 + 12 * 1 + 8 * 3 + 6 * 1 + 5 * 9);
  EXPECT_EQ(space.n_dofs(), space.n_skeleton_dofs() + 1 + 27);
  EXPECT_EQ(space.shape_count(0), 27);
  EXPECT_EQ(space.shape_count(1), 8 + (4 * 1 + 8 * 3) + (1 * 1 + 5 * 9) + 27);
}

}  // namespace
}  // namespace hpcontact::space
