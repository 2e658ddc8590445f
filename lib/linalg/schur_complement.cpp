// schur_complement_through_trailing: the trailing-block product or blocked solves.
#include "linalg/schur_complement.hpp"

#include <algorithm>

namespace hpcontact::linalg {

Eigen::MatrixXd schur_complement_through_trailing(const Coupling& b,
                                                  const Eigen::Ref<const Eigen::MatrixXd>& trailing_factor,
                                                  const std::function<int(int)>& trailing_position,
                                                  const std::function<Eigen::MatrixXd(const Eigen::MatrixXd&)>& solve) {
  const auto m = b.rows();
  bool inside = trailing_factor.rows() > 0;
  for (int row = 0; inside && row < b.outerSize(); ++row)
    for (Coupling::InnerIterator it(b, row); it; ++it)
      if (it.value() != 0.0 && trailing_position(it.col()) < 0) inside = false;
  Eigen::MatrixXd result(m, m);
  if (inside) {
    Eigen::MatrixXd bt = Eigen::MatrixXd::Zero(trailing_factor.rows(), m);  // (B P_tᵀ)ᵀ
    for (int row = 0; row < b.outerSize(); ++row)
      for (Coupling::InnerIterator it(b, row); it; ++it) bt(trailing_position(it.col()), it.row()) += it.value();
    trailing_factor.triangularView<Eigen::Lower>().solveInPlace(bt);
    result.setZero();
    result.selfadjointView<Eigen::Lower>().rankUpdate(bt.transpose());
    return result.selfadjointView<Eigen::Lower>();
  }
  const auto bt = squeezed<Eigen::SparseMatrix<double>>(b.transpose());  // by columns: m + 1 column pointers
  constexpr int block = 64;
  for (Eigen::Index first = 0; first < m; first += block) {
    const auto count = std::min<Eigen::Index>(block, m - first);
    result.middleCols(first, count) = b * solve(Eigen::MatrixXd(bt.middleCols(first, count)));
  }
  // Round-off leaves the product slightly unsymmetric; symmetric eigen solvers want it exact.
  return 0.5 * (result + result.transpose());
}

}  // namespace hpcontact::linalg
