// Legendre recurrence and Lobatto shape functions.
#include "basis/lobatto.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace hpcontact::basis {

Eigen::VectorXd legendre_values(int n, double t) {
  Eigen::VectorXd values(n + 1);
  values(0) = 1.0;
  if (n >= 1) values(1) = t;
  for (int k = 2; k <= n; ++k) values(k) = ((2.0 * k - 1.0) * t * values(k - 1) - (k - 1.0) * values(k - 2)) / k;
  return values;
}

std::vector<double> gauss_lobatto_points(int p) {
  HPC_VERIFY(p >= 1, "Gauss-Lobatto points of degree >= 1");
  // The interior points are the roots of P_p' ∝ P^{(1,1)}_{p-1}: the eigenvalues of its symmetric
  // tridiagonal Jacobi matrix (zero diagonal, off-diagonal sqrt(n(n+2)/((2n+1)(2n+3)))).
  std::vector<double> points{-1.0};
  if (p >= 2) {
    Eigen::MatrixXd jacobi = Eigen::MatrixXd::Zero(p - 1, p - 1);
    for (int n = 1; n <= p - 2; ++n)
      jacobi(n - 1, n) = jacobi(n, n - 1) = std::sqrt(n * (n + 2.0) / ((2.0 * n + 1.0) * (2.0 * n + 3.0)));
    const Eigen::VectorXd roots = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(jacobi).eigenvalues();
    points.insert(points.end(), roots.begin(), roots.end());
  }
  points.push_back(1.0);
  return points;
}

void lobatto_values(int p, double t, Eigen::Ref<Eigen::VectorXd> values, Eigen::Ref<Eigen::VectorXd> derivatives) {
  const Eigen::VectorXd legendre = legendre_values(std::max(p, 1), t);
  values(0) = 0.5 * (1.0 - t);
  derivatives(0) = -0.5;
  if (p >= 1) {
    values(1) = 0.5 * (1.0 + t);
    derivatives(1) = 0.5;
  }
  for (int k = 2; k <= p; ++k) {
    values(k) = (legendre(k) - legendre(k - 2)) / std::sqrt(2.0 * (2.0 * k - 1.0));
    derivatives(k) = std::sqrt((2.0 * k - 1.0) / 2.0) * legendre(k - 1);
  }
}

Tabulation1D tabulate_lobatto(int p, const std::vector<double>& points) {
  const int n = static_cast<int>(points.size());
  Tabulation1D table{Eigen::MatrixXd(n, p + 1), Eigen::MatrixXd(n, p + 1)};
  Eigen::VectorXd values(p + 1), derivatives(p + 1);
  for (int i = 0; i < n; ++i) {
    lobatto_values(p, points[i], values, derivatives);
    table.values.row(i) = values.transpose();
    table.derivatives.row(i) = derivatives.transpose();
  }
  return table;
}

std::vector<double> chebyshev_lobatto_points(int q) {
  HPC_VERIFY(q >= 1, "at least one point");
  if (q == 1) return {0.0};
  std::vector<double> points(q);
  for (int k = 0; k < q; ++k) points[k] = -std::cos(std::numbers::pi * k / (q - 1));
  return points;
}

Eigen::VectorXd lagrange_values(const std::vector<double>& nodes, double t) {
  const Eigen::Index n = static_cast<Eigen::Index>(nodes.size());
  Eigen::VectorXd values = Eigen::VectorXd::Ones(n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j)
      if (j != i) values(i) *= (t - nodes[j]) / (nodes[i] - nodes[j]);
  return values;
}

}  // namespace hpcontact::basis
