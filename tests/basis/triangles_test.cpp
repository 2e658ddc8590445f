// Triangles and mixed meshes: the triangle basis (edge traces equal to the square's Lobatto
// functions, exact gradients, a basis of P_p with conditioning measured against Q_p), the collapsed
// quadrature rule, triangle cell maps and refinement, conformity across triangle–quadrilateral
// edges with mixed degrees, convergence against an exact solution (rate p in h, exponential in p),
// the §7 Signorini problem on a Gmsh triangle mesh against the quadrilateral mesh, the Gmsh
// reader and scene keys for triangles, and triangles with curved sides (exact arcs, exponential
// convergence, the tutorial's arch scene).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>

#include "assembly/cell_values.hpp"
#include "assembly/element_matrices.hpp"
#include "basis/lobatto.hpp"
#include "basis/quadrature.hpp"
#include "basis/triangle_basis.hpp"
#include "core/error.hpp"
#include "driver/scene_run.hpp"
#include "mesh/cell_map.hpp"
#include "mesh/gmsh_reader.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "mesh/refine.hpp"
#include "operators/poisson_problem.hpp"
#include "postprocess/error_norms.hpp"
#include "postprocess/fe_function.hpp"
#include "scene/scene_mesh.hpp"
#include "scene/scene_reader.hpp"
#include "space/h1_space.hpp"
#include "support/curved_convergence_check.hpp"
#include "support/manufactured_solution.hpp"
#include "support/scratch.hpp"

using namespace hpcontact;
using mesh::CellType;
using mesh::Point;
using ::testing::HasSubstr;

namespace {

const std::string kTriangles = std::string(HPCONTACT_SOURCE_DIR) + "/studies/triangles/";

// Every shape of degree p on the reference triangle at (ξ, η), in the order vertices, edges
// (mode 2…p each), bubbles.
std::vector<basis::ShapeValue> all_shapes(int p, double xi, double eta) {
  const basis::TriangleShapes shapes(p, xi, eta);
  std::vector<basis::ShapeValue> out;
  for (int v = 0; v < 3; ++v) out.push_back(shapes.vertex(v));
  for (int e = 0; e < 3; ++e)
    for (int k = 2; k <= p; ++k) out.push_back(shapes.edge(e, k));
  for (int n1 = 0; n1 <= p - 3; ++n1)
    for (int n2 = 0; n1 + n2 <= p - 3; ++n2) out.push_back(shapes.bubble(n1, n2));
  return out;
}

// Condition number of the Jacobi-scaled (unit diagonal) symmetric positive definite matrix.
double scaled_condition(const Eigen::MatrixXd& a) {
  const Eigen::VectorXd d = a.diagonal().cwiseSqrt().cwiseInverse();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(d.asDiagonal() * a * d.asDiagonal());
  return eigen.eigenvalues().maxCoeff() / eigen.eigenvalues().minCoeff();
}

// The Poisson problem of the manufactured solution on `m` (Γ_D of §7 marked), its error norms.
postprocess::ErrorNorms manufactured_errors(const mesh::Mesh& m, int p) {
  const space::H1Space s(m, p);
  operators::PoissonData data{
      hpcontact::testing::manufactured_f,
      [](const Point& x, const Point& normal) { return hpcontact::testing::manufactured_gradient(x).dot(normal); },
      {}};
  return postprocess::compute_errors(s, operators::solve_poisson(s, data).coefficients,
                                     {hpcontact::testing::manufactured_u, hpcontact::testing::manufactured_gradient});
}

// The §7 square of n × n cells cut into triangles.
mesh::Mesh triangle_square(int n) { return mesh::split_into_triangles(mesh::make_paper_square_mesh(n)); }

}  // namespace

TEST(TriangleBasis, EdgeModesTraceTheLobattoFunctionsAndVanishElsewhere) {
  const int p = 9;
  Eigen::VectorXd lobatto(p + 1), derivative(p + 1);
  for (double t : {-0.93, -0.4, 0.0, 0.27, 0.81}) {
    basis::lobatto_values(p, t, lobatto, derivative);
    for (int edge = 0; edge < 3; ++edge) {
      const Eigen::Vector2d at = mesh::local_edge_point(CellType::triangle, edge, t);
      const basis::TriangleShapes shapes(p, at.x(), at.y());
      const auto [start, end] = mesh::local_edge_vertices(CellType::triangle, edge);
      EXPECT_NEAR(shapes.vertex(start).value, lobatto(0), 1e-15);
      EXPECT_NEAR(shapes.vertex(end).value, lobatto(1), 1e-15);
      EXPECT_NEAR(shapes.vertex(3 - start - end).value, 0.0, 1e-15);
      for (int k = 2; k <= p; ++k)
        for (int other = 0; other < 3; ++other)
          EXPECT_NEAR(shapes.edge(other, k).value, other == edge ? lobatto(k) : 0.0, 2e-14)
              << "edge " << other << " mode " << k << " on edge " << edge << " at t = " << t;
      for (int n1 = 0; n1 <= p - 3; ++n1)
        for (int n2 = 0; n1 + n2 <= p - 3; ++n2) EXPECT_NEAR(shapes.bubble(n1, n2).value, 0.0, 1e-15);
    }
  }
}

TEST(TriangleBasis, GradientsEqualCentralDifferences) {
  const int p = 12;
  const double step = 1e-6;
  for (const auto& [xi, eta] : {std::pair{-0.7, -0.2}, std::pair{0.1, -0.95}, std::pair{-0.3, 0.25}}) {
    const auto at = all_shapes(p, xi, eta);
    const auto right = all_shapes(p, xi + step, eta), left = all_shapes(p, xi - step, eta);
    const auto up = all_shapes(p, xi, eta + step), down = all_shapes(p, xi, eta - step);
    ASSERT_EQ(static_cast<int>(at.size()), basis::triangle_shape_count(p));
    for (std::size_t s = 0; s < at.size(); ++s) {
      const double scale = 1.0 + std::abs(at[s].d_xi) + std::abs(at[s].d_eta);
      EXPECT_NEAR(at[s].d_xi, (right[s].value - left[s].value) / (2 * step), 1e-7 * scale) << "shape " << s;
      EXPECT_NEAR(at[s].d_eta, (up[s].value - down[s].value) / (2 * step), 1e-7 * scale) << "shape " << s;
    }
  }
}

// The (p+1)(p+2)/2 shapes are linearly independent (so a basis of P_p), and the Jacobi-scaled
// reference stiffness + mass matrix stays as well conditioned as the square's Lobatto basis of Q_p
// (same p) up to p = 16; the numbers are printed for docs/triangles.md.
TEST(TriangleBasis, IsABasisOfPpConditionedLikeTheSquaresBasis) {
  for (int p : {2, 4, 8, 12, 16}) {
    const auto& rule = basis::collapsed_triangle_rule(p + 2);
    const int n = basis::triangle_shape_count(p);
    Eigen::MatrixXd values(rule.weights.size(), n), dx(rule.weights.size(), n), dy(rule.weights.size(), n);
    for (std::size_t q = 0; q < rule.weights.size(); ++q) {
      const auto shapes = all_shapes(p, rule.xi[q], rule.eta[q]);
      for (int s = 0; s < n; ++s) {
        values(q, s) = shapes[s].value;
        dx(q, s) = shapes[s].d_xi;
        dy(q, s) = shapes[s].d_eta;
      }
    }
    const Eigen::VectorXd w = Eigen::Map<const Eigen::VectorXd>(rule.weights.data(), rule.weights.size());
    const Eigen::MatrixXd mass = values.transpose() * w.asDiagonal() * values;
    const Eigen::MatrixXd triangle = mass + dx.transpose() * w.asDiagonal() * dx + dy.transpose() * w.asDiagonal() * dy;

    const auto square_mesh = mesh::make_rectangle_mesh({}, 1, 1);
    const space::H1Space square_space(square_mesh, std::vector<int>{p}, space::DirichletDofs::kept);
    assembly::ElementMatrices element(square_space);
    Eigen::MatrixXd stiffness, square_mass;
    element.compute(0, &stiffness, &square_mass);
    const double triangle_condition = scaled_condition(triangle),
                 square_condition = scaled_condition(stiffness + square_mass);
    std::cout << "p = " << p << ": scaled condition of K + M, triangle " << triangle_condition << ", square "
              << square_condition << "\n";
    EXPECT_TRUE(std::isfinite(triangle_condition));
    EXPECT_LT(triangle_condition, 10.0 * square_condition) << "p = " << p;
  }
}

TEST(CollapsedRule, IntegratesTotalDegree2nMinus2Exactly) {
  // ∫ over the reference triangle of ξ^a η^b, through x = (1+ξ)/2, y = (1+η)/2 and
  // ∫_{x,y ≥ 0, x+y ≤ 1} x^i y^j = i! j! / (i + j + 2)!.
  auto exact = [](int a, int b) {
    double sum = 0.0;
    for (int i = 0; i <= a; ++i)
      for (int j = 0; j <= b; ++j)
        sum += std::tgamma(a + 1.0) / (std::tgamma(i + 1.0) * std::tgamma(a - i + 1.0)) * std::pow(2.0, i) *
               std::pow(-1.0, a - i) * std::tgamma(b + 1.0) / (std::tgamma(j + 1.0) * std::tgamma(b - j + 1.0)) *
               std::pow(2.0, j) * std::pow(-1.0, b - j) * std::tgamma(i + 1.0) * std::tgamma(j + 1.0) /
               std::tgamma(i + j + 3.0);
    return 4.0 * sum;
  };
  for (int n : {1, 3, 6}) {
    const auto& rule = basis::collapsed_triangle_rule(n);
    for (int a = 0; a <= 2 * n - 2; ++a)
      for (int b = 0; a + b <= 2 * n - 2; ++b) {
        double sum = 0.0;
        for (std::size_t q = 0; q < rule.weights.size(); ++q)
          sum += rule.weights[q] * std::pow(rule.xi[q], a) * std::pow(rule.eta[q], b);
        EXPECT_NEAR(sum, exact(a, b), 1e-13) << "n = " << n << ", ξ^" << a << " η^" << b;
      }
  }
}

TEST(TriangleMesh, MapsInvertsRefinesAndKeepsBoundaryLabels) {
  auto m = mesh::split_into_triangles(mesh::make_paper_square_mesh(4), [](int c) { return c % 2 == 0; });
  mesh::perturb_interior_vertices(m, 0.1, 3);
  ASSERT_TRUE(m.has_triangles());
  EXPECT_EQ(m.n_cells(), 16 + 8);
  const auto fine = mesh::refine_uniformly(mesh::refine_uniformly(m));
  EXPECT_EQ(fine.n_cells(), 16 * m.n_cells());
  for (const mesh::Mesh* mesh : std::vector<const mesh::Mesh*>{&m, &fine}) {
    double area = 0.0;
    for (int c = 0; c < mesh->n_cells(); ++c) {
      const mesh::CellMap map(*mesh, c);
      const auto rule = assembly::cell_quadrature(mesh->cell_type(c), 3);
      for (int q = 0; q < rule.points.size(); ++q)
        area += rule.weights[q] * map.jacobian(rule.points.xi[q], rule.points.eta[q]).determinant();
      // The inverse map finds an interior point and refuses one beyond the hypotenuse.
      const Eigen::Vector2d inside = mesh::reference_centre(mesh->cell_type(c));
      const auto found = map.inverse(map.map(inside.x(), inside.y()));
      ASSERT_TRUE(found);
      EXPECT_LT((*found - inside).norm(), 1e-12);
      if (mesh->cell_type(c) == CellType::triangle) {
        EXPECT_FALSE(map.inverse(map.map(0.3, 0.3)));
      }
    }
    EXPECT_NEAR(area, 4.0, 1e-13);
    double contact_length = 0.0;
    for (int e : mesh->boundary_edges()) {
      const Point middle = mesh->edge_midpoint(e), outward = mesh->boundary_normal(e, 0.0);
      // Outward: a step along the normal leaves the square.
      EXPECT_GT((middle + 0.01 * outward).cwiseAbs().maxCoeff(), 1.0);
      if (mesh->edge_part(e) == mesh::BoundaryPart::contact) contact_length += mesh->edge_length(e);
    }
    EXPECT_NEAR(contact_length, 2.0, 1e-14);
  }
  EXPECT_THROW(mesh::Mesh({Point(0, 0), Point(1, 0), Point(0, 1)}, {{0, 2, 1, -1}}, "clockwise"), InputError);
}

TEST(TriangleSpace, ConformingAcrossTriangleAndQuadrilateralEdgesWithMixedDegrees) {
  auto m = mesh::split_into_triangles(mesh::make_paper_square_mesh(6), [](int c) { return (c * 7) % 3 != 0; });
  mesh::perturb_interior_vertices(m, 0.15, 5);
  std::mt19937 generator(17);
  std::vector<int> degrees(m.n_cells());
  for (int& p : degrees) p = std::uniform_int_distribution<int>(1, 8)(generator);
  const space::H1Space s(m, degrees);
  operators::PoissonData data;
  data.f = [](const Point& x) { return std::exp(x.x()) * std::cos(3 * x.y()); };
  data.neumann = [](const Point& x, const Point&) { return std::sin(2 * x.x()); };
  const auto u = operators::solve_poisson(s, data).coefficients;
  ASSERT_GT(u.norm(), 1e-3);
  double largest_jump = 0.0;
  int mixed_edges = 0;
  for (int e = 0; e < m.n_edges(); ++e) {
    if (m.is_boundary_edge(e)) continue;
    const auto& cells = m.edge_cells(e);
    mixed_edges += m.cell_type(cells[0]) != m.cell_type(cells[1]);
    const mesh::CellMap map0(m, cells[0]), map1(m, cells[1]);
    for (double t : {-0.9, -0.41, 0.0, 0.23, 0.77}) {
      const Point x = (1 - t) / 2 * m.vertex(m.edge(e)[0]) + (1 + t) / 2 * m.vertex(m.edge(e)[1]);
      const auto r0 = map0.inverse(x), r1 = map1.inverse(x);
      ASSERT_TRUE(r0 && r1);
      const auto v0 = postprocess::evaluate(s, u, {cells[0], r0->x(), r0->y()});
      const auto v1 = postprocess::evaluate(s, u, {cells[1], r1->x(), r1->y()});
      const Point tangent = (m.vertex(m.edge(e)[1]) - m.vertex(m.edge(e)[0])).normalized();
      largest_jump =
          std::max({largest_jump, std::abs(v0.value - v1.value), std::abs((v0.gradient - v1.gradient).dot(tangent))});
    }
  }
  EXPECT_GT(mixed_edges, 10);
  EXPECT_LT(largest_jump, 1e-11);
}

TEST(TriangleConvergence, EnergyErrorRateIsPInHAndExponentialInP) {
  const int coarse[] = {0, 8, 4, 4, 2};
  for (int p = 1; p <= 4; ++p) {
    const auto a = manufactured_errors(triangle_square(2 * coarse[p]), p);
    const auto b = manufactured_errors(triangle_square(4 * coarse[p]), p);
    EXPECT_NEAR(std::log2(a.energy / b.energy), p, 0.2) << "p = " << p << ": " << a.energy << " -> " << b.energy;
  }
  // A perturbed mixed mesh at p = 1 … 12: each step gains a factor, down to 1e-9.
  auto m = mesh::split_into_triangles(mesh::make_paper_square_mesh(2), [](int c) { return c != 1; });
  mesh::perturb_interior_vertices(m, 0.2, 9);
  double previous = INFINITY;
  for (int p = 1; p <= 12; ++p) {
    const double error = manufactured_errors(m, p).energy;
    EXPECT_LT(error, 0.6 * previous) << "p = " << p;
    previous = error;
  }
  EXPECT_LT(previous, 1e-9);
}

// The §7 Signorini problem (Figure 1) on Gmsh's unstructured triangles (studies/triangles/
// square.msh, h = 1/8) and on the 16 × 16 quadrilaterals: at each p the two energies differ by less
// than the quadrilateral energy's own change from p to p + 2 (an estimate of its discretization
// error), the difference shrinks with p, and both meet the KKT conditions.
TEST(TriangleScenes, SignoriniOnAGmshTriangleMeshHasTheQuadrilateralEnergy) {
  auto energy = [](const std::string& file, int p) {
    const auto dir = hpcontact::testing::scratch("triangle_signorini");
    const auto scene = scene::read_scene(file, {{"run.effects", std::vector<std::string>{"signorini"}, "test"},
                                                {"discretization.p", static_cast<long long>(p), "test"}});
    driver::SceneRunOptions options;
    options.out = dir;
    const driver::RunResult summary = driver::run_scene(scene, options);
    EXPECT_LT(summary.contact("signorini").solver.kkt_residual, 1e-12);
    return summary.contact("signorini").energy;
  };
  const std::string quadrilaterals = std::string(HPCONTACT_SOURCE_DIR) + "/studies/paper/figure1_signorini.toml";
  double previous_difference = INFINITY;
  for (int p : {2, 4, 6}) {
    const double triangle = energy(kTriangles + "signorini.toml", p), quad = energy(quadrilaterals, p);
    const double quad_change = std::abs(energy(quadrilaterals, p + 2) - quad);
    const double difference = std::abs(triangle - quad);
    EXPECT_LT(difference, quad_change) << "p = " << p;
    EXPECT_LT(difference, previous_difference) << "p = " << p;
    previous_difference = difference;
  }
}

TEST(TriangleScenes, GmshTrianglesReadAndTheCellsKeyIsChecked) {
  const auto m = mesh::read_gmsh_mesh(kTriangles + "square.msh");
  EXPECT_TRUE(m.has_triangles());
  for (int c = 0; c < m.n_cells(); ++c) EXPECT_EQ(m.cell_type(c), CellType::triangle);
  // triangles.msh: the unit square as two triangles, the second given clockwise.
  const auto two = mesh::read_gmsh_mesh(std::string(HPCONTACT_TEST_DATA) + "/triangles.msh");
  ASSERT_EQ(two.n_cells(), 2);
  for (int c = 0; c < 2; ++c) EXPECT_GT(mesh::CellMap(two, c).jacobian(-0.5, -0.5).determinant(), 0.0);
  // A .geo meshed into triangles or quadrilaterals on request.
  const auto triangles = mesh::read_gmsh_mesh(kTriangles + "square.geo", {0.5, mesh::GeneratedCells::triangles});
  const auto quads = mesh::read_gmsh_mesh(kTriangles + "square.geo", {0.5, mesh::GeneratedCells::quadrilaterals});
  EXPECT_TRUE(triangles.has_triangles());
  EXPECT_FALSE(quads.has_triangles());
  // `cells` names the rectangle's or a .geo's cells; a mesh file holds its own.
  try {
    scene::read_scene(kTriangles + "signorini.toml", {{"domain.cells", std::string("triangles"), "test"}});
    ADD_FAILURE() << "domain.cells with a .msh file was accepted";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("domain.cells"));
    EXPECT_THAT(error.what(), HasSubstr("holds its own cells"));
  }
  const auto rectangle = scene::build_scene_mesh(
      scene::read_scene(std::string(HPCONTACT_SOURCE_DIR) + "/studies/paper/figure1_signorini.toml",
                        {{"domain.cells", std::string("triangles"), "test"}}));
  EXPECT_EQ(rectangle.n_cells(), 2 * 16 * 16);
  EXPECT_THROW(scene::read_scene(kTriangles + "signorini.toml", {{"domain.cells", std::string("hexagons"), "test"}}),
               InputError);
}
namespace {

double triangle_aware_area(const mesh::Mesh& m) {
  double sum = 0.0;
  for (int c = 0; c < m.n_cells(); ++c) {
    const mesh::CellMap map(m, c);
    const auto rule = assembly::cell_quadrature(m.cell_type(c), 20);
    for (int q = 0; q < rule.points.size(); ++q)
      sum += rule.weights[q] * map.jacobian(rule.points.xi[q], rule.points.eta[q]).determinant();
  }
  return sum;
}

}  // namespace

// Triangles with a curved side: the annulus.geo arcs followed exactly by blended triangles, on the
// mesh and on its refinements (children keep the parent's map), and the H¹ error falls
// exponentially in p where the polygonal domain through the same vertices stalls.
TEST(CurvedTriangles, ArcsFollowedExactlyNestedUnderRefinementAndExponentialInP) {
  const double quarter_annulus = 3.0 * std::acos(-1.0) / 4.0;
  auto m = mesh::read_gmsh_mesh(std::string(HPCONTACT_SOURCE_DIR) + "/studies/curved/annulus.geo",
                                {std::nullopt, mesh::GeneratedCells::triangles});
  ASSERT_TRUE(m.has_triangles());
  ASSERT_TRUE(m.has_curved_cells());
  for (int level = 0; level < 3; ++level) {
    EXPECT_NEAR(triangle_aware_area(m), quarter_annulus, 1e-13) << "level " << level;
    for (int e : m.boundary_edges())
      for (double t : {-0.6, 0.1, 0.7}) {
        const double radius = m.edge_point(e, t).norm();
        if (m.edge_label(e) == "outer") {
          EXPECT_NEAR(radius, 2.0, 1e-14);
        } else if (m.edge_label(e) == "inner") {
          EXPECT_NEAR(radius, 1.0, 1e-14);
        }
      }
    m = mesh::refine_uniformly(m);
  }
  hpcontact::testing::expect_curved_convergence(kTriangles + "curved_convergence.toml", 0.15);
}

// The tutorial's triangle scene: a slab with a circular-arc contact edge meshed into triangles on
// the fly; the contact problem meets KKT and the contact set is a proper part of the arc.
TEST(CurvedTriangles, TutorialArchSceneSolvesOnItsArc) {
  const auto dir = hpcontact::testing::scratch("triangle_arch");
  const auto scene = scene::read_scene(std::string(HPCONTACT_SOURCE_DIR) + "/studies/tutorial/arch.toml",
                                       {{"run.effects", std::vector<std::string>{"signorini"}, "test"}});
  driver::SceneRunOptions options;
  options.out = dir;
  const driver::RunResult summary = driver::run_scene(scene, options);
  EXPECT_LT(summary.contact("signorini").solver.kkt_residual, 1e-12);
  // The arc through (±1, 0) and (0, -0.3) with centre (0, 91/60): radius 109/60, angle 2 asin(60/109).
  const double arc = 109.0 / 60.0 * 2.0 * std::asin(60.0 / 109.0);
  const double contact = summary.contact("signorini").contact_set_length;
  EXPECT_GT(contact, 0.2 * arc);
  EXPECT_LT(contact, 0.95 * arc);
}
