// H1Space: dof numbering with the minimum rule, edge orientation and Dirichlet elimination, on
// quadrilaterals and triangles alike.
#include "space/h1_space.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "core/error.hpp"
#include "mesh/reference_cell.hpp"

namespace hpcontact::space {
namespace {

// Lobatto indices (i, j) of the local vertex functions: N_0 = (1-t)/2 is 1 at t = -1.
constexpr std::array<std::array<int, 2>, 4> kVertexIndex{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};

// Mode k on local edge `local`: the index along the edge is k, across it the vertex function
// that is 1 on that edge.
std::array<int, 2> edge_mode_index(int local, int k) {
  switch (local) {
    case 0:
      return {k, 0};
    case 1:
      return {1, k};
    case 2:
      return {k, 1};
    default:
      return {0, k};
  }
}

LocalShape shape(int i, int j, int dof, double sign, ShapeRole role, int entity) {
  return {static_cast<std::int16_t>(i),    static_cast<std::int16_t>(j), dof, static_cast<float>(sign), role,
          static_cast<std::int8_t>(entity)};
}

}  // namespace

int local_edge_of(const LocalShape& shape) { return shape.role == ShapeRole::edge ? shape.entity : -1; }

int edge_mode_degree(const LocalShape& shape) {
  HPC_VERIFY(shape.role == ShapeRole::edge, "an edge mode");
  // Quadrilateral: the index along the edge is the one ≥ 2; triangle: j = 0.
  return std::max(shape.i, shape.j);
}

H1Space::H1Space(const mesh::Mesh& mesh, int degree) : H1Space(mesh, std::vector<int>(mesh.n_cells(), degree)) {}

H1Space::H1Space(const mesh::Mesh& mesh, std::vector<int> cell_degrees, DirichletDofs dirichlet,
                 const std::vector<char>& held)
    : mesh_(&mesh), cell_degrees_(std::move(cell_degrees)) {
  if (static_cast<int>(cell_degrees_.size()) != mesh.n_cells())
    throw InputError("degree distribution has " + std::to_string(cell_degrees_.size()) + " entries but the mesh has " +
                     std::to_string(mesh.n_cells()) + " cells");
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (cell_degrees_[c] < 1)
      throw_bad_input("degree distribution", "p", std::to_string(cell_degrees_[c]),
                      "must be >= 1 (cell " + std::to_string(c) + ")");
  HPC_VERIFY(held.empty() || static_cast<int>(held.size()) == mesh.n_cells(), "one held flag per cell");
  HPC_VERIFY(!mesh.is_part(), "a part's space keeps the whole space's numbering: restricted_to");
  build(dirichlet, held);
}

void H1Space::not_held(int cell) {
  throw std::logic_error("the shapes of cell " + std::to_string(cell) + " were read on a rank that does not hold it");
}

std::vector<char> H1Space::held_cells() const {
  std::vector<char> held(mesh_->n_cells());
  bool all = true;
  for (int c = 0; c < mesh_->n_cells(); ++c) all = (held[c] = holds(c)) && all;
  if (all) held.clear();
  return held;
}

int H1Space::interior_count(int cell) const {
  const int p = cell_degrees_[cell];
  return mesh_->cell_type(cell) == mesh::CellType::triangle ? (p - 1) * (p - 2) / 2 : (p - 1) * (p - 1);
}

int H1Space::shape_count(int cell) const {
  const auto& mesh = *mesh_;
  int count = mesh.cell_size(cell) + interior_count(cell);
  for (int local = 0; local < mesh.cell_size(cell); ++local)
    count += std::max(edge_degrees_[mesh.cell_edge(cell, local)] - 1, 0);
  return count;
}

H1Space H1Space::restricted_to(const mesh::Mesh& part, bool with_shapes) const {
  const auto& mesh = *mesh_;
  HPC_VERIFY(part.is_part() && !mesh.is_part(), "a space is restricted to a part of its whole mesh");
  // (a part remembers its indices, not its whole mesh: at least they must be this mesh's)
  HPC_VERIFY(part.global_cell(part.n_cells() - 1) < mesh.n_cells() &&
                 part.global_vertex(part.n_vertices() - 1) < mesh.n_vertices() &&
                 part.global_edge(part.n_edges() - 1) < mesh.n_edges(),
             "a part of another mesh");
  H1Space out;
  out.mesh_ = &part;
  out.n_dofs_ = n_dofs_;
  out.n_skeleton_dofs_ = n_skeleton_dofs_;
  out.max_degree_ = max_degree_;
  for (int v = 0; v < part.n_vertices(); ++v) out.vertex_dofs_.push_back(vertex_dofs_[part.global_vertex(v)]);
  for (int e = 0; e < part.n_edges(); ++e) {
    out.edge_degrees_.push_back(edge_degrees_[part.global_edge(e)]);
    out.edge_first_dofs_.push_back(edge_first_dofs_[part.global_edge(e)]);
  }
  for (int c = 0; c < part.n_cells(); ++c) {
    out.cell_degrees_.push_back(cell_degrees_[part.global_cell(c)]);
    out.first_interior_.push_back(first_interior_[part.global_cell(c)]);
  }
  out.first_shape_.assign(part.n_cells() + 1, 0);
  return with_shapes ? out.with_shapes() : out;
}

H1Space H1Space::with_shapes() const {
  H1Space out = *this;
  const int n_cells = mesh_->n_cells();
  for (int c = 0; c < n_cells; ++c) out.first_shape_[c + 1] = out.first_shape_[c] + out.shape_count(c);
  out.shapes_.clear();
  out.shapes_.reserve(out.first_shape_.back());
  for (int c = 0; c < n_cells; ++c) out.append_shapes(c, first_interior_[c]);
  return out;
}

void H1Space::append_shapes(int c, int first_interior) {
  const auto& mesh = *mesh_;
  const int p = cell_degrees_[c];
  const bool triangle = mesh.cell_type(c) == mesh::CellType::triangle;
  for (int k = 0; k < mesh.cell_size(c); ++k) {
    const auto [i, j] = triangle ? std::array<int, 2>{0, 0} : kVertexIndex[k];
    shapes_.push_back(shape(i, j, vertex_dofs_[mesh.cell(c)[k]], 1.0, ShapeRole::vertex, k));
  }
  for (int local = 0; local < mesh.cell_size(c); ++local) {
    const int e = mesh.cell_edge(c, local);
    const int sign = mesh.edge_sign(c, local);
    for (int k = 2; k <= edge_degrees_[e]; ++k) {
      const auto [i, j] = triangle ? std::array<int, 2>{k, 0} : edge_mode_index(local, k);
      // N_k(-t) = (-1)^k N_k(t): a reversed edge flips the odd modes.
      shapes_.push_back(
          shape(i, j, edge_mode_dof(e, k), (sign < 0 && k % 2 == 1) ? -1.0 : 1.0, ShapeRole::edge, local));
    }
  }
  int next = first_interior;
  if (triangle) {
    for (int n1 = 0; n1 <= p - 3; ++n1)
      for (int n2 = 0; n1 + n2 <= p - 3; ++n2) shapes_.push_back(shape(n1, n2, next++, 1.0, ShapeRole::interior, -1));
  } else {
    for (int j = 2; j <= p; ++j)
      for (int i = 2; i <= p; ++i) shapes_.push_back(shape(i, j, next++, 1.0, ShapeRole::interior, -1));
  }
  HPC_VERIFY(static_cast<std::int64_t>(shapes_.size()) == first_shape_[c + 1], "shape count of a cell");
}

void H1Space::build(DirichletDofs dirichlet, const std::vector<char>& held) {
  const auto& mesh = *mesh_;
  max_degree_ = *std::max_element(cell_degrees_.begin(), cell_degrees_.end());
  edge_degrees_.assign(mesh.n_edges(), 0);
  for (int e = 0; e < mesh.n_edges(); ++e) {
    const auto& cells = mesh.edge_cells(e);
    edge_degrees_[e] = cell_degrees_[cells[0]];
    if (cells[1] >= 0) edge_degrees_[e] = std::min(edge_degrees_[e], cell_degrees_[cells[1]]);
  }

  // Dirichlet elimination: closed Γ_D edges, so their end points are eliminated too.
  std::vector<bool> vertex_fixed(mesh.n_vertices(), false);
  std::vector<bool> edge_fixed(mesh.n_edges(), false);
  for (int e : mesh.boundary_edges())
    if (dirichlet == DirichletDofs::eliminated && mesh.edge_part(e) == mesh::BoundaryPart::dirichlet) {
      edge_fixed[e] = true;
      vertex_fixed[mesh.edge(e)[0]] = vertex_fixed[mesh.edge(e)[1]] = true;
    }

  int next = 0;
  vertex_dofs_.assign(mesh.n_vertices(), -1);
  for (int v = 0; v < mesh.n_vertices(); ++v)
    if (!vertex_fixed[v]) vertex_dofs_[v] = next++;
  edge_first_dofs_.assign(mesh.n_edges(), -1);  // dof of mode 2; modes are contiguous
  for (int e = 0; e < mesh.n_edges(); ++e)
    if (!edge_fixed[e] && edge_degrees_[e] >= 2) {
      edge_first_dofs_[e] = next;
      next += edge_degrees_[e] - 1;
    }

  n_skeleton_dofs_ = next;
  // Sizes first, so the flat table is allocated once; a cell not held has an empty range.
  const auto is_held = [&](int c) { return held.empty() || held[c]; };
  first_shape_.assign(mesh.n_cells() + 1, 0);
  for (int c = 0; c < mesh.n_cells(); ++c) first_shape_[c + 1] = first_shape_[c] + (is_held(c) ? shape_count(c) : 0);
  shapes_.clear();
  shapes_.reserve(first_shape_.back());
  first_interior_.resize(mesh.n_cells());
  for (int c = 0; c < mesh.n_cells(); ++c) {
    first_interior_[c] = next;
    if (is_held(c)) append_shapes(c, next);  // a cell not held is numbered all the same
    next += interior_count(c);
  }
  n_dofs_ = next;
}

}  // namespace hpcontact::space
