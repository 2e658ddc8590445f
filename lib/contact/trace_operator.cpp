// The Lanczos estimate of S's largest eigenvalue, from products only.
#include "contact/trace_operator.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace hpcontact::contact {

double largest_eigenvalue_bound(const TraceOperator& s, int steps) {
  const Eigen::Index n = s.size();
  HPC_VERIFY(steps >= 1, "largest_eigenvalue_bound: at least one Lanczos step");
  if (n == 0) return 0.0;
  steps = static_cast<int>(std::min<Eigen::Index>(steps, n));
  // A fixed start with every component present (λ_max's eigenvector is not missed by symmetry):
  // the same estimate on every run.
  Eigen::VectorXd v = Eigen::VectorXd::NullaryExpr(n, [](Eigen::Index i) { return 1.0 + std::sin(1.7 * i + 0.3); });
  v.normalize();
  Eigen::MatrixXd basis(n, steps);
  Eigen::VectorXd alpha(steps), beta(steps);
  int k = 0;
  for (; k < steps; ++k) {
    basis.col(k) = v;
    Eigen::VectorXd w = s(v);
    alpha(k) = v.dot(w);
    // Full reorthogonalization (twice is enough): the basis is small, and without it the
    // estimate would carry ghost copies of λ_max.
    for (int pass = 0; pass < 2; ++pass) w -= basis.leftCols(k + 1) * (basis.leftCols(k + 1).transpose() * w);
    beta(k) = w.norm();
    if (!(beta(k) > 1e-14 * std::max(std::abs(alpha(k)), 1e-300))) {
      ++k;
      beta(k - 1) = 0.0;
      break;
    }
    v = w / beta(k);
  }
  Eigen::MatrixXd t = Eigen::MatrixXd::Zero(k, k);
  for (int i = 0; i < k; ++i) {
    t(i, i) = alpha(i);
    if (i + 1 < k) t(i, i + 1) = t(i + 1, i) = beta(i);
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ritz(t);
  const double theta = ritz.eigenvalues()(k - 1);
  const double residual = std::abs(beta(k - 1) * ritz.eigenvectors()(k - 1, k - 1));
  return std::max(theta + residual, 0.0);
}

}  // namespace hpcontact::contact
