// Sparse symmetric positive definite direct solver over the MPI ranks: PETSc MPIAIJ (rows in
// contiguous blocks, assembled from every rank's contributions) and MUMPS's Cholesky. Right-hand
// sides and results are replicated on every rank, so that the small dense work around it (the
// contact QP, the eigenproblem on the trace) runs unchanged on each.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

namespace hpcontact::linalg {

class DistributedCholesky {
 public:
  /// `lower_entries`: this rank's contributions (row ≥ col) to the lower triangle of the n × n
  /// matrix; contributions to one entry, from one rank or several, are summed. Collective on
  /// PETSC_COMM_WORLD. @throws NumericalError if MUMPS fails (e.g. not positive definite).
  DistributedCholesky(int n, const std::vector<Eigen::Triplet<double>>& lower_entries);
  ~DistributedCholesky();
  DistributedCholesky(DistributedCholesky&&) noexcept;
  DistributedCholesky& operator=(DistributedCholesky&&) noexcept;

  int size() const { return size_; }
  /// A⁻¹ rhs, shape (n, k), the same on every rank. Collective.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& rhs) const;
  /// B A⁻¹ Bᵀ, dense symmetric (m, m), the same on every rank; B (m, n) replicated. Solves in
  /// blocks of 64 columns, each rank multiplying its own rows of A⁻¹ Bᵀ. Collective.
  Eigen::MatrixXd schur_complement(const Eigen::SparseMatrix<double>& b) const;

 private:
  struct Impl;
  /// This rank's rows [row_begin, row_end) of A⁻¹ rhs, for replicated rhs of shape (n, k).
  Eigen::MatrixXd solve_owned_rows(const Eigen::MatrixXd& rhs) const;
  std::unique_ptr<Impl> impl_;
  int size_ = 0;
};

}  // namespace hpcontact::linalg
