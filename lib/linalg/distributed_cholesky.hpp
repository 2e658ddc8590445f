// Sparse symmetric positive definite direct solver over the MPI ranks: PETSc MPIAIJ (rows in
// contiguous blocks, assembled from every rank's contributions) and MUMPS's Cholesky, with a
// trailing set (the Γ_C trace) through MUMPS's Schur-complement interface. Right-hand sides and
// results either replicated on every rank or held on the unknowns each rank touches.
#pragma once

#include <mpi.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "linalg/coupling_matrix.hpp"
#include "linalg/skeleton_solver.hpp"

namespace hpcontact::linalg {

class DistributedCholesky : public SkeletonSolver {
 public:
  /// `lower_entries`: this rank's contributions (row ≥ col) to the lower triangle of the n × n
  /// matrix; contributions to one entry, from one rank or several, are summed. `trailing` (the
  /// same on every rank): unknowns T whose Schur complement S_T = A_TT − A_TI A_II⁻¹ A_IT MUMPS
  /// returns with the factorization of A_II (dense, |T|², replicated: T is trace-sized). Then
  /// B A⁻¹ Bᵀ = B_T S_T⁻¹ B_Tᵀ needs no solve when B lives on T, and a solve runs as interior
  /// solve, dense S_T solve, interior solve. Collective on `ranks`, which must outlive the solver.
  /// @throws NumericalError if MUMPS fails or the matrix is not positive definite (a negative or
  /// null pivot of MUMPS's LDLᵀ, or with a trailing set an S_T that is not positive definite).
  DistributedCholesky(MPI_Comm ranks, int n, const std::vector<Eigen::Triplet<double>>& lower_entries,
                      const std::vector<int>& trailing = {});
  ~DistributedCholesky() override;
  DistributedCholesky(DistributedCholesky&&) noexcept;
  DistributedCholesky& operator=(DistributedCholesky&&) noexcept;

  int size() const override { return size_; }
  /// A⁻¹ rhs, shape (n, k), the same on every rank. Collective.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& rhs) const override;
  /// The unknowns this rank's entries touch (ascending): the rows of solve_local.
  const std::vector<int>& local_unknowns() const override;
  /// A⁻¹ b for b = Σ_r b_r: each rank passes its share b_r at its local unknowns (shape
  /// (local_unknowns().size(), k), k the same on every rank) and receives A⁻¹ b there; PETSc moves
  /// the rows to and from their owners. Collective.
  Eigen::MatrixXd solve_local(const Eigen::MatrixXd& partial_rhs) const override;
  /// B A⁻¹ Bᵀ, dense symmetric (m, m), the same on every rank; B (m, n) replicated. From S_T when
  /// B's nonzero columns lie in the trailing set, else by solves in blocks of 64 columns.
  /// Collective.
  Eigen::MatrixXd schur_complement(const Coupling& b) const override;
  /// |T|: the size of the dense Schur complement MUMPS returned (0 without a trailing set).
  int trailing_size() const;

 private:
  struct Impl;
  /// MUMPS's solve on this rank's rows [row_begin, row_end): A⁻¹ b, or with a trailing set
  /// A_II⁻¹ b_I (zero on T). Collective.
  Eigen::MatrixXd mumps_owned(const Eigen::MatrixXd& owned_rhs) const;
  /// A x on this rank's rows (PETSc's MatMult), for x given by its rows on every rank.
  Eigen::MatrixXd multiply_owned(const Eigen::MatrixXd& owned_x) const;
  /// A⁻¹ b on this rank's rows, through S_T when there is a trailing set.
  Eigen::MatrixXd solve_owned(const Eigen::MatrixXd& owned_rhs) const;
  std::unique_ptr<Impl> impl_;
  MPI_Comm ranks_ = MPI_COMM_NULL;  ///< the ranks sharing the matrix
  int size_ = 0;
};

}  // namespace hpcontact::linalg
