// T_{C,H} of triangles on a flat Γ_C of a hexahedral mesh, against the grid T_{C,H}: a multiplier
// that both spaces hold (a constant for p_C = 0, an affine function for p_C = 1) has the same
// coupling row sums cᵀB = ∫ μ φ_j and the same load ∫ μ g, on triangles that cut across the trace
// faces; the clipped overlaps tile Γ_C; a triangle mesh that misses part of Γ_C, covers part of it
// twice, leaves its plane or has a flat triangle is refused; an L-shaped Γ_C takes triangles; the Signorini problem (9)
// solved on triangles satisfies its KKT conditions at the vertices.
#include <gtest/gtest.h>

#include <cmath>

#include "assembly/surface_coupling.hpp"
#include "contact/solid_contact.hpp"
#include "core/error.hpp"
#include "mesh/contact_surface.hpp"
#include "support/solid_meshes.hpp"

namespace hpcontact::assembly {
namespace {

/// The k × k squares of [x0, x1] × [y0, y1] at height z, each cut along a diagonal (alternating),
/// interior vertices moved by up to `shift` of a square: triangles that do not follow the faces.
struct Triangulation {
  std::vector<mesh::SolidPoint> vertices;
  std::vector<std::array<int, 3>> triangles;
};
Triangulation triangulate(double x0, double x1, double y0, double y1, double z, int k, double shift) {
  Triangulation t;
  for (int j = 0; j <= k; ++j)
    for (int i = 0; i <= k; ++i) {
      const bool inner = i > 0 && i < k && j > 0 && j < k;
      const double dx = inner ? shift * std::sin(3.1 * i + 1.7 * j) : 0.0,
                   dy = inner ? shift * std::cos(2.3 * i * j) : 0.0;
      t.vertices.emplace_back(x0 + (i + dx) * (x1 - x0) / k, y0 + (j + dy) * (y1 - y0) / k, z);
    }
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) {
      const int a = i + (k + 1) * j, b = a + 1, c = a + k + 1, d = c + 1;
      if ((i + j) % 2 == 0) {
        t.triangles.push_back({a, b, d});
        t.triangles.push_back({a, d, c});
      } else {
        t.triangles.push_back({a, b, c});
        t.triangles.push_back({b, d, c});  // (clockwise: either orientation is taken)
      }
    }
  return t;
}

struct Fixture {
  mesh::SolidMesh box = mesh::make_box_mesh(Eigen::Vector3d::Zero(), Eigen::Vector3d(1.0, 0.8, 0.5), {3, 4, 2});
  space::SolidH1Space space{box, std::vector<int>(box.n_cells(), 3), {}};
  mesh::FlatContactSurface surface{box, {"z_max"}, "test"};
};

TEST(TriangleMultipliers, CouplingAndLoadOfSharedFunctionsEqualTheGrids) {
  const Fixture f;
  const Triangulation t = triangulate(0.0, 1.0, 0.0, 0.8, 0.5, 5, 0.3);
  const mesh::SurfaceMultiplierMesh triangles(f.surface, t.vertices, t.triangles, "test");
  const mesh::SurfaceMultiplierMesh grid(f.surface, {2, 3}, "test");
  double area = 0.0;
  for (const auto& overlap : triangles.overlaps())
    for (std::size_t k = 1; k + 1 < overlap.polygon.size(); ++k) {
      const Eigen::Vector2d e1 = overlap.polygon[k] - overlap.polygon[0],
                            e2 = overlap.polygon[k + 1] - overlap.polygon[0];
      area += 0.5 * (e1(0) * e2(1) - e1(1) * e2(0));
    }
  EXPECT_NEAR(area, 0.8, 1e-14);
  const SolidFunction g = [](const mesh::SolidPoint& x) { return x(0) * x(0) * x(1) + 1.0; };
  for (int pc : {0, 1}) {
    const SolidFunction mu = [pc](const mesh::SolidPoint& x) { return pc == 0 ? 1.7 : 0.4 + 2.0 * x(0) - 1.3 * x(1); };
    const space::SurfaceMultiplierSpace on_triangles(triangles, pc), on_grid(grid, pc);
    EXPECT_EQ(on_triangles.n_dofs(), static_cast<int>(t.triangles.size()) * (pc == 0 ? 1 : 3));
    const auto coefficients = [&](const space::SurfaceMultiplierSpace& m) {
      Eigen::VectorXd c(m.n_dofs());
      for (int dof = 0; dof < m.n_dofs(); ++dof) c(dof) = mu(f.surface.from_plane(m.nodal_point(dof)));
      return c;
    };
    const Eigen::VectorXd a = coefficients(on_triangles), b = coefficients(on_grid);
    const Eigen::VectorXd rows_triangles = surface_coupling(f.space, on_triangles, {}).transpose() * a;
    const Eigen::VectorXd rows_grid = surface_coupling(f.space, on_grid, {}).transpose() * b;
    EXPECT_LT((rows_triangles - rows_grid).lpNorm<Eigen::Infinity>(), 1e-13 * rows_grid.lpNorm<Eigen::Infinity>())
        << "p_C " << pc;
    EXPECT_GT(rows_grid.lpNorm<Eigen::Infinity>(), 1e-3);
    const double load_triangles = a.dot(surface_multiplier_load(on_triangles, g));
    EXPECT_NEAR(load_triangles, b.dot(surface_multiplier_load(on_grid, g)), 1e-13) << "p_C " << pc;
    // (every basis function on a triangle has a positive integral: nonnegative coefficients are a cone of nonnegative
    // means)
    const Eigen::VectorXd integrals =
        surface_multiplier_load(on_triangles, [](const mesh::SolidPoint&) { return 1.0; });
    EXPECT_GT(integrals.minCoeff(), 0.0);
    EXPECT_NEAR(integrals.sum(), 0.8, 1e-14);
  }
  EXPECT_THROW(space::SurfaceMultiplierSpace(triangles, 2), InputError);
}

TEST(TriangleMultipliers, MeshesThatDoNotCoverTheSurfaceOnceAreRefused) {
  const Fixture f;
  const Triangulation half = triangulate(0.0, 0.5, 0.0, 0.8, 0.5, 2, 0.0);
  EXPECT_THROW(mesh::SurfaceMultiplierMesh(f.surface, half.vertices, half.triangles, "test"), InputError);
  Triangulation twice = triangulate(0.0, 1.0, 0.0, 0.8, 0.5, 2, 0.0);
  twice.triangles.push_back(twice.triangles.front());
  EXPECT_THROW(mesh::SurfaceMultiplierMesh(f.surface, twice.vertices, twice.triangles, "test"), InputError);
  // (the right area, all inside Γ_C, but overlapping each other over what they leave bare)
  const std::vector<mesh::SolidPoint> corners{{0, 0, 0.5}, {1, 0, 0.5}, {1, 0.8, 0.5}, {0, 0.8, 0.5}};
  EXPECT_THROW(mesh::SurfaceMultiplierMesh(f.surface, corners, {{0, 1, 2}, {1, 2, 3}}, "test"), InputError);
  EXPECT_NO_THROW(mesh::SurfaceMultiplierMesh(f.surface, corners, {{0, 1, 2}, {0, 2, 3}}, "test"));
  Triangulation lifted = triangulate(0.0, 1.0, 0.0, 0.8, 0.5, 2, 0.0);
  lifted.vertices[4](2) += 0.01;
  EXPECT_THROW(mesh::SurfaceMultiplierMesh(f.surface, lifted.vertices, lifted.triangles, "test"), InputError);
  Triangulation flat = triangulate(0.0, 1.0, 0.0, 0.8, 0.5, 2, 0.0);
  flat.triangles.push_back({0, 1, 2});  // three vertices on the edge y = 0
  EXPECT_THROW(mesh::SurfaceMultiplierMesh(f.surface, flat.vertices, flat.triangles, "test"), InputError);
}

TEST(TriangleMultipliers, AnLShapedSurfaceTakesTheTrianglesThatCoverIt) {
  mesh::SolidMesh box = mesh::make_box_mesh(Eigen::Vector3d::Zero(), Eigen::Vector3d(1.0, 0.8, 0.5), {3, 4, 2});
  const auto on_l = [](const mesh::SolidPoint& x) { return x(2) > 0.5 - 1e-9 && (x(0) < 2.0 / 3.0 || x(1) < 0.4); };
  box.label_boundary_faces(on_l, "contact");
  const mesh::FlatContactSurface surface(box, {"contact"}, "test");
  EXPECT_NEAR(surface.area(), 0.8 - 0.4 / 3.0, 1e-14);
  EXPECT_THROW(mesh::SurfaceMultiplierMesh(surface, {2, 2}, "test"), InputError);  // (a grid needs a rectangle)
  const Triangulation full = triangulate(0.0, 1.0, 0.0, 0.8, 0.5, 6, 0.0);
  EXPECT_THROW(mesh::SurfaceMultiplierMesh(surface, full.vertices, full.triangles, "test"), InputError);
  Triangulation l = full;
  l.triangles.clear();
  for (const auto& t : full.triangles) {
    const mesh::SolidPoint centre = (full.vertices[t[0]] + full.vertices[t[1]] + full.vertices[t[2]]) / 3.0;
    if (on_l(centre)) l.triangles.push_back(t);
  }
  const mesh::SurfaceMultiplierMesh triangles(surface, l.vertices, l.triangles, "test");
  const space::SurfaceMultiplierSpace multipliers(triangles, 1);
  const Eigen::VectorXd integrals = surface_multiplier_load(multipliers, [](const mesh::SolidPoint&) { return 1.0; });
  EXPECT_NEAR(integrals.sum(), surface.area(), 1e-14);
  EXPECT_EQ(triangles.n_cells(), 72 - 12);  // (6 × 6 squares less 2 × 3 of them, two triangles each)
}

TEST(TriangleMultipliers, ClippingTwoConvexPolygons) {
  const std::vector<Eigen::Vector2d> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  // |x − ½| + |y − ½| ≤ ¾: the square less four corner triangles of legs ¼, in either order
  const std::vector<Eigen::Vector2d> diamond{{0.5, -0.25}, {1.25, 0.5}, {0.5, 1.25}, {-0.25, 0.5}};
  const auto area = [](const std::vector<Eigen::Vector2d>& piece) {
    double twice = 0.0;
    for (std::size_t k = 0; k < piece.size(); ++k)
      twice += piece[k](0) * piece[(k + 1) % piece.size()](1) - piece[(k + 1) % piece.size()](0) * piece[k](1);
    return 0.5 * twice;
  };
  EXPECT_NEAR(area(mesh::clip_convex(diamond, square)), 0.875, 1e-15);
  EXPECT_NEAR(area(mesh::clip_convex(square, diamond)), 0.875, 1e-15);
  EXPECT_EQ(mesh::clip_convex(square, diamond).size(), 8u);
  EXPECT_TRUE(mesh::clip_convex(diamond, {{2, 2}, {3, 2}, {3, 3}}).empty());
}

TEST(TriangleMultipliers, SignoriniOnTrianglesMeetsItsKktConditions) {
  const mesh::SolidMesh box = testing::extruded_paper_mesh(4, 2, 0.5);
  const space::SolidH1Space space(box, std::vector<int>(box.n_cells(), 2), space::faces_labelled(box, {"dirichlet"}));
  const mesh::FlatContactSurface surface(box, {"contact"}, "test");
  const Triangulation t = triangulate(-1.0, 1.0, 0.0, 0.5, -1.0, 3, 0.2);
  const mesh::SurfaceMultiplierMesh triangles(surface, t.vertices, t.triangles, "test");
  const space::SurfaceMultiplierSpace multipliers(triangles, 1);
  contact::SolidContactSetup setup;
  setup.space = &space;
  setup.multipliers = &multipliers;
  setup.problem = contact::ContactProblem::signorini;
  setup.f = [](const mesh::SolidPoint&) { return -1.0; };
  setup.obstacle = [](const mesh::SolidPoint& x) { return -x(0) * x(0); };
  const contact::SolidContactSolution solved = contact::solve_solid_contact(setup);
  ASSERT_TRUE(solved.qp.converged);
  const double scale = solved.gap.lpNorm<Eigen::Infinity>() + 1.0;
  int active = 0;
  for (Eigen::Index i = 0; i < solved.lambda.size(); ++i) {
    // λ within its bounds, the dual gradient −(Sλ − d) pushing only against a bound that holds λ
    EXPECT_LE(solved.lambda(i), solved.upper(i) + 1e-12);
    EXPECT_GE(solved.lambda(i), solved.lower(i) - 1e-12);
    const double to_upper = solved.upper(i) - solved.lambda(i), to_lower = solved.lambda(i) - solved.lower(i);
    EXPECT_LE(std::max(solved.gap(i), 0.0) * std::min(to_upper, 1e3), 1e-9 * scale);
    EXPECT_LE(std::max(-solved.gap(i), 0.0) * std::min(to_lower, 1e3), 1e-9 * scale);
    active += std::abs(solved.lambda(i)) > 1e-10 ? 1 : 0;
  }
  EXPECT_GT(active, 0);
  EXPECT_LT(active, solved.lambda.size());
}

}  // namespace
}  // namespace hpcontact::assembly
