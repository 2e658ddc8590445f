// The Poisson problem on solid meshes through static condensation: on hexahedra exactness for a
// Q_2 solution under every orientation of edges and faces and with mixed degrees (conformity),
// rates p in h for p = 1 … 4 on affine and distorted meshes, exponential convergence in p (on the
// box and on a Gmsh mesh of tetrahedra split into hexahedra); on tetrahedra the same for P_p.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>

#include "assembly/condensed_factor.hpp"
#include "assembly/solid_cell_system.hpp"
#include "assembly/solid_load.hpp"
#include "mesh/gmsh_solid_reader.hpp"
#include "postprocess/solid_errors.hpp"
#include "support/scratch.hpp"
#include "support/solid_meshes.hpp"

namespace hpcontact::assembly {
namespace {

const std::vector<std::string> kAllSides{"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};

struct Manufactured {
  std::function<double(const mesh::SolidPoint&)> u, f;
  std::function<Eigen::Vector3d(const mesh::SolidPoint&)> gradient;
};

/// u = 64 x(1 − x) y(1 − y) z(1 − z) ∈ Q_2 on the unit cube, zero on its boundary.
Manufactured bubble() {
  const auto q = [](double t) { return t * (1.0 - t); };
  const auto dq = [](double t) { return 1.0 - 2.0 * t; };
  return {
      [=](const mesh::SolidPoint& x) { return 64.0 * q(x(0)) * q(x(1)) * q(x(2)); },
      [=](const mesh::SolidPoint& x) { return 128.0 * (q(x(1)) * q(x(2)) + q(x(0)) * q(x(2)) + q(x(0)) * q(x(1))); },
      [=](const mesh::SolidPoint& x) {
        return Eigen::Vector3d(64.0 * dq(x(0)) * q(x(1)) * q(x(2)), 64.0 * q(x(0)) * dq(x(1)) * q(x(2)),
                               64.0 * q(x(0)) * q(x(1)) * dq(x(2)));
      }};
}

/// u = sin(πx) sin(πy) sin(πz), −Δu = 3π² u.
Manufactured sines() {
  return {
      [](const mesh::SolidPoint& x) { return std::sin(M_PI * x(0)) * std::sin(M_PI * x(1)) * std::sin(M_PI * x(2)); },
      [](const mesh::SolidPoint& x) {
        return 3.0 * M_PI * M_PI * std::sin(M_PI * x(0)) * std::sin(M_PI * x(1)) * std::sin(M_PI * x(2));
      },
      [](const mesh::SolidPoint& x) {
        const Eigen::Array3d s = (M_PI * x.array()).sin(), c = (M_PI * x.array()).cos();
        return Eigen::Vector3d(M_PI * c(0) * s(1) * s(2), M_PI * s(0) * c(1) * s(2), M_PI * s(0) * s(1) * c(2));
      }};
}

/// Solves −Δu = f, u = 0 on the boundary, and returns the relative errors (H¹ seminorm, L²).
std::pair<double, double> relative_errors(const space::SolidH1Space& space, const Manufactured& problem,
                                          int* eliminations = nullptr) {
  const CondensedFactor factor(std::make_unique<SolidScalarCellSystem>(space, 1.0, 0.0));
  if (eliminations != nullptr) *eliminations = factor.n_eliminations();
  const Eigen::VectorXd u = factor.solve(solid_load(space, problem.f));
  const postprocess::SolidErrors errors = postprocess::solid_errors(space, u, problem.u, problem.gradient);
  const postprocess::SolidErrors size =
      postprocess::solid_errors(space, Eigen::VectorXd::Zero(space.n_dofs()), problem.u, problem.gradient);
  return {errors.h1_semi / errors.exact_h1_semi, errors.l2 / size.l2};
}

/// Solves −Δu = f for the sines on `mesh` (Γ_D the faces labelled `walls`) at p = first … last and
/// expects each degree to divide the relative H¹ error by more than `factor`, the last error below
/// `final`, and, when `eliminations` ≥ 0, that many distinct eliminations (congruent cells share one).
void expect_exponential_in_p(const mesh::SolidMesh& mesh, const std::vector<std::string>& walls, int first, int last,
                             double factor, double final, int eliminations = -1) {
  double previous = INFINITY;
  for (int p = first; p <= last; ++p) {
    const space::SolidH1Space space(mesh, std::vector<int>(mesh.n_cells(), p), space::faces_labelled(mesh, walls));
    int made = 0;
    const double h1 = relative_errors(space, sines(), &made).first;
    std::printf("%d %s, p = %d: relative H1 error %.3e, %d eliminations\n", mesh.n_cells(),
                mesh.is_tetrahedral() ? "tetrahedra" : "hexahedra", p, h1, made);
    if (eliminations >= 0) EXPECT_EQ(made, eliminations) << "p = " << p;
    if (p > first) EXPECT_LT(h1, previous / factor) << "p = " << p;
    previous = h1;
  }
  EXPECT_LT(previous, final);
}

/// The unit cube meshed by Gmsh with `options`, its six faces the physical surface "wall".
mesh::SolidMesh gmsh_cube(const std::string& name, const std::string& options) {
  const auto geo = testing::scratch_root() / name;
  std::ofstream(geo) << "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n"
                     << options
                     << "\nPhysical Surface(\"wall\") = {1, 2, 3, 4, 5, 6};\nPhysical Volume(\"cube\") = {1};\n";
  return mesh::read_gmsh_solid_mesh(geo.string());
}

TEST(SolidPoisson, QuadraticSolutionIsExactUnderEveryOrientation) {
  const mesh::SolidMesh box = mesh::make_box_mesh(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), {3, 3, 3});
  // p = 2 checks the numbering under shuffling (mode (2, 2) is the same under a swap and every
  // sign is +1); p = 3 the signs of reversed edges and faces ((−1)^k) and the swapped face modes
  // (2, 3) and (3, 2).
  for (int p : {2, 3})
    for (unsigned seed : {1U, 2U, 3U}) {
      const mesh::SolidMesh mesh = testing::shuffled(box, seed);
      const space::SolidH1Space space(mesh, std::vector<int>(mesh.n_cells(), p),
                                      space::faces_labelled(mesh, kAllSides));
      const auto [h1, l2] = relative_errors(space, bubble());
      EXPECT_LT(h1, 1e-12) << "p = " << p << ", seed " << seed;
      EXPECT_LT(l2, 1e-12) << "p = " << p << ", seed " << seed;
    }
}

TEST(SolidPoisson, MixedDegreesStayConforming) {
  // Degrees 2 … 4 at random: edges and faces carry the smallest of their cells' (minimum rule),
  // so the Q_2 solution is still in the space, and a sign error on any shared mode would lose it.
  const mesh::SolidMesh mesh =
      testing::shuffled(mesh::make_box_mesh(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), {3, 3, 3}), 11);
  std::mt19937 random(5);
  std::vector<int> degrees(mesh.n_cells());
  for (int& degree : degrees) degree = 2 + static_cast<int>(random() % 3);
  const space::SolidH1Space space(mesh, degrees, space::faces_labelled(mesh, kAllSides));
  const auto [h1, l2] = relative_errors(space, bubble());
  EXPECT_LT(h1, 1e-12);
  EXPECT_LT(l2, 1e-12);
}

TEST(SolidPoisson, RatesArePInH) {
  for (bool distorted : {false, true})
    for (int p = 1; p <= 4; ++p) {
      // Two meshes in the asymptotic range: the H¹ error falls like h^p, the L² error like h^(p+1).
      const int coarse = p == 1 ? 6 : (p == 2 ? 4 : 3);
      std::array<std::pair<double, double>, 2> errors;
      for (int level = 0; level < 2; ++level) {
        const int n = coarse * (level + 1);
        const mesh::SolidMesh mesh =
            distorted ? testing::distorted_unit_cube(n, 0.05)
                      : mesh::make_box_mesh(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), {n, n, n});
        const space::SolidH1Space space(mesh, std::vector<int>(mesh.n_cells(), p),
                                        space::faces_labelled(mesh, kAllSides));
        errors[level] = relative_errors(space, sines());
      }
      const double h1_rate = std::log2(errors[0].first / errors[1].first);
      const double l2_rate = std::log2(errors[0].second / errors[1].second);
      std::printf("%s p = %d: H1 rate %.3f, L2 rate %.3f\n", distorted ? "distorted" : "box", p, h1_rate, l2_rate);
      EXPECT_NEAR(h1_rate, p, 0.15) << "p = " << p << (distorted ? " distorted" : " box");
      EXPECT_NEAR(l2_rate, p + 1, 0.3) << "p = " << p << (distorted ? " distorted" : " box");
    }
}

TEST(SolidPoisson, ConvergesExponentiallyInPAndEliminatesOnceOnABox) {
  // Each degree gains at least a factor 2.5 here (sin is entire; the factor grows with p).
  expect_exponential_in_p(mesh::make_box_mesh(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), {2, 2, 2}), kAllSides,
                          2, 7, 2.5, 1e-5, 1);
}

TEST(SolidPoisson, ConvergesExponentiallyInPOnAGmshMeshOfHexahedra) {
  // Gmsh's tetrahedra of the unit cube, each split into four hexahedra: trilinear, far from
  // parallelepipeds, in every orientation (each degree gains a factor 8 to 12 here).
  expect_exponential_in_p(
      gmsh_cube("poisson_cube.geo", "Mesh.SubdivisionAlgorithm = 2;\nMeshSize{ PointsOf{ Volume{1}; } } = 0.6;"),
      {"wall"}, 1, 4, 5.0, 1e-3);
}

/// The unit cube in n³ cubes of six tetrahedra each (mesh::make_tetrahedral_box_mesh).
mesh::SolidMesh tetrahedral_cube(int n) {
  std::vector<double> nodes;
  for (int i = 0; i <= n; ++i) nodes.push_back(static_cast<double>(i) / n);
  return mesh::make_tetrahedral_box_mesh({nodes, nodes, nodes}, "tetrahedral cube");
}

TEST(SolidPoisson, SexticSolutionIsExactOnTetrahedraUnderEveryVertexOrder) {
  // The bubble has total degree 6: in P_6 on every tetrahedron. Renumbered vertices give every
  // order of each cell's vertices (the face modes' order, the Jacobian's sign); random degrees
  // 6 … 7 check the minimum rule on edges and faces.
  const mesh::SolidMesh cube = tetrahedral_cube(2);
  for (unsigned seed : {1U, 2U}) {
    const mesh::SolidMesh mesh = testing::shuffled(cube, seed);
    std::mt19937 random(seed);
    std::vector<int> degrees(mesh.n_cells(), 6);
    if (seed == 2U)
      for (int& degree : degrees) degree = 6 + static_cast<int>(random() % 2);
    const space::SolidH1Space space(mesh, degrees, space::faces_labelled(mesh, kAllSides));
    const auto [h1, l2] = relative_errors(space, bubble());
    EXPECT_LT(h1, 1e-11) << "seed " << seed;
    EXPECT_LT(l2, 1e-11) << "seed " << seed;
  }
  // Below degree 6 it is not in the space.
  const space::SolidH1Space p5(cube, std::vector<int>(cube.n_cells(), 5), space::faces_labelled(cube, kAllSides));
  EXPECT_GT(relative_errors(p5, bubble()).first, 1e-4);
}

TEST(SolidPoisson, RatesArePInHOnTetrahedra) {
  for (int p = 1; p <= 4; ++p) {
    const int coarse = p == 1 ? 6 : (p == 2 ? 4 : 3);
    std::array<std::pair<double, double>, 2> errors;
    for (int level = 0; level < 2; ++level) {
      const mesh::SolidMesh mesh = testing::shuffled(tetrahedral_cube(coarse * (level + 1)), 7);
      const space::SolidH1Space space(mesh, std::vector<int>(mesh.n_cells(), p),
                                      space::faces_labelled(mesh, kAllSides));
      errors[level] = relative_errors(space, sines());
    }
    const double h1_rate = std::log2(errors[0].first / errors[1].first);
    const double l2_rate = std::log2(errors[0].second / errors[1].second);
    std::printf("tetrahedra p = %d: H1 error %.3e then %.3e (rate %.3f), L2 rate %.3f\n", p, errors[0].first,
                errors[1].first, h1_rate, l2_rate);
    EXPECT_NEAR(h1_rate, p, 0.2) << "p = " << p;
    EXPECT_NEAR(l2_rate, p + 1, 0.35) << "p = " << p;
  }
}

TEST(SolidPoisson, ConvergesExponentiallyInPOnTetrahedra) {
  // Congruent cells share one elimination: the six tetrahedra of Kuhn's cube, each in one vertex
  // order in every cube (vertices numbered x fastest). Each degree gains a factor 3.5 to 7.6 here,
  // growing with p.
  expect_exponential_in_p(tetrahedral_cube(2), kAllSides, 2, 8, 3.0, 3e-5, 6);
}

TEST(SolidPoisson, ConvergesExponentiallyInPOnAGmshMeshOfTetrahedra) {
  // Gmsh's 1111 Delaunay tetrahedra of the unit cube: unstructured, in every vertex order (each
  // degree gains a factor 7.5 to 13 here). On the coarser 184 tetrahedra of size 0.35 the odd
  // degrees gain more than the even ones: factors 3.3, 9.2, 3.0, 22 from p = 1 to 5.
  const mesh::SolidMesh mesh = gmsh_cube("poisson_tetrahedra.geo", "MeshSize{ PointsOf{ Volume{1}; } } = 0.175;");
  ASSERT_TRUE(mesh.is_tetrahedral());
  expect_exponential_in_p(mesh, {"wall"}, 1, 4, 5.0, 1e-3);
}

TEST(SolidPoisson, SpaceRejectsBadInput) {
  const mesh::SolidMesh mesh = mesh::make_box_mesh(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), {2, 2, 2});
  EXPECT_THROW(space::SolidH1Space(mesh, std::vector<int>(7, 2), {}), InputError);
  EXPECT_THROW(space::SolidH1Space(mesh, std::vector<int>(8, 0), {}), InputError);
  std::vector<char> inner(mesh.n_faces(), 0);
  for (int f = 0; f < mesh.n_faces(); ++f)
    if (!mesh.is_boundary_face(f)) inner[f] = 1;
  EXPECT_THROW(space::SolidH1Space(mesh, std::vector<int>(8, 2), inner), InputError);
}

}  // namespace
}  // namespace hpcontact::assembly
