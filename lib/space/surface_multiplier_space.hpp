// The multiplier space M^{p_C}(T_{C,H}) on a surface multiplier mesh: discontinuous Q_{p_C} on each
// rectangle of T_{C,H}, in the tensor Lagrange basis at the Chebyshev–Lobatto points (the
// midpoint for p_C = 0), so that the sign condition of the Signorini problem at those points is a
// bound on each coefficient (the paper's Remark 3).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "mesh/contact_surface.hpp"

namespace hpcontact::space {

/// Cell c's coefficients are dofs c (p_C + 1)² … (c + 1)(p_C + 1)² − 1, nodal point (i, j) at
/// local index i + (p_C + 1) j.
class SurfaceMultiplierSpace {
 public:
  /// @throws InputError if p_C < 0.
  SurfaceMultiplierSpace(const mesh::SurfaceMultiplierMesh& mesh, int degree);

  const mesh::SurfaceMultiplierMesh& mesh() const { return *mesh_; }
  int degree() const { return degree_; }
  int n_dofs() const { return mesh_->n_cells() * per_cell(); }
  int per_cell() const { return (degree_ + 1) * (degree_ + 1); }
  int first_dof(int cell) const { return cell * per_cell(); }
  /// The cell's basis functions at the plane point a (inside the cell): shape (per_cell()).
  Eigen::VectorXd values(int cell, const Eigen::Vector2d& a) const;
  /// The nodal point of `dof` in plane coordinates.
  Eigen::Vector2d nodal_point(int dof) const;

 private:
  /// Reference coordinates in [-1,1]² of the plane point a in cell c.
  Eigen::Vector2d reference(int cell, const Eigen::Vector2d& a) const;

  const mesh::SurfaceMultiplierMesh* mesh_;
  int degree_;
  std::vector<double> nodes_;  ///< the 1-D nodal points
};

}  // namespace hpcontact::space
