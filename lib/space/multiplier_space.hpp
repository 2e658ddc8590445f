// The multiplier space M^{p_C}(T_{C,H}) (the paper's §5): discontinuous polynomials of degree
// p_C per segment of the boundary mesh, Legendre basis in the segment coordinate τ ∈ [-1,1].
#pragma once

#include <Eigen/Core>
#include <vector>

#include "mesh/boundary_mesh.hpp"

namespace hpcontact::space {

class MultiplierSpace {
 public:
  /// @param segment_degrees p_C per segment (≥ 0). @throws InputError otherwise.
  MultiplierSpace(const mesh::BoundaryMesh& boundary_mesh, std::vector<int> segment_degrees);
  MultiplierSpace(const mesh::BoundaryMesh& boundary_mesh, int degree);
  // The space refers to its boundary mesh, which must outlive it: a temporary would dangle.
  MultiplierSpace(mesh::BoundaryMesh&&, std::vector<int>) = delete;
  MultiplierSpace(mesh::BoundaryMesh&&, int) = delete;

  const mesh::BoundaryMesh& boundary_mesh() const { return *mesh_; }
  int n_dofs() const { return n_dofs_; }
  int n_segments() const { return mesh_->n_segments(); }
  int segment_degree(int k) const { return degrees_[k]; }
  int max_degree() const { return max_degree_; }
  /// Dofs of segment k are first_dof(k) .. first_dof(k) + p_C(k), mode j ↔ P_j(τ).
  int first_dof(int k) const { return first_dof_[k]; }
  /// Segment coordinate τ ∈ [-1,1] of arc length s in segment k.
  double local_coordinate(int k, double s) const;
  /// Values of the segment's basis functions at τ: shape (p_C(k) + 1).
  Eigen::VectorXd basis_values(int k, double tau) const;
  /// μ(s) for coefficients c (shape n_dofs), taking the segment of s from the left.
  double evaluate(const Eigen::VectorXd& coefficients, double s) const;

 private:
  const mesh::BoundaryMesh* mesh_;
  std::vector<int> degrees_;
  std::vector<int> first_dof_;
  int n_dofs_ = 0;
  int max_degree_ = 0;
};

}  // namespace hpcontact::space
