// Lagrange multipliers on the rectangles (tensor Chebyshev–Lobatto) or triangles (centroid,
// vertices) of a surface multiplier mesh.
#include "space/surface_multiplier_space.hpp"

#include <fmt/format.h>

#include <Eigen/LU>

#include "basis/lobatto.hpp"
#include "core/error.hpp"

namespace hpcontact::space {

SurfaceMultiplierSpace::SurfaceMultiplierSpace(const mesh::SurfaceMultiplierMesh& mesh, int degree)
    : mesh_(&mesh), degree_(degree) {
  if (degree < 0) throw InputError(fmt::format("multiplier degree p_C = {}; at least 0", degree));
  // Beyond P_1 no Lagrange basis at the lattice has positive integrals (P_2's vertex functions
  // integrate to 0), so its nodal signs would not be a cone of nonnegative multipliers.
  if (!mesh.is_grid() && degree > 1)
    throw InputError(fmt::format(
        "multiplier degree p_C = {} on the triangles of T_{{C,H}}: 0 or 1 (constraints at the centroid or the "
        "vertices; higher degrees need a grid T_{{C,H}})",
        degree));
  nodes_ = basis::chebyshev_lobatto_points(degree + 1);
}

Eigen::Vector2d SurfaceMultiplierSpace::reference(int cell, const Eigen::Vector2d& a) const {
  if (!mesh_->is_grid()) {
    const std::vector<Eigen::Vector2d> v = mesh_->cell_polygon(cell);
    Eigen::Matrix2d edges;
    edges << v[1] - v[0], v[2] - v[0];
    return edges.inverse() * (a - v[0]);
  }
  const auto [lo, hi] = mesh_->cell_bounds(cell);
  return (2.0 * (a - lo).array() / (hi - lo).array() - 1.0).matrix();
}

Eigen::VectorXd SurfaceMultiplierSpace::triangle_values(const Eigen::Vector2d& st) const {
  if (degree_ == 0) return Eigen::VectorXd::Ones(1);
  return Eigen::Vector3d(1.0 - st(0) - st(1), st(0), st(1));  // (the barycentric weights of v_0, v_1, v_2)
}

Eigen::VectorXd SurfaceMultiplierSpace::values(int cell, const Eigen::Vector2d& a) const {
  const Eigen::Vector2d t = reference(cell, a);
  if (!mesh_->is_grid()) return triangle_values(t);
  const Eigen::VectorXd along_1 = basis::lagrange_values(nodes_, t(0)), along_2 = basis::lagrange_values(nodes_, t(1));
  Eigen::VectorXd out(per_cell());
  for (int j = 0; j <= degree_; ++j)
    for (int i = 0; i <= degree_; ++i) out(i + (degree_ + 1) * j) = along_1(i) * along_2(j);
  return out;
}

Eigen::Vector2d SurfaceMultiplierSpace::nodal_point(int dof) const {
  const int cell = dof / per_cell(), local = dof % per_cell();
  if (!mesh_->is_grid()) {
    const std::vector<Eigen::Vector2d> v = mesh_->cell_polygon(cell);
    return degree_ == 0 ? Eigen::Vector2d((v[0] + v[1] + v[2]) / 3.0) : v[static_cast<std::size_t>(local)];
  }
  const auto [lo, hi] = mesh_->cell_bounds(cell);
  const Eigen::Vector2d t(nodes_[local % (degree_ + 1)], nodes_[local / (degree_ + 1)]);
  return lo + (0.5 * (t.array() + 1.0) * (hi - lo).array()).matrix();
}

}  // namespace hpcontact::space
