// schur_complement.
#include "linalg/schur_complement.hpp"

#include <algorithm>

namespace hpcontact::linalg {

Eigen::MatrixXd schur_complement(const SparseCholesky& a, const Eigen::SparseMatrix<double>& b,
                                 int block) {
  const int m = static_cast<int>(b.rows());
  const Eigen::SparseMatrix<double> bt = b.transpose();
  Eigen::MatrixXd result(m, m);
  for (int first = 0; first < m; first += block) {
    const int count = std::min(block, m - first);
    const Eigen::MatrixXd rhs = Eigen::MatrixXd(bt.middleCols(first, count));
    result.middleCols(first, count) = b * a.solve(rhs);
  }
  // Round-off leaves result slightly unsymmetric; eigen solvers for symmetric problems want it exact.
  return 0.5 * (result + result.transpose());
}

}  // namespace hpcontact::linalg
