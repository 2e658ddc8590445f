// Sparse symmetric positive definite direct solver: CHOLMOD (supernodal LLᵀ) through Eigen.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>

namespace hpcontact::linalg {

/// Factorizes once, solves many times. The matrix must be symmetric positive definite; only its
/// lower triangle is read.
class SparseCholesky {
 public:
  /// @throws NumericalError if the matrix is not positive definite (with the failing column).
  explicit SparseCholesky(const Eigen::SparseMatrix<double>& matrix);
  ~SparseCholesky();
  SparseCholesky(SparseCholesky&&) noexcept;
  SparseCholesky& operator=(SparseCholesky&&) noexcept;

  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const;
  /// Solves for several right-hand sides at once, shape (n, k).
  Eigen::MatrixXd solve(const Eigen::MatrixXd& rhs) const;
  int size() const { return size_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int size_ = 0;
};

}  // namespace hpcontact::linalg
