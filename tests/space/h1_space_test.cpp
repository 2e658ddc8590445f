// Space: dof counts, Dirichlet elimination, and conformity of mixed degree
// distributions (u_h continuous across every interior edge).
#include "space/h1_space.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <span>

#include "core/error.hpp"
#include "mesh/cell_map.hpp"
#include "mesh/cell_partition.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "mesh/refine.hpp"
#include "operators/poisson_problem.hpp"
#include "postprocess/fe_function.hpp"
#include "space/vector_space.hpp"

using namespace hpcontact;

namespace {

// One degree in 1 … max_degree per cell, drawn with `seed`.
std::vector<int> random_degrees(const mesh::Mesh& mesh, int max_degree, unsigned seed) {
  std::mt19937 generator(seed);
  std::vector<int> degrees(mesh.n_cells());
  for (int& p : degrees) p = std::uniform_int_distribution<int>(1, max_degree)(generator);
  return degrees;
}

// The same local shapes (dofs, signs, indices, roles, entities) in the same order; returns how many.
int expect_same_shapes(std::span<const space::LocalShape> a, std::span<const space::LocalShape> b) {
  EXPECT_EQ(a.size(), b.size());
  const std::size_t n = std::min(a.size(), b.size());
  for (std::size_t s = 0; s < n; ++s) {
    EXPECT_EQ(a[s].dof, b[s].dof);
    EXPECT_EQ(a[s].sign, b[s].sign);
    EXPECT_EQ(a[s].i, b[s].i);
    EXPECT_EQ(a[s].j, b[s].j);
    EXPECT_EQ(a[s].role, b[s].role);
    EXPECT_EQ(a[s].entity, b[s].entity);
  }
  return static_cast<int>(n);
}

}  // namespace

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
  const auto degrees = random_degrees(m, 7, 11);
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

// A rank's part of the mesh (Mesh::extract) and of the space (restricted_to): on a perturbed mixed
// mesh of random degrees split into three parts, every part's cell must carry the whole cell's
// vertices, edge signs, degree and shapes with the same global dofs; the part's boundary edges must
// be the whole mesh's boundary edges it holds (with their parts and labels), and the edges it
// shares with another part cuts, not boundary.
TEST(H1Space, RestrictedToAPartOfTheMeshKeepsTheWholeNumbering) {
  auto m = mesh::split_into_triangles(mesh::make_paper_square_mesh(8), [](int c) { return c % 3 != 0; });
  mesh::perturb_interior_vertices(m, 0.1, 9);
  const auto degrees = random_degrees(m, 6, 4);
  const space::H1Space whole(m, degrees);
  const auto parts = mesh::bisect_cells(m, 3, std::vector<int>(m.n_cells(), 1));
  int compared = 0, cuts = 0;
  std::vector<int> times_held(m.n_cells(), 0);
  for (int r = 0; r < 3; ++r) {
    std::vector<int> cells;
    for (int c = 0; c < m.n_cells(); ++c)
      if (parts[c] == r) cells.push_back(c);
    const mesh::Mesh part = m.extract(cells);
    const space::H1Space space = whole.restricted_to(part);
    // The numbering alone, shapes added later (a Dirichlet lift's extended space): the same shapes.
    const space::H1Space numbering = whole.restricted_to(part, false);
    EXPECT_FALSE(numbering.holds(0));
    const space::H1Space later = numbering.with_shapes();
    for (int c = 0; c < part.n_cells(); ++c) expect_same_shapes(later.cell_shapes(c), space.cell_shapes(c));
    ASSERT_TRUE(part.is_part());
    ASSERT_EQ(part.n_cells(), static_cast<int>(cells.size()));
    EXPECT_EQ(space.n_dofs(), whole.n_dofs());
    EXPECT_EQ(space.n_skeleton_dofs(), whole.n_skeleton_dofs());
    EXPECT_EQ(space.max_degree(), whole.max_degree());
    for (int c = 0; c < part.n_cells(); ++c) {
      const int g = part.global_cell(c);
      ++times_held[g];
      ASSERT_EQ(g, cells[c]);
      ASSERT_EQ(part.cell_type(c), m.cell_type(g));
      for (int k = 0; k < part.cell_size(c); ++k) {
        EXPECT_EQ(part.global_vertex(part.cell(c)[k]), m.cell(g)[k]);
        EXPECT_EQ(part.vertex(part.cell(c)[k]), m.vertex(m.cell(g)[k]));
        EXPECT_EQ(part.global_edge(part.cell_edge(c, k)), m.cell_edge(g, k));
        EXPECT_EQ(part.edge_sign(c, k), m.edge_sign(g, k));
      }
      EXPECT_EQ(space.cell_degree(c), whole.cell_degree(g));
      compared += expect_same_shapes(space.cell_shapes(c), whole.cell_shapes(g));
    }
    std::vector<int> boundary;
    for (int e = 0; e < part.n_edges(); ++e) {
      const int g = part.global_edge(e);
      EXPECT_EQ(part.edge(e)[0] < part.edge(e)[1], m.edge(g)[0] < m.edge(g)[1]);
      EXPECT_EQ(part.edge_part(e), m.edge_part(g));
      EXPECT_EQ(part.edge_label(e), m.edge_label(g));
      EXPECT_EQ(part.is_boundary_edge(e), m.is_boundary_edge(g));
      EXPECT_EQ(part.global_cell(part.edge_cells(e)[0]),
                parts[m.edge_cells(g)[0]] == r ? m.edge_cells(g)[0] : m.edge_cells(g)[1]);
      if (part.edge_cells(e)[1] == mesh::Mesh::kCellElsewhere) {
        ++cuts;
        EXPECT_FALSE(m.is_boundary_edge(g));
      }
      if (m.is_boundary_edge(g)) boundary.push_back(e);
    }
    EXPECT_EQ(part.boundary_edges(), boundary);
  }
  EXPECT_EQ(std::count(times_held.begin(), times_held.end(), 1), m.n_cells());
  EXPECT_GT(compared, 1000);
  EXPECT_GT(cuts, 2 * 8);  // each of the three parts meets another along a cut
  // A space numbered on a part alone would not be the whole one's: refused.
  EXPECT_THROW(static_cast<void>(space::H1Space(m.extract({0, 1}), 2)), std::logic_error);
}

// A rank of a distributed run builds the space holding its cells' shapes only: the numbering must
// be the whole space's, the counts and entity dofs known for every cell, and a read of a cell it
// does not hold an error (not another cell's shapes). Also for rollers, whose fixed dofs
// VectorSpace now finds from the entity dofs.
TEST(H1Space, HoldingSomeCellsKeepsTheWholeNumbering) {
  auto m = mesh::make_paper_square_mesh(6);
  mesh::perturb_interior_vertices(m, 0.2, 5);
  const auto degrees = random_degrees(m, 6, 3);
  const space::H1Space whole(m, degrees);
  std::vector<char> held(m.n_cells(), 0);
  for (int c = 0; c < m.n_cells(); ++c) held[c] = (c % 3 == 1);
  const space::H1Space part(m, degrees, space::DirichletDofs::eliminated, held);
  EXPECT_EQ(part.n_dofs(), whole.n_dofs());
  EXPECT_EQ(part.n_skeleton_dofs(), whole.n_skeleton_dofs());
  EXPECT_EQ(part.held_cells(), held);
  EXPECT_TRUE(whole.held_cells().empty());
  int compared = 0;
  for (int c = 0; c < m.n_cells(); ++c) {
    EXPECT_EQ(part.shape_count(c), static_cast<int>(whole.cell_shapes(c).size()));
    ASSERT_EQ(part.holds(c), held[c] != 0);
    if (!held[c]) {
      EXPECT_THROW(static_cast<void>(part.cell_shapes(c)), std::logic_error);
      continue;
    }
    const auto b = whole.cell_shapes(c);
    compared += expect_same_shapes(part.cell_shapes(c), b);
    // The entity dofs agree with the shapes: vertex shapes first, then the edge modes in order.
    const auto vertices = m.cell(c);
    for (std::size_t k = 0; k < vertices.size(); ++k) EXPECT_EQ(part.vertex_dof(vertices[k]), b[k].dof);
    for (const auto& shape : b) {
      if (shape.role != space::ShapeRole::edge) continue;
      EXPECT_EQ(part.edge_mode_dof(m.cell_edge(c, shape.entity), space::edge_mode_degree(shape)), shape.dof);
    }
  }
  EXPECT_GT(compared, 100);

  // Rollers: u_x fixed on the left edge, u_y on the bottom edge.
  std::array<std::vector<char>, space::kComponents> fixed{std::vector<char>(m.n_edges(), 0),
                                                          std::vector<char>(m.n_edges(), 0)};
  for (int e : m.boundary_edges()) {
    const mesh::Point mid = m.edge_midpoint(e);
    if (std::abs(mid.x() + 1.0) < 1e-12) fixed[0][e] = 1;
    if (std::abs(mid.y() + 1.0) < 1e-12) fixed[1][e] = 1;
  }
  const space::VectorSpace whole_vector(whole, fixed), part_vector(part, fixed);
  ASSERT_TRUE(whole_vector.has_rollers());
  EXPECT_EQ(part_vector.n_dofs(), whole_vector.n_dofs());
  // Unknowns in slot order, 0 … n − 1 without gaps; a slot is fixed exactly when a roller edge of
  // its component carries the scalar dof (read from the whole space's shapes).
  std::vector<char> on_roller(space::kComponents * whole.n_dofs(), 0);
  for (int e : m.boundary_edges()) {
    const auto& cells = m.edge_cells(e);
    for (const auto& shape : whole.cell_shapes(cells[0])) {
      if (shape.dof < 0 || shape.role == space::ShapeRole::interior) continue;
      const auto ends = mesh::local_edge_vertices(m.cell_type(cells[0]), m.local_edge_of(e, 0));
      const bool on_edge = shape.role == space::ShapeRole::edge ? m.cell_edge(cells[0], shape.entity) == e
                                                                : ends[0] == shape.entity || ends[1] == shape.entity;
      for (int k = 0; k < space::kComponents; ++k)
        if (on_edge && fixed[k][e]) on_roller[space::kComponents * shape.dof + k] = 1;
    }
  }
  int next = 0;
  for (int d = 0; d < whole.n_dofs(); ++d)
    for (int k = 0; k < space::kComponents; ++k) {
      ASSERT_EQ(part_vector.dof(d, k), whole_vector.dof(d, k));
      ASSERT_EQ(whole_vector.dof(d, k), on_roller[space::kComponents * d + k] ? -1 : next++) << d << ", " << k;
    }
  EXPECT_EQ(next, whole_vector.n_dofs());
}
