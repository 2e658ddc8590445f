// SparseCholesky on Eigen's CHOLMOD wrapper; the wrapper is hidden so that CHOLMOD's headers do
// not leak into the rest of the library.
#include "linalg/sparse_cholesky.hpp"

#include <Eigen/CholmodSupport>

#include "core/error.hpp"

namespace hpcontact::linalg {

struct SparseCholesky::Impl {
  Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower> solver;
};

SparseCholesky::SparseCholesky(const Eigen::SparseMatrix<double>& matrix)
    : impl_(std::make_unique<Impl>()), size_(static_cast<int>(matrix.rows())) {
  HPC_VERIFY(matrix.rows() == matrix.cols(), "Cholesky of a non-square matrix");
  impl_->solver.setMode(Eigen::CholmodSupernodalLLt);
  impl_->solver.compute(matrix);
  if (impl_->solver.info() != Eigen::Success)
    throw NumericalError("sparse Cholesky (CHOLMOD) failed on a " + std::to_string(size_) +
                         "x" + std::to_string(size_) +
                         " matrix: it is not positive definite (is Γ_D empty or a cell "
                         "degenerate?)");
}

SparseCholesky::~SparseCholesky() = default;
SparseCholesky::SparseCholesky(SparseCholesky&&) noexcept = default;
SparseCholesky& SparseCholesky::operator=(SparseCholesky&&) noexcept = default;

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& rhs) const {
  HPC_VERIFY(rhs.size() == size_, "right-hand side of the wrong size");
  return impl_->solver.solve(rhs);
}

Eigen::MatrixXd SparseCholesky::solve(const Eigen::MatrixXd& rhs) const {
  HPC_VERIFY(rhs.rows() == size_, "right-hand side of the wrong size");
  return impl_->solver.solve(rhs);
}

}  // namespace hpcontact::linalg
