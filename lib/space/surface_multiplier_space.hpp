// The multiplier space M^{p_C}(T_{C,H}) on a surface multiplier mesh: discontinuous Q_{p_C} on each
// rectangle of T_{C,H}, in the tensor Lagrange basis at the Chebyshev–Lobatto points (the
// midpoint for p_C = 0), or discontinuous P_0 / P_1 on each triangle, in the Lagrange basis at the
// centroid / the vertices, so that the sign condition of the Signorini problem at those points is
// a bound on each coefficient (the paper's Remark 3). (Every basis function has a positive
// integral, so nonnegative coefficients are nonnegative mean pressures.)
#pragma once

#include <Eigen/Core>
#include <vector>

#include "mesh/contact_surface.hpp"

namespace hpcontact::space {

/// Cell c's coefficients are dofs c n … (c + 1) n − 1 with n = per_cell(); on a rectangle nodal
/// point (i, j) at local index i + (p_C + 1) j, on a triangle vertex k (p_C = 1) at local index k.
class SurfaceMultiplierSpace {
 public:
  /// @throws InputError if p_C < 0, or p_C > 1 on triangles.
  SurfaceMultiplierSpace(const mesh::SurfaceMultiplierMesh& mesh, int degree);

  const mesh::SurfaceMultiplierMesh& mesh() const { return *mesh_; }
  int degree() const { return degree_; }
  int n_dofs() const { return mesh_->n_cells() * per_cell(); }
  int per_cell() const { return mesh_->is_grid() ? (degree_ + 1) * (degree_ + 1) : (degree_ == 0 ? 1 : 3); }
  int first_dof(int cell) const { return cell * per_cell(); }
  /// The cell's basis functions at the plane point a (inside the cell): shape (per_cell()).
  Eigen::VectorXd values(int cell, const Eigen::Vector2d& a) const;
  /// The nodal point of `dof` in plane coordinates.
  Eigen::Vector2d nodal_point(int dof) const;

 private:
  /// Reference coordinates of the plane point a in cell c: in [-1,1]² on a rectangle, the
  /// barycentric weights (s, t) of v_1 and v_2 on a triangle.
  Eigen::Vector2d reference(int cell, const Eigen::Vector2d& a) const;
  Eigen::VectorXd triangle_values(const Eigen::Vector2d& st) const;

  const mesh::SurfaceMultiplierMesh* mesh_;
  int degree_;
  std::vector<double> nodes_;  ///< the 1-D nodal points
};

}  // namespace hpcontact::space
