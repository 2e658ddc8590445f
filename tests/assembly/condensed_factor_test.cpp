// Static condensation: the factorization of a K + b M from element eliminations and the
// skeleton Schur complement must equal a direct factorization of the assembled matrix: Schur
// complements B A⁻¹ Bᵀ (through the trace and by solves), solves and quadratic forms, on meshes
// of parallelograms (shared eliminations, reversed edges), of general quadrilaterals and of mixed
// triangles and quadrilaterals, with mixed degrees and Dirichlet dofs.
#include "assembly/condensed_factor.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <random>

#include "assembly/coupling.hpp"
#include "assembly/poisson_assembly.hpp"
#include "linalg/sparse_cholesky.hpp"
#include "mesh/contact_boundary.hpp"
#include "mesh/point_grading.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "mesh/refine.hpp"
#include "space/multiplier_space.hpp"

using namespace hpcontact;

namespace {

double relative_difference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).norm() / b.norm(); }

// The §7 mesh with its vertices numbered in random order, so that the local edge directions
// disagree with the global ones on about half the edges (shape signs −1), as in Gmsh meshes.
mesh::Mesh renumbered_paper_square(int n, std::uint32_t seed) {
  const auto ordered = mesh::make_paper_square_mesh(n);
  std::vector<int> new_index(ordered.n_vertices());
  for (int v = 0; v < ordered.n_vertices(); ++v) new_index[v] = v;
  std::shuffle(new_index.begin(), new_index.end(), std::mt19937(seed));
  std::vector<mesh::Point> vertices(ordered.n_vertices());
  for (int v = 0; v < ordered.n_vertices(); ++v) vertices[new_index[v]] = ordered.vertex(v);
  std::vector<std::array<int, 4>> cells;
  for (int c = 0; c < ordered.n_cells(); ++c) {
    std::array<int, 4> cell{};
    for (int k = 0; k < 4; ++k) cell[k] = new_index[ordered.cell(c)[k]];
    cells.push_back(cell);
  }
  mesh::Mesh out(std::move(vertices), std::move(cells), "renumbered §7 square");
  mesh::assign_paper_boundary_parts(out);
  return out;
}

// Sheared into congruent parallelograms, and randomly perturbed; both with mixed edge signs.
std::vector<mesh::Mesh> test_meshes() {
  auto sheared = renumbered_paper_square(6, 1);
  std::vector<mesh::Point> moved;
  for (int v = 0; v < sheared.n_vertices(); ++v) {
    const auto& x = sheared.vertex(v);
    moved.emplace_back(x.x() + 0.3 * x.y(), 0.8 * x.y());
  }
  sheared.move_vertices(moved, "test");
  auto perturbed = renumbered_paper_square(6, 2);
  mesh::perturb_interior_vertices(perturbed, 0.2, 3);
  // Two of every three cells cut into triangles: a mixed mesh, perturbed.
  auto mixed = mesh::split_into_triangles(renumbered_paper_square(6, 4), [](int c) { return c % 3 != 0; });
  mesh::perturb_interior_vertices(mixed, 0.1, 7);
  std::vector<mesh::Mesh> out;
  out.push_back(std::move(sheared));
  out.push_back(std::move(perturbed));
  out.push_back(std::move(mixed));
  for (const auto& mesh : out) {
    int reversed = 0;
    for (int c = 0; c < mesh.n_cells(); ++c)
      for (int k = 0; k < mesh.cell_size(c); ++k) reversed += mesh.edge_sign(c, k) < 0;
    EXPECT_GT(reversed, mesh.n_cells());  // the test exercises the signs
  }
  return out;
}

}  // namespace

TEST(CondensedFactor, EqualsTheFactorOfTheAssembledMatrix) {
  std::mt19937 random(5);
  std::normal_distribution<double> normal;
  for (const auto& mesh : test_meshes()) {
    std::vector<int> degrees;
    for (int c = 0; c < mesh.n_cells(); ++c) degrees.push_back(1 + (c / 7) % 6);  // runs of equal degree
    const space::H1Space space(mesh, degrees);
    ASSERT_LT(space.n_skeleton_dofs(), space.n_dofs());
    const mesh::ContactBoundary contact(mesh);
    const auto boundary = mesh::BoundaryMesh::uniform(contact.length(), 4);
    const space::MultiplierSpace multipliers(boundary, 2);
    const linalg::Coupling b = assembly::assemble_coupling(space, contact, multipliers);
    const auto trace = linalg::nonzero_columns(b);
    const auto volume = assembly::assemble_volume_matrices(space, {.stiffness = true, .mass = true});
    for (const double mass_weight : {0.0, 1.0}) {
      const Eigen::MatrixXd a = Eigen::MatrixXd(volume.stiffness) + mass_weight * Eigen::MatrixXd(volume.mass);
      const Eigen::LLT<Eigen::MatrixXd> dense(a);
      const assembly::CondensedFactor factor(space, 1.0, mass_weight, trace);
      EXPECT_EQ(factor.n_skeleton(), space.n_skeleton_dofs());
      EXPECT_EQ(factor.n_trailing(), static_cast<int>(trace.size()));
      const Eigen::MatrixXd bt = Eigen::MatrixXd(b.transpose());
      EXPECT_LT(relative_difference(factor.schur_complement(b), Eigen::MatrixXd(b) * dense.solve(bt)), 1e-11);

      Eigen::VectorXd rhs(space.n_dofs());
      for (auto& value : rhs) value = normal(random);
      const Eigen::VectorXd u = factor.solve(rhs);
      EXPECT_LT(relative_difference(u, dense.solve(rhs)), 1e-11);
      EXPECT_NEAR(factor.quadratic_form(u), u.dot(a * u), 1e-12 * u.dot(a * u));

      // A B reaching interior modes (the last dof is one) takes the path by solves.
      linalg::Coupling b_interior = b;
      b_interior.coeffRef(0, space.n_dofs() - 1) = 1.0;
      const Eigen::MatrixXd bit = Eigen::MatrixXd(b_interior.transpose());
      EXPECT_LT(
          relative_difference(factor.schur_complement(b_interior), Eigen::MatrixXd(b_interior) * dense.solve(bit)),
          1e-11);
    }
  }
}

TEST(CondensedFactor, CongruentCellsShareOneElimination) {
  const auto meshes = test_meshes();
  // Sheared: every cell is the same parallelogram, whatever its edges' orientation.
  EXPECT_EQ(assembly::CondensedFactor(space::H1Space(meshes[0], 4), 1.0, 1.0).n_eliminations(), 1);
  // 12 × 12 cells of width 1/6, a width with no exact binary representation.
  const auto square = mesh::make_paper_square_mesh(12);
  EXPECT_EQ(assembly::CondensedFactor(space::H1Space(square, 3), 1.0, 0.0).n_eliminations(), 1);
  // Perturbed: no two cells alike.
  EXPECT_EQ(assembly::CondensedFactor(space::H1Space(meshes[1], 4), 1.0, 1.0).n_eliminations(), meshes[1].n_cells());
}

// A geometric mesh has similar parallelograms of different sizes (the centre cell of a star and
// the cells of the coarse mesh): they share K's element matrix but not M's, which scales with the
// area, so K + M must not share their elimination (it did, and α on graded meshes was off).
TEST(CondensedFactor, SimilarCellsOfDifferentSizesKeepTheirOwnMass) {
  const auto coarse = mesh::make_paper_square_mesh(4);
  const int corner = mesh::vertex_at(coarse, mesh::Point(-1.0, -1.0), "test");
  for (int layers : {2, 3}) {
    const auto graded = mesh::grade_towards_vertices(coarse, {corner}, 0.2, layers, "test");
    const space::H1Space space(graded, 3);
    const mesh::ContactBoundary contact(graded);
    const auto boundary = mesh::BoundaryMesh::uniform(contact.length(), 3);
    const space::MultiplierSpace multipliers(boundary, 1);
    const linalg::Coupling b = assembly::assemble_coupling(space, contact, multipliers);
    const auto volume = assembly::assemble_volume_matrices(space, {.stiffness = true, .mass = true});
    const Eigen::LLT<Eigen::MatrixXd> dense(Eigen::MatrixXd(volume.stiffness) + Eigen::MatrixXd(volume.mass));
    const assembly::CondensedFactor factor(space, 1.0, 1.0, linalg::nonzero_columns(b));
    const Eigen::MatrixXd bt = Eigen::MatrixXd(b.transpose());
    EXPECT_LT(relative_difference(factor.schur_complement(b), Eigen::MatrixXd(b) * dense.solve(bt)), 1e-11)
        << layers << " layers";
  }
}
