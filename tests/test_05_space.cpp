// Stage 5, space: dof counts, Dirichlet elimination, and conformity of mixed degree
// distributions (u_h continuous across every interior edge).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.hpp"
#include "mesh/cell_map.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "operators/poisson_problem.hpp"
#include "postprocess/fe_function.hpp"
#include "space/h1_space.hpp"

using namespace hpcontact;

TEST(H1Space, UniformDegreeDofCount) {
  auto m = mesh::make_rectangle_mesh({}, 4, 3);  // all Neumann: nothing eliminated
  for (int p = 1; p <= 8; ++p) {
    const space::H1Space s(m, p);
    EXPECT_EQ(s.n_dofs(), (4 * p + 1) * (3 * p + 1)) << "p = " << p;
  }
  const auto paper = mesh::make_paper_square_mesh(4);
  // Γ_D: top edge (5 vertices, 4 edges) and right upper half (2 more vertices, 2 edges).
  const int p = 3;
  EXPECT_EQ(space::H1Space(paper, p).n_dofs(), (4 * p + 1) * (4 * p + 1) - 7 - 6 * (p - 1));
}

TEST(H1Space, RejectsBadDegrees) {
  const auto m = mesh::make_paper_square_mesh(2);
  EXPECT_THROW(space::H1Space(m, 0), InputError);
  EXPECT_THROW(space::H1Space(m, std::vector<int>{1, 2}), InputError);
}

// A random degree distribution 1..7 on a perturbed mesh: solve a Poisson problem and compare
// u_h and its tangential derivative from both sides of every interior edge.
TEST(H1Space, MixedDegreesAreConforming) {
  auto m = mesh::make_paper_square_mesh(6);
  mesh::perturb_interior_vertices(m, 0.2, 3);
  std::mt19937 generator(11);
  std::vector<int> degrees(m.n_cells());
  for (int& p : degrees) p = std::uniform_int_distribution<int>(1, 7)(generator);
  const space::H1Space s(m, degrees);
  operators::PoissonData data;
  data.f = [](const mesh::Point& x) { return std::exp(x.x()) * std::cos(3 * x.y()); };
  data.neumann = [](const mesh::Point& x, const mesh::Point&) { return std::sin(2 * x.x()); };
  const auto u = operators::solve_poisson(s, data).coefficients;
  ASSERT_GT(u.norm(), 1e-3);

  double largest_jump = 0.0;
  int edges_checked = 0;
  for (int e = 0; e < m.n_edges(); ++e) {
    if (m.is_boundary_edge(e)) continue;
    const auto& cells = m.edge_cells(e);
    ++edges_checked;
    const mesh::CellMap map0(m, cells[0]), map1(m, cells[1]);
    for (double t : {-0.9, -0.41, 0.0, 0.23, 0.77}) {
      const mesh::Point x = (1 - t) / 2 * m.vertex(m.edge(e)[0]) + (1 + t) / 2 * m.vertex(m.edge(e)[1]);
      const auto r0 = map0.inverse(x), r1 = map1.inverse(x);
      ASSERT_TRUE(r0 && r1);
      const auto v0 = postprocess::evaluate(s, u, {cells[0], r0->x(), r0->y()});
      const auto v1 = postprocess::evaluate(s, u, {cells[1], r1->x(), r1->y()});
      const mesh::Point tangent = (m.vertex(m.edge(e)[1]) - m.vertex(m.edge(e)[0])).normalized();
      largest_jump =
          std::max({largest_jump, std::abs(v0.value - v1.value), std::abs((v0.gradient - v1.gradient).dot(tangent))});
    }
  }
  EXPECT_EQ(edges_checked, 60);
  EXPECT_LT(largest_jump, 1e-12);
}

TEST(H1Space, DiscreteFunctionsVanishOnDirichletBoundary) {
  const auto m = mesh::make_paper_square_mesh(4);
  const space::H1Space s(m, 4);
  const Eigen::VectorXd u = Eigen::VectorXd::Ones(s.n_dofs());
  const postprocess::PointLocator locator(m);
  for (double t : {-0.95, -0.3, 0.4, 0.99}) {
    EXPECT_NEAR(postprocess::evaluate_at(s, u, locator, {t, 1.0}).value, 0.0, 1e-14);
    EXPECT_NEAR(postprocess::evaluate_at(s, u, locator, {1.0, 0.5 * (t + 1)}).value, 0.0, 1e-14);
  }
  EXPECT_GT(std::abs(postprocess::evaluate_at(s, u, locator, {0.3, -1.0}).value), 0.1);
}
