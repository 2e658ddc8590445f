// DistributedCholesky: COO assembly into MPIAIJ (both triangles: MUMPS's Cholesky reads the upper
// one of an AIJ matrix), MUMPS factorization, MatMatSolve on dense right-hand sides whose rows are
// split like the matrix's, results summed over the ranks.
#include "linalg/distributed_cholesky.hpp"

#include <petscmat.h>

#include <algorithm>

#include "core/error.hpp"
#include "core/petsc_check.hpp"
#include "core/petsc_handle.hpp"
#include "core/petsc_session.hpp"

namespace hpcontact::linalg {

struct DistributedCholesky::Impl {
  PetscHandle<Mat, MatDestroy> matrix, factor;
  PetscInt row_begin = 0, row_end = 0;
};

DistributedCholesky::DistributedCholesky(int n, const std::vector<Eigen::Triplet<double>>& lower_entries)
    : impl_(std::make_unique<Impl>()), size_(n) {
  std::vector<PetscInt> rows, cols;
  std::vector<PetscScalar> values;
  rows.reserve(2 * lower_entries.size());
  cols.reserve(2 * lower_entries.size());
  values.reserve(2 * lower_entries.size());
  for (const auto& entry : lower_entries) {
    HPC_VERIFY(entry.row() >= entry.col() && entry.row() < n, "distributed Cholesky: entry outside the lower triangle");
    rows.push_back(entry.row()), cols.push_back(entry.col()), values.push_back(entry.value());
    if (entry.row() != entry.col())
      rows.push_back(entry.col()), cols.push_back(entry.row()), values.push_back(entry.value());
  }
  Mat& a = *impl_->matrix.out();
  HPC_PETSC_CALL(MatCreate(PETSC_COMM_WORLD, &a));
  HPC_PETSC_CALL(MatSetSizes(a, PETSC_DECIDE, PETSC_DECIDE, n, n));
  HPC_PETSC_CALL(MatSetType(a, MATAIJ));
  HPC_PETSC_CALL(MatSetPreallocationCOO(a, static_cast<PetscCount>(rows.size()), rows.data(), cols.data()));
  HPC_PETSC_CALL(MatSetValuesCOO(a, values.data(), ADD_VALUES));
  HPC_PETSC_CALL(MatSetOption(a, MAT_SYMMETRIC, PETSC_TRUE));
  HPC_PETSC_CALL(MatSetOption(a, MAT_SPD, PETSC_TRUE));
  HPC_PETSC_CALL(MatGetOwnershipRange(a, &impl_->row_begin, &impl_->row_end));
  Mat& f = *impl_->factor.out();
  HPC_PETSC_CALL(MatGetFactor(a, MATSOLVERMUMPS, MAT_FACTOR_CHOLESKY, &f));
  MatFactorInfo info;
  HPC_PETSC_CALL(MatFactorInfoInitialize(&info));
  HPC_PETSC_CALL(MatCholeskyFactorSymbolic(f, a, nullptr, &info));
  HPC_PETSC_CALL(MatCholeskyFactorNumeric(f, a, &info));
  MatFactorError error = MAT_FACTOR_NOERROR;
  HPC_PETSC_CALL(MatFactorGetError(f, &error));
  if (error != MAT_FACTOR_NOERROR)
    throw NumericalError("distributed Cholesky (MUMPS) failed on a " + std::to_string(n) + "x" + std::to_string(n) +
                         " matrix (not positive definite?)");
}

DistributedCholesky::~DistributedCholesky() = default;
DistributedCholesky::DistributedCholesky(DistributedCholesky&&) noexcept = default;
DistributedCholesky& DistributedCholesky::operator=(DistributedCholesky&&) noexcept = default;

Eigen::MatrixXd DistributedCholesky::solve_owned_rows(const Eigen::MatrixXd& rhs) const {
  HPC_VERIFY(rhs.rows() == size_, "right-hand side of the wrong size");
  const PetscInt owned = impl_->row_end - impl_->row_begin, k = static_cast<PetscInt>(rhs.cols());
  // Column-major local blocks: PETSc's dense layout (lda = owned rows).
  Eigen::MatrixXd local_rhs = rhs.middleRows(impl_->row_begin, owned), local_solution(owned, k);
  PetscHandle<Mat, MatDestroy> b, x;
  HPC_PETSC_CALL(MatCreateDense(PETSC_COMM_WORLD, owned, PETSC_DECIDE, size_, k, local_rhs.data(), b.out()));
  HPC_PETSC_CALL(MatCreateDense(PETSC_COMM_WORLD, owned, PETSC_DECIDE, size_, k, local_solution.data(), x.out()));
  HPC_PETSC_CALL(MatMatSolve(impl_->factor.get(), b.get(), x.get()));
  return local_solution;
}

Eigen::MatrixXd DistributedCholesky::solve(const Eigen::MatrixXd& rhs) const {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(size_, rhs.cols());
  if (rhs.cols() == 0) return out;
  out.middleRows(impl_->row_begin, impl_->row_end - impl_->row_begin) = solve_owned_rows(rhs);
  sum_over_ranks(out.data(), out.size());  // each row is non-zero on its owner only
  return out;
}

Eigen::MatrixXd DistributedCholesky::schur_complement(const Eigen::SparseMatrix<double>& b) const {
  HPC_VERIFY(b.cols() == size_, "B A⁻¹ Bᵀ: B has the wrong number of columns");
  const auto m = b.rows();
  const PetscInt owned = impl_->row_end - impl_->row_begin;
  const Eigen::SparseMatrix<double> bt = b.transpose();
  const Eigen::SparseMatrix<double> b_owned = b.middleCols(impl_->row_begin, owned);
  Eigen::MatrixXd result = Eigen::MatrixXd::Zero(m, m);
  constexpr Eigen::Index block = 64;
  for (Eigen::Index first = 0; first < m; first += block) {
    const auto count = std::min<Eigen::Index>(block, m - first);
    result.middleCols(first, count) = b_owned * solve_owned_rows(Eigen::MatrixXd(bt.middleCols(first, count)));
  }
  sum_over_ranks(result.data(), result.size());
  return 0.5 * (result + result.transpose());
}

}  // namespace hpcontact::linalg
