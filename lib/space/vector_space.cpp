// VectorSpace: which scalar dofs lie on roller edges, and the numbering of the rest.
#include "space/vector_space.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>

#include "core/error.hpp"

namespace hpcontact::space {

VectorSpace::VectorSpace(const H1Space& scalar, const std::array<std::vector<char>, kComponents>& fixed)
    : scalar_(&scalar) {
  const auto& mesh = scalar.mesh();
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
      if (dof >= 0) fixed_.push_back(kComponents * dof + c);
    };
    for (int e = 0; e < mesh.n_edges(); ++e) {
      if (!fixed[c][e]) continue;
      for (const int v : mesh.edge(e)) fix(scalar.vertex_dof(v));
      for (int k = 2; k <= scalar.edge_degree(e); ++k) fix(scalar.edge_mode_dof(e, k));
    }
  }
  std::sort(fixed_.begin(), fixed_.end());
  fixed_.erase(std::unique(fixed_.begin(), fixed_.end()), fixed_.end());
  n_dofs_ = kComponents * scalar.n_dofs() - static_cast<int>(fixed_.size());
  const int skeleton_slots = kComponents * scalar.n_skeleton_dofs();
  n_skeleton_dofs_ = skeleton_slots -
                     static_cast<int>(std::lower_bound(fixed_.begin(), fixed_.end(), skeleton_slots) - fixed_.begin());
}

VectorSpace::VectorSpace(const H1Space& scalar, const VectorSpace& numbering)
    : scalar_(&scalar),
      fixed_(numbering.fixed_),
      n_dofs_(numbering.n_dofs_),
      n_skeleton_dofs_(numbering.n_skeleton_dofs_) {
  HPC_VERIFY(scalar.n_dofs() == numbering.scalar().n_dofs() &&
                 scalar.n_skeleton_dofs() == numbering.scalar().n_skeleton_dofs(),
             "a vector space on the same scalar numbering");
}

int VectorSpace::dof_with_rollers(int slot) const {
  const auto it = std::lower_bound(fixed_.begin(), fixed_.end(), slot);
  if (it != fixed_.end() && *it == slot) return -1;
  return slot - static_cast<int>(it - fixed_.begin());
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
