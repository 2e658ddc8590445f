// VectorSpace: which scalar dofs lie on roller edges, and the numbering of the rest.
#include "space/vector_space.hpp"

#include <fmt/format.h>

#include <array>

#include "core/error.hpp"

namespace hpcontact::space {

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
    // A fixed (closed) edge holds the dofs of its end points and its modes; read from the
    // numbering, not from the cells' shapes, which a rank of a distributed run holds for its
    // cells only.
    const auto fix = [&](int dof) {
      if (dof >= 0) is_fixed[kComponents * dof + c] = 1;
    };
    for (int e = 0; e < mesh.n_edges(); ++e) {
      if (!fixed[c][e]) continue;
      for (const int v : mesh.edge(e)) fix(scalar.vertex_dof(v));
      for (int k = 2; k <= scalar.edge_degree(e); ++k) fix(scalar.edge_mode_dof(e, k));
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
