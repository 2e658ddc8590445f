// The dense interface problem of substructuring, held and factorized over the ranks: its block
// between the parts is a PETSc MATSCALAPACK matrix (2D block-cyclic, |H|²/P entries per rank,
// Cholesky by ScaLAPACK); only trace-sized blocks are replicated. No rank holds |G|² entries.
#pragma once

#include <mpi.h>

#include <Eigen/Core>
#include <memory>
#include <vector>

namespace hpcontact::linalg {

/// S_G = [A_HH A_HC; A_CH A_CC] on the interface G = H ∪ C, C the trailing set (last). A_HH is
/// distributed and factorized by ScaLAPACK; Y = A_HH⁻¹ A_HC is kept in row blocks over the
/// ranks (|H| m / P each); the trace's Schur complement S_CC = A_CC − A_HCᵀ Y (m × m) and its
/// Cholesky factor L_CC — the trailing block of chol(S_G) — are replicated. A solve is one
/// ScaLAPACK solve with A_HH and block elimination:
///     y = A_HH⁻¹ g,  S_CC x_C = c − Yᵀ g,  x_H = y − Y x_C.
class InterfaceCholesky {
 public:
  /// This rank's contribution `block` (symmetric, at the ascending interface positions
  /// `positions`; those ≥ n − n_trailing are C); S_G is the sum over the ranks. Collective.
  /// @throws NumericalError if S_G is not positive definite.
  InterfaceCholesky(MPI_Comm ranks, int n, int n_trailing, const std::vector<int>& positions,
                    const Eigen::MatrixXd& block);
  ~InterfaceCholesky();
  InterfaceCholesky(InterfaceCholesky&&) noexcept;
  InterfaceCholesky& operator=(InterfaceCholesky&&) noexcept;

  int size() const { return size_; }
  /// S_G⁻¹ rhs for rhs (n × k) the same on every rank; the result the same on every rank.
  /// Collective.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& rhs) const;
  /// L_CC (lower triangular, m × m): L_CC L_CCᵀ = S_CC.
  const Eigen::MatrixXd& trailing_factor() const { return trailing_factor_; }
  /// Entries of S_G this rank stores (its share of A_HH's blocks, its rows of Y, S_CC, L_CC).
  double stored_entries() const { return stored_entries_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  MPI_Comm ranks_ = MPI_COMM_NULL;
  int size_ = 0, n_trailing_ = 0;
  Eigen::MatrixXd trailing_factor_;
  double stored_entries_ = 0.0;
};

}  // namespace hpcontact::linalg
