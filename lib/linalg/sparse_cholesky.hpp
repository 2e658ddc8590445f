// Sparse symmetric positive definite direct solver: CHOLMOD's supernodal LLᵀ, optionally with a
// set of unknowns (the Γ_C trace) ordered last, which turns every Schur complement B A⁻¹ Bᵀ with B
// supported on that set into dense algebra on the trailing block of the factor.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "linalg/coupling_matrix.hpp"
#include "linalg/skeleton_solver.hpp"

namespace hpcontact::linalg {

/// The fill-reducing ordering: minimum degree (AMD; measured faster on planar meshes, where its
/// factor is little larger) or nested dissection (METIS; far less fill on solid meshes).
enum class FillOrdering { minimum_degree, nested_dissection };

/// Factorizes once, solves many times. The matrix must be symmetric positive definite; only its
/// lower triangle is read.
///
/// With `trailing` (indices into 0..n-1), the fill-reducing ordering (AMD or METIS) is that of the
/// other unknowns followed by those: P A Pᵀ = L Lᵀ with L = [L_ii 0; L_ti L_tt]. For B whose columns lie in
/// the trailing set, L⁻¹ P Bᵀ vanishes outside the trailing rows, so
///     B A⁻¹ Bᵀ = Wᵀ W,   W = L_tt⁻¹ (B P_tᵀ)ᵀ,
/// i.e. the Steklov–Poincaré condensation onto the trace: one factorization, then dense work of
/// size |trailing| — no solve with the full factor per column of B. As a SkeletonSolver it is the
/// serial one: its local unknowns are all n, solve_local is solve.
class SparseCholesky : public SkeletonSolver {
 public:
  /// @throws NumericalError if the matrix is not positive definite (with the failing column).
  explicit SparseCholesky(const Eigen::SparseMatrix<double>& matrix, const std::vector<int>& trailing = {},
                          FillOrdering ordering = FillOrdering::minimum_degree);
  ~SparseCholesky() override;
  SparseCholesky(SparseCholesky&&) noexcept;
  SparseCholesky& operator=(SparseCholesky&&) noexcept;

  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const;
  /// Solves for several right-hand sides at once, shape (n, k).
  Eigen::MatrixXd solve(const Eigen::MatrixXd& rhs) const override;
  int size() const override { return size_; }
  /// 0, …, n − 1: one process holds every unknown.
  const std::vector<int>& local_unknowns() const override { return all_unknowns_; }
  /// solve: the one share is the whole right-hand side.
  Eigen::MatrixXd solve_local(const Eigen::MatrixXd& partial_rhs) const override { return solve(partial_rhs); }
  /// Number of unknowns ordered last (0 without a trailing set).
  int n_trailing() const;
  /// The trailing block L_tt of the factor, dense lower triangular (n_trailing, n_trailing):
  /// L_tt L_ttᵀ is the Schur complement of the other unknowns onto the trailing set. Row k belongs
  /// to the index i with trailing_position()[i] == k (−1 for indices outside the set).
  const Eigen::MatrixXd& trailing_factor() const;
  const std::vector<int>& trailing_position() const;
  /// Nonzeros of the factor L (a measure of the factorization's cost and memory).
  long long factor_nonzeros() const;

  /// B A⁻¹ Bᵀ, dense symmetric (m, m), for B of shape (m, n). Through the trailing block when
  /// every column of B with a nonzero lies in the trailing set, otherwise by solves in blocks of
  /// 64 columns.
  Eigen::MatrixXd schur_complement(const Coupling& b) const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int size_ = 0;
  std::vector<int> all_unknowns_;  ///< see local_unknowns()
};

}  // namespace hpcontact::linalg
