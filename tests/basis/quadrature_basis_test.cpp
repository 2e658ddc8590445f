// Basis: Gauss–Legendre exactness per degree, Lobatto shape function properties.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "basis/lobatto.hpp"
#include "basis/quadrature.hpp"

using namespace hpcontact::basis;

// Every rule used by assembly (up to p = 16 plus extra points) integrates every polynomial of
// degree ≤ 2n - 1 exactly (checked on the Legendre basis P_0..P_{2n-1}, whose integrals are 2δ_k0)
// and misses P_n², of degree 2n, completely (P_n vanishes at the Gauss points), so the test can
// tell a wrong rule.
TEST(Quadrature, GaussLegendreExactForDegree2nMinus1) {
  for (int n = 1; n <= 24; ++n) {
    const auto& rule = gauss_legendre(n);
    Eigen::VectorXd integrals = Eigen::VectorXd::Zero(2 * n);
    double square_of_pn = 0.0;
    for (int q = 0; q < n; ++q) {
      const Eigen::VectorXd legendre = legendre_values(2 * n - 1, rule.points[q]);
      integrals += rule.weights[q] * legendre;
      square_of_pn += rule.weights[q] * legendre(n) * legendre(n);
    }
    EXPECT_NEAR(integrals(0), 2.0, 1e-14) << "n = " << n;
    EXPECT_LT(integrals.tail(2 * n - 1).cwiseAbs().maxCoeff(), 1e-14) << "n = " << n;
    EXPECT_NEAR(square_of_pn, 0.0, 1e-13) << "n = " << n;
    EXPECT_GT(2.0 / (2 * n + 1) - square_of_pn, 0.01) << "n = " << n;
  }
}

TEST(Quadrature, PointsForDegree) {
  EXPECT_EQ(gauss_points_for_degree(0), 1);
  EXPECT_EQ(gauss_points_for_degree(3), 2);
  EXPECT_EQ(gauss_points_for_degree(4), 3);
}

TEST(Lobatto, BubblesVanishAtEndsAndHaveParity) {
  const int p = 16;
  Eigen::VectorXd v(p + 1), d(p + 1), w(p + 1), e(p + 1);
  lobatto_values(p, -1.0, v, d);
  lobatto_values(p, 1.0, w, e);
  EXPECT_DOUBLE_EQ(v(0), 1.0);
  EXPECT_DOUBLE_EQ(w(1), 1.0);
  for (int k = 2; k <= p; ++k) {
    EXPECT_NEAR(v(k), 0.0, 1e-14);
    EXPECT_NEAR(w(k), 0.0, 1e-14);
  }
  lobatto_values(p, 0.3, v, d);
  lobatto_values(p, -0.3, w, e);
  for (int k = 2; k <= p; ++k) EXPECT_NEAR(w(k), (k % 2 ? -1.0 : 1.0) * v(k), 1e-14);
}

TEST(Lobatto, DerivativeMatchesFiniteDifference) {
  const int p = 12;
  Eigen::VectorXd v(p + 1), d(p + 1), vp(p + 1), vm(p + 1), dummy(p + 1);
  const double t = 0.37, h = 1e-6;
  lobatto_values(p, t, v, d);
  lobatto_values(p, t + h, vp, dummy);
  lobatto_values(p, t - h, vm, dummy);
  for (int k = 0; k <= p; ++k) EXPECT_NEAR(d(k), (vp(k) - vm(k)) / (2 * h), 1e-7) << k;
}

// ∫ N_j' N_k' = δ_jk for the bubbles: the 1-D stiffness matrix of the bubbles is the identity,
// which is what keeps the basis well conditioned at high p.
TEST(Lobatto, BubbleStiffnessIsIdentityAndMassWellConditioned) {
  const int p = 16;
  const auto& rule = gauss_legendre(p + 1);
  const auto table = tabulate_lobatto(p, rule.points);
  Eigen::MatrixXd stiffness = Eigen::MatrixXd::Zero(p + 1, p + 1), mass = stiffness;
  for (std::size_t q = 0; q < rule.points.size(); ++q) {
    stiffness += rule.weights[q] * table.derivatives.row(q).transpose() * table.derivatives.row(q);
    mass += rule.weights[q] * table.values.row(q).transpose() * table.values.row(q);
  }
  const Eigen::MatrixXd bubbles = stiffness.bottomRightCorner(p - 1, p - 1);
  EXPECT_NEAR((bubbles - Eigen::MatrixXd::Identity(p - 1, p - 1)).norm(), 0.0, 1e-13);
  const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(mass).eigenvalues();
  const double condition = eigenvalues.maxCoeff() / eigenvalues.minCoeff();
  // Measured: 27 (p = 2), 1.2e3 (p = 8), 1.3e4 (p = 16), i.e. about 3 p³, from the bubble
  // entries ∫ N_k² ~ k⁻²; a monomial basis is near 1e10 at p = 16.
  EXPECT_LT(condition, 4.0 * p * p * p) << "condition number " << condition;
}
