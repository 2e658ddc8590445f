// VectorSpace: which scalar dofs lie on roller edges, and the numbering of the rest.
#include "space/vector_space.hpp"

#include <fmt/format.h>

#include "core/error.hpp"

namespace hpcontact::space {

namespace {

// The local edge a shape belongs to (-1 for interior modes); vertex shapes belong to two, and
// `second` gets the other one. Local numbering of quad_mesh.hpp: vertex (i, j) ∈ {0,1}² is
// (ξ, η) = (2i − 1, 2j − 1); edges 0: η = −1, 1: ξ = +1, 2: η = +1, 3: ξ = −1.
int shape_edge(const LocalShape& shape, int& second) {
  second = -1;
  const bool vertex_i = shape.i <= 1, vertex_j = shape.j <= 1;
  const int edge_of_j = shape.j == 0 ? 0 : 2, edge_of_i = shape.i == 1 ? 1 : 3;
  if (vertex_i && vertex_j) {
    second = edge_of_i;
    return edge_of_j;
  }
  if (vertex_j) return edge_of_j;  // an edge mode along ξ
  if (vertex_i) return edge_of_i;  // an edge mode along η
  return -1;
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
        int second = -1;
        const int local = shape_edge(shape, second);
        for (const int edge : {local, second})
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
