// VectorSpace: which scalar dofs lie on roller edges, and the numbering of the rest.
#include "space/vector_space.hpp"

#include <fmt/format.h>

#include <array>

#include "core/error.hpp"

namespace hpcontact::space {

namespace {

// The local edges a shape belongs to (none for interior modes): a vertex shape belongs to the two
// local edges that meet at its vertex, an edge mode to its edge.
std::array<int, 2> shape_edges(const mesh::Mesh& mesh, int cell, const LocalShape& shape) {
  if (shape.role == ShapeRole::edge) return {shape.entity, -1};
  if (shape.role == ShapeRole::interior) return {-1, -1};
  std::array<int, 2> out{-1, -1};
  int found = 0;
  for (int local = 0; local < mesh.cell_size(cell); ++local) {
    const auto ends = mesh::local_edge_vertices(mesh.cell_type(cell), local);
    if (ends[0] == shape.entity || ends[1] == shape.entity) out[found++] = local;
  }
  return out;
}

}  // namespace

VectorSpace::VectorSpace(const H1Space& scalar, const std::array<std::vector<char>, kComponents>& fixed)
    : scalar_(&scalar) {
  const auto& mesh = scalar.mesh();
  std::vector<char> is_fixed(kComponents * scalar.n_dofs(), 0);
  for (int c = 0; c < kComponents; ++c) {
    if (fixed[c].empty()) continue;
    if (static_cast<int>(fixed[c].size()) != mesh.n_edges())
      throw InputError(fmt::format("component mask of size {} for {} edges", fixed[c].size(), mesh.n_edges()));
    for (int e = 0; e < mesh.n_edges(); ++e)
      if (fixed[c][e] && !mesh.is_boundary_edge(e))
        throw InputError(fmt::format("edge {} is interior: only boundary edges can fix a component", e));
    for (int cell = 0; cell < mesh.n_cells(); ++cell)
      for (const auto& shape : scalar.cell_shapes(cell)) {
        if (shape.dof < 0) continue;
        for (const int edge : shape_edges(mesh, cell, shape))
          if (edge >= 0 && fixed[c][mesh.cell_edge(cell, edge)]) is_fixed[kComponents * shape.dof + c] = 1;
      }
  }
  dofs_.assign(kComponents * scalar.n_dofs(), -1);
  for (int d = 0; d < scalar.n_dofs(); ++d) {
    if (d == scalar.n_skeleton_dofs()) n_skeleton_dofs_ = n_dofs_;
    for (int c = 0; c < kComponents; ++c)
      if (!is_fixed[kComponents * d + c]) dofs_[kComponents * d + c] = n_dofs_++;
  }
  if (scalar.n_skeleton_dofs() == scalar.n_dofs()) n_skeleton_dofs_ = n_dofs_;
}

Eigen::VectorXd VectorSpace::component(const Eigen::VectorXd& u, int component) const {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(scalar_->n_dofs());
  for (int d = 0; d < scalar_->n_dofs(); ++d)
    if (const int k = dof(d, component); k >= 0) out(d) = u(k);
  return out;
}

Eigen::VectorXd VectorSpace::from_components(const Eigen::VectorXd& x, const Eigen::VectorXd& y) const {
  Eigen::VectorXd u(n_dofs_);
  for (int d = 0; d < scalar_->n_dofs(); ++d)
    for (int c = 0; c < kComponents; ++c)
      if (const int k = dof(d, c); k >= 0) u(k) = (c == 0 ? x : y)(d);
  return u;
}

}  // namespace hpcontact::space
