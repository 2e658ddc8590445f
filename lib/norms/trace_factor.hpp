// A_G = K + M of S^p(T_h), factorized once with every Γ_C trace dof ordered last, so that
// B A_G⁻¹ Bᵀ for ANY multiplier space on Γ_C (any p_C, H, weight s) is dense work on the trace
// only. Built once per (T_h, p) and shared by all sweep points on them: the S_G of (11) and (22),
// and the extension-norm Gram matrix on the reference space.
#pragma once

#include <memory>
#include <vector>

#include "linalg/sparse_cholesky.hpp"
#include "mesh/contact_boundary.hpp"
#include "space/h1_space.hpp"

namespace hpcontact::norms {

class TraceFactor {
 public:
  /// `mesh` must outlive the factor.
  TraceFactor(const mesh::QuadMesh& mesh, std::vector<int> cell_degrees);

  const space::H1Space& space() const { return *space_; }
  const mesh::ContactBoundary& contact() const { return *contact_; }
  const linalg::SparseCholesky& factor() const { return *factor_; }
  int n_trace() const { return factor_->n_trailing(); }
  double seconds_assembly() const { return seconds_assembly_; }
  double seconds_factorization() const { return seconds_factorization_; }

 private:
  std::unique_ptr<space::H1Space> space_;
  std::unique_ptr<mesh::ContactBoundary> contact_;
  std::unique_ptr<linalg::SparseCholesky> factor_;
  double seconds_assembly_ = 0.0, seconds_factorization_ = 0.0;
};

}  // namespace hpcontact::norms
