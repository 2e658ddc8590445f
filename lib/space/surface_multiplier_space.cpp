// Tensor Lagrange multipliers on the rectangles of a surface multiplier mesh.
#include "space/surface_multiplier_space.hpp"

#include <fmt/format.h>

#include "basis/lobatto.hpp"
#include "core/error.hpp"

namespace hpcontact::space {

SurfaceMultiplierSpace::SurfaceMultiplierSpace(const mesh::SurfaceMultiplierMesh& mesh, int degree)
    : mesh_(&mesh), degree_(degree) {
  if (degree < 0) throw InputError(fmt::format("multiplier degree p_C = {}; at least 0", degree));
  nodes_ = basis::chebyshev_lobatto_points(degree + 1);
}

Eigen::Vector2d SurfaceMultiplierSpace::reference(int cell, const Eigen::Vector2d& a) const {
  const auto [lo, hi] = mesh_->cell_bounds(cell);
  return (2.0 * (a - lo).array() / (hi - lo).array() - 1.0).matrix();
}

Eigen::VectorXd SurfaceMultiplierSpace::values(int cell, const Eigen::Vector2d& a) const {
  const Eigen::Vector2d t = reference(cell, a);
  const Eigen::VectorXd along_1 = basis::lagrange_values(nodes_, t(0)), along_2 = basis::lagrange_values(nodes_, t(1));
  Eigen::VectorXd out(per_cell());
  for (int j = 0; j <= degree_; ++j)
    for (int i = 0; i <= degree_; ++i) out(i + (degree_ + 1) * j) = along_1(i) * along_2(j);
  return out;
}

Eigen::Vector2d SurfaceMultiplierSpace::nodal_point(int dof) const {
  const int cell = dof / per_cell(), local = dof % per_cell();
  const auto [lo, hi] = mesh_->cell_bounds(cell);
  const Eigen::Vector2d t(nodes_[local % (degree_ + 1)], nodes_[local / (degree_ + 1)]);
  return lo + (0.5 * (t.array() + 1.0) * (hi - lo).array()).matrix();
}

}  // namespace hpcontact::space
