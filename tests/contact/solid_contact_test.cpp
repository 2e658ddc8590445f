// The scalar contact problems on hexahedral meshes against the planar ones: the §7 problems
// extruded in y (Neumann on the new sides, data independent of y) have the planar solution,
// constant in y, for every multiplier mesh of T_{C,H} = (planar segments) × (any grid in y), since
// the tensor nodal bounds are those of the planar problem times positive weights. So the energy
// is the planar energy times the width, and λ is the planar λ at every y for stable pairings.
#include "contact/solid_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "assembly/condensed_factor.hpp"
#include "assembly/solid_cell_system.hpp"
#include "assembly/solid_load.hpp"
#include "assembly/surface_coupling.hpp"
#include "core/error.hpp"
#include "mesh/contact_surface.hpp"
#include "space/surface_multiplier_space.hpp"
#include "support/contact_fixture.hpp"
#include "support/solid_meshes.hpp"

namespace hpcontact::contact {
namespace {

constexpr double kWidth = 0.5;

struct Case {
  ContactProblem problem;
  int n, p, pc, m, n_y, m_y;
  /// Whether the pairing is stable along y too, so that λ is unique: more multipliers along y
  /// than trace functions there leave λ undetermined (u and the energy stay unique).
  bool unique_lambda = true;
  unsigned shuffle = 0;  ///< see testing::extruded_paper_mesh
};

TEST(SolidContact, ExtrudedPaperProblemsHaveThePlanarSolution) {
  for (const Case& c :
       {Case{ContactProblem::signorini, 4, 2, 1, 2, 1, 1}, Case{ContactProblem::signorini, 4, 2, 1, 2, 3, 2},
        Case{ContactProblem::signorini, 4, 2, 1, 2, 2, 3, false},
        Case{ContactProblem::signorini, 4, 2, 1, 3, 2, 1},  // T_{C,H} across the trace faces in x
        Case{ContactProblem::signorini, 4, 3, 2, 4, 2, 1}, Case{ContactProblem::signorini, 6, 1, 0, 3, 2, 1},
        Case{ContactProblem::friction_s, 4, 2, 1, 4, 1, 2}, Case{ContactProblem::friction, 4, 3, 1, 2, 2, 1},
        Case{ContactProblem::signorini, 4, 3, 2, 4, 2, 1, true, 5},
        Case{ContactProblem::friction_s, 4, 3, 1, 3, 2, 1, true, 9}}) {
    const std::string label = ::testing::PrintToString(
        std::vector<int>{int(c.problem), c.n, c.p, c.pc, c.m, c.n_y, c.m_y, static_cast<int>(c.shuffle)});
    const ContactSolution planar = testing::solve_paper_contact(c.problem, c.n, c.p, c.pc, c.m);
    const mesh::SolidMesh mesh = testing::extruded_paper_mesh(c.n, c.n_y, kWidth, c.shuffle);
    const space::SolidH1Space space(mesh, std::vector<int>(mesh.n_cells(), c.p),
                                    space::faces_labelled(mesh, {"dirichlet"}));
    const mesh::FlatContactSurface surface(mesh, {"contact"}, "test");
    const mesh::SurfaceMultiplierMesh multiplier_mesh(surface, {c.m, c.m_y}, "test");
    const space::SurfaceMultiplierSpace multipliers(multiplier_mesh, c.pc);
    SolidContactSetup setup;
    setup.space = &space;
    setup.multipliers = &multipliers;
    setup.problem = c.problem;
    setup.f = [](const mesh::SolidPoint&) { return -1.0; };
    setup.obstacle = [](const mesh::SolidPoint& x) { return -x(0) * x(0); };
    setup.bound = [](const mesh::SolidPoint& x) { return (1.0 - x(0)) * (1.0 - x(0)); };
    const SolidContactSolution solid = solve_solid_contact(setup);
    EXPECT_TRUE(solid.qp.converged) << label;
    EXPECT_NEAR(solid.energy, kWidth * planar.energy, 1e-10 * std::abs(planar.energy)) << label;
    // The plane's in-plane axes: e_1 along x; λ at nodal point (i, j) of T_{C,H} cell (k, l) is the
    // planar λ at point i of segment k (the planar nodal points run with x as well).
    if (c.problem == ContactProblem::signorini && c.unique_lambda) {
      const int per = c.pc + 1;
      double worst = 0.0;
      for (int dof = 0; dof < multipliers.n_dofs(); ++dof) {
        const int cell = dof / (per * per), local = dof % (per * per);
        const int k = cell % c.m, i = local % per;
        worst = std::max(worst, std::abs(solid.lambda(dof) - planar.lambda(k * per + i)));
      }
      EXPECT_LT(worst, 1e-8 * planar.lambda.lpNorm<Eigen::Infinity>()) << label;
    }
    // KKT at the nodal points: bounds, and the gap (the dual gradient) pushing only against a
    // bound that holds λ.
    const double scale = solid.gap.lpNorm<Eigen::Infinity>() + 1.0;
    for (Eigen::Index i = 0; i < solid.lambda.size(); ++i) {
      EXPECT_LE(solid.lambda(i), solid.upper(i) + 1e-12) << label;
      EXPECT_GE(solid.lambda(i), solid.lower(i) - 1e-12) << label;
      const double to_upper = solid.upper(i) - solid.lambda(i), to_lower = solid.lambda(i) - solid.lower(i);
      EXPECT_LE(std::max(solid.gap(i), 0.0) * std::min(to_upper, 1e3), 1e-9 * scale) << label << " i " << i;
      EXPECT_LE(std::max(-solid.gap(i), 0.0) * std::min(to_lower, 1e3), 1e-9 * scale) << label << " i " << i;
    }
  }
}

TEST(SolidContact, ContactSurfacesAndMultiplierMeshesRejectBadInput) {
  const mesh::SolidMesh mesh = testing::extruded_paper_mesh(2, 1, kWidth);
  EXPECT_THROW(mesh::FlatContactSurface(mesh, {"nowhere"}, "scene.toml"), InputError);
  // Γ_C over two sides of the box is not flat.
  EXPECT_THROW(mesh::FlatContactSurface(mesh, {"contact", "x_min"}, "scene.toml"), InputError);
  const mesh::FlatContactSurface surface(mesh, {"contact"}, "scene.toml");
  EXPECT_THROW(mesh::SurfaceMultiplierMesh(surface, {0, 1}, "scene.toml"), InputError);
  // Three of the four bottom faces: an L, not its bounding rectangle.
  mesh::SolidMesh l_shape = testing::extruded_paper_mesh(2, 2, kWidth);
  l_shape.label_boundary_faces(
      [](const mesh::SolidPoint& x) { return x(2) < -1.0 + 1e-9 && x(0) > 0.0 && x(1) > 0.25; }, "z_min");
  const mesh::FlatContactSurface l_surface(l_shape, {"contact"}, "scene.toml");
  EXPECT_FALSE(l_surface.is_rectangle());
  EXPECT_THROW(mesh::SurfaceMultiplierMesh(l_surface, {2, 2}, "scene.toml"), InputError);
}

TEST(SolidContact, CouplingOnTriangleTraceFacesIsExactForPolynomials) {
  // u ∈ P_3 on Kuhn tetrahedra (renumbered), represented exactly by its L² projection; B u
  // (trace triangles clipped against T_{C,H}, shapes evaluated in the cells) must equal ∫ ℓ_i u
  // over the cells of T_{C,H} (u evaluated directly), on a grid that the triangles do not align with.
  std::vector<double> nodes{0.0, 0.3, 0.7, 1.0};
  const mesh::SolidMesh mesh = testing::shuffled(mesh::make_tetrahedral_box_mesh({nodes, nodes, nodes}, "box"), 4);
  const space::SolidH1Space space(mesh, std::vector<int>(mesh.n_cells(), 3), {});
  const auto u = [](const mesh::SolidPoint& x) {
    return 1.0 + x(0) - 2.0 * x(1) * x(1) + x(0) * x(1) * x(2) + x(1) * x(1) * x(1) + 0.5 * x(2);
  };
  const assembly::CondensedFactor mass(std::make_unique<assembly::SolidScalarCellSystem>(space, 0.0, 1.0));
  const Eigen::VectorXd coefficients = mass.solve(assembly::solid_load(space, u));
  for (const char* side : {"z_min", "x_max"}) {
    const mesh::FlatContactSurface surface(mesh, {side}, "box");
    EXPECT_NEAR(surface.area(), 1.0, 1e-14) << side;
    const mesh::SurfaceMultiplierMesh grid(surface, {3, 2}, "box");
    for (int pc : {0, 1, 2}) {
      const space::SurfaceMultiplierSpace multipliers(grid, pc);
      const Eigen::VectorXd traced = assembly::surface_coupling(space, multipliers) * coefficients;
      const Eigen::VectorXd direct = assembly::surface_multiplier_load(multipliers, u);
      EXPECT_LT((traced - direct).lpNorm<Eigen::Infinity>(), 1e-12 * direct.lpNorm<Eigen::Infinity>())
          << side << ", p_C = " << pc;
    }
  }
}

TEST(SolidContact, ClippingKeepsTheCommonPolygon) {
  // A diamond |x − ½| + |y − ½| ≤ ¾ clipped by the unit square: the square without its four corner
  // triangles of legs ¼, an octagon of area 1 − 4 · 1/32.
  const std::vector<Eigen::Vector2d> diamond{{0.5, -0.25}, {1.25, 0.5}, {0.5, 1.25}, {-0.25, 0.5}};
  const auto piece = mesh::clip_to_rectangle(diamond, Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1));
  ASSERT_EQ(piece.size(), 8U);
  double twice = 0.0;
  for (std::size_t k = 0; k < piece.size(); ++k)
    twice += piece[k](0) * piece[(k + 1) % piece.size()](1) - piece[k](1) * piece[(k + 1) % piece.size()](0);
  EXPECT_NEAR(0.5 * twice, 0.875, 1e-15);
  EXPECT_TRUE(mesh::clip_to_rectangle(diamond, Eigen::Vector2d(2, 2), Eigen::Vector2d(3, 3)).empty());
}

}  // namespace
}  // namespace hpcontact::contact
