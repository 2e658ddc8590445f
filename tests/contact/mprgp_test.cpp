// MPRGP (products by S only) against the dense active-set method on random bound-constrained QPs:
// the same minimizer where S is definite, the same minimum where it is singular; the Lanczos
// bound of λ_max from products; an objective unbounded on the box is refused.
#include "contact/mprgp.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <limits>
#include <random>

#include "contact/multiplier_qp.hpp"
#include "core/error.hpp"

namespace hpcontact::contact {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// S = AᵀA / n (+ shift I), A with `rank` rows: singular for rank < n and shift 0.
Eigen::MatrixXd random_s(int n, int rank, double shift, std::mt19937& random) {
  std::normal_distribution<double> normal;
  const Eigen::MatrixXd a = Eigen::MatrixXd::NullaryExpr(rank, n, [&] { return normal(random); });
  return a.transpose() * a / n + shift * Eigen::MatrixXd::Identity(n, n);
}

double objective(const Eigen::MatrixXd& s, const Eigen::VectorXd& d, const Eigen::VectorXd& x) {
  return 0.5 * x.dot(s * x) - d.dot(x);
}

struct Bounds {
  const char* name;
  Eigen::VectorXd lo, hi;
};

/// The bounds of the contact problems: λ ≤ 0 (9), P ≥ 0 (frictionless), |λ| ≤ s with some λ fixed
/// at 0 (13, cells outside supp s).
std::vector<Bounds> contact_bounds(int n, std::mt19937& random) {
  std::uniform_real_distribution<double> uniform(0.05, 0.5);
  Bounds box{"box with fixed entries", Eigen::VectorXd(n), Eigen::VectorXd(n)};
  for (int i = 0; i < n; ++i) {
    const double s = i % 5 == 0 ? 0.0 : uniform(random);
    box.lo(i) = -s;
    box.hi(i) = s;
  }
  return {{"sign (9)", Eigen::VectorXd::Constant(n, -kInfinity), Eigen::VectorXd::Zero(n)},
          {"pressure", Eigen::VectorXd::Zero(n), Eigen::VectorXd::Constant(n, kInfinity)},
          box};
}

TEST(Mprgp, EqualsTheActiveSetMethodWhereSIsDefinite) {
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  for (int n : {1, 5, 40, 120}) {
    const Eigen::MatrixXd s = random_s(n, n, 0.01, random);
    const Eigen::VectorXd d = Eigen::VectorXd::NullaryExpr(n, [&] { return normal(random); });
    for (const Bounds& b : contact_bounds(n, random)) {
      const BoxQpResult dense = solve_box_qp(s, d, b.lo, b.hi);
      const TraceOperator op = TraceOperator::dense(s);
      const BoxQpResult products = solve_box_qp_by_products(op, d, b.lo, b.hi);
      ASSERT_TRUE(products.report.converged) << b.name << " n " << n;
      EXPECT_EQ(products.report.method, "mprgp");
      EXPECT_EQ(products.report.products, op.products());
      EXPECT_LT((products.x - dense.x).lpNorm<Eigen::Infinity>(), 1e-8 * (1.0 + dense.x.lpNorm<Eigen::Infinity>()))
          << b.name << " n " << n;
      EXPECT_TRUE(((products.x - b.lo).array() >= 0.0).all() && ((b.hi - products.x).array() >= 0.0).all()) << b.name;
    }
  }
}

TEST(Mprgp, ReachesTheMinimumWhereSIsSingular) {
  // An unstable pairing's S: many solutions, one minimum (d in the range of S keeps it bounded).
  std::mt19937 random(11);
  std::normal_distribution<double> normal;
  const int n = 60;
  const Eigen::MatrixXd s = random_s(n, 35, 0.0, random);
  const Eigen::VectorXd d = s * Eigen::VectorXd::NullaryExpr(n, [&] { return normal(random); });
  for (const Bounds& b : contact_bounds(n, random)) {
    // (the dense reference: the active-set method, or the interior-point method where it stalls,
    // as the dense path of a solve does)
    MultiplierConstraints constraints;
    constraints.to_nodal = constraints.matrix = Eigen::MatrixXd::Identity(n, n);
    constraints.lower = b.lo;
    constraints.upper = b.hi;
    const MultiplierQpSolution dense = solve_multiplier_qp(s, d, constraints, {}, {});
    const BoxQpResult products = solve_box_qp_by_products(TraceOperator::dense(s), d, b.lo, b.hi);
    const double dense_min = objective(s, d, dense.x);
    EXPECT_NEAR(objective(s, d, products.x), dense_min, 1e-9 * (1.0 + std::abs(dense_min))) << b.name;
    EXPECT_TRUE(((products.x - b.lo).array() >= 0.0).all() && ((b.hi - products.x).array() >= 0.0).all()) << b.name;
  }
}

TEST(Mprgp, RefusesAnObjectiveUnboundedOnTheBox) {
  // S = diag(1, 0), d = (0, −1): x₂ → −∞ lowers the objective, and only P ≥ 0 bounds are given
  // on x₁.
  Eigen::MatrixXd s = Eigen::MatrixXd::Zero(2, 2);
  s(0, 0) = 1.0;
  const Eigen::VectorXd d = Eigen::Vector2d(0.0, -1.0);
  const Eigen::VectorXd lo = Eigen::Vector2d(0.0, -kInfinity), hi = Eigen::Vector2d::Constant(kInfinity);
  EXPECT_THROW(solve_box_qp_by_products(TraceOperator::dense(s), d, lo, hi), NumericalError);
  // The same with the null direction's curvature at round-off, as products give it: still refused,
  // not a step of 1e16 reported as converged.
  s(1, 1) = 1e-18;
  EXPECT_THROW(solve_box_qp_by_products(TraceOperator::dense(s), d, lo, hi), NumericalError);
}

TEST(Mprgp, PutsEachUnknownAtTheBoundItsLoadPointsToWhereSVanishes) {
  const Eigen::MatrixXd s = Eigen::MatrixXd::Zero(3, 3);
  const Eigen::VectorXd d = Eigen::Vector3d(1.0, -2.0, 0.0);
  const Eigen::VectorXd lo = Eigen::Vector3d::Constant(-0.5), hi = Eigen::Vector3d::Constant(0.25);
  const BoxQpResult result = solve_box_qp_by_products(TraceOperator::dense(s), d, lo, hi);
  EXPECT_EQ(result.x, Eigen::VectorXd(Eigen::Vector3d(0.25, -0.5, 0.0)));
  const Eigen::VectorXd open = Eigen::Vector3d::Constant(kInfinity);
  EXPECT_THROW(solve_box_qp_by_products(TraceOperator::dense(s), d, lo, open), NumericalError);
}

TEST(Mprgp, LanczosBoundsTheLargestEigenvalueFromAbove) {
  std::mt19937 random(3);
  // (n = 300 of rank 10: the Lanczos basis breaks down after 10 steps; n = 300 of full rank: 30
  // steps of 300, the estimate not exact)
  for (const auto [n, rank] : {std::pair{3, 3}, std::pair{300, 10}, std::pair{300, 300}}) {
    const Eigen::MatrixXd s = random_s(n, rank, 0.0, random);
    const double largest = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(s).eigenvalues().maxCoeff();
    const double bound = largest_eigenvalue_bound(TraceOperator::dense(s));
    EXPECT_GE(bound, largest * (1 - 1e-12)) << n;
    EXPECT_LE(bound, largest * 1.05) << n;
  }
  const Eigen::MatrixXd zero = Eigen::MatrixXd::Zero(4, 4);
  EXPECT_EQ(largest_eigenvalue_bound(TraceOperator::dense(zero)), 0.0);
}

}  // namespace
}  // namespace hpcontact::contact
