// Contact core: the general-inequality QP (more constraint points than coefficients).
// Checked by its KKT residuals, against an exhaustive enumeration of active sets on small
// problems (independent of any iteration), and against the box-QP active-set solver when C = I.
#include "contact/inequality_qp.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <limits>
#include <random>

#include "contact/box_qp.hpp"
#include "core/error.hpp"

using namespace hpcontact;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

double objective(const Eigen::MatrixXd& s, const Eigen::VectorXd& d, const Eigen::VectorXd& x) {
  return 0.5 * x.dot(s * x) - d.dot(x);
}

// The exact minimum over lo ≤ Cx ≤ hi by enumerating every set of rows held at a bound: for each,
// solve the equality-constrained QP (least-squares KKT system) and keep the best feasible point.
// Exponential, so only for a handful of rows; shares no code with the solver.
double brute_force_minimum(const Eigen::MatrixXd& s, const Eigen::VectorXd& d, const Eigen::MatrixXd& c,
                           const Eigen::VectorXd& lo, const Eigen::VectorXd& hi) {
  const Eigen::Index n = d.size(), rows = c.rows();
  double best = inf;
  std::vector<int> choice(rows, 0);  // 0 free, 1 at hi, 2 at lo
  const int total = static_cast<int>(std::pow(3, rows));
  for (int code = 0; code < total; ++code) {
    int rest = code;
    std::vector<Eigen::Index> active;
    std::vector<double> value;
    bool usable = true;
    for (Eigen::Index j = 0; j < rows; ++j, rest /= 3) {
      choice[j] = rest % 3;
      if (choice[j] == 0) continue;
      const double bound = choice[j] == 1 ? hi(j) : lo(j);
      if (!std::isfinite(bound)) usable = false;
      active.push_back(j);
      value.push_back(bound);
    }
    if (!usable) continue;
    const auto k = static_cast<Eigen::Index>(active.size());
    Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(n + k, n + k);
    Eigen::VectorXd rhs(n + k);
    kkt.topLeftCorner(n, n) = s;
    rhs.head(n) = d;
    for (Eigen::Index i = 0; i < k; ++i) {
      kkt.block(n + i, 0, 1, n) = c.row(active[i]);
      kkt.block(0, n + i, n, 1) = c.row(active[i]).transpose();
      rhs(n + i) = value[i];
    }
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(kkt);
    const Eigen::VectorXd solution = lu.solve(rhs);
    if (!((kkt * solution - rhs).norm() <= 1e-9 * (1.0 + rhs.norm()))) continue;  // inconsistent
    const Eigen::VectorXd x = solution.head(n);
    const Eigen::VectorXd cx = c * x;
    if (((cx - hi).array() > 1e-9).any() || ((lo - cx).array() > 1e-9).any()) continue;
    best = std::min(best, objective(s, d, x));
  }
  return best;
}

struct Problem {
  Eigen::MatrixXd s, c;
  Eigen::VectorXd d, lo, hi;
};

// n unknowns, S of the given rank, `rows` ≥ n constraint rows whose first n form the identity (so C
// has full column rank); one-sided (Signorini-like) or two-sided (friction-like) bounds.
Problem random_problem(int n, int rank, int rows, bool two_sided, unsigned seed) {
  std::mt19937 generator(seed);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd b(rank, n);
  for (auto& v : b.reshaped()) v = normal(generator);
  Problem p;
  p.s = b.transpose() * b / n;
  p.d.resize(n);
  for (auto& v : p.d) v = 2.0 * normal(generator);
  p.c = Eigen::MatrixXd::Zero(rows, n);
  p.c.topRows(n).setIdentity();
  for (int j = n; j < rows; ++j)
    for (int i = 0; i < n; ++i) p.c(j, i) = normal(generator) / std::sqrt(double(n));
  p.hi = Eigen::VectorXd::Constant(rows, two_sided ? 1.0 : 0.0);
  p.lo = Eigen::VectorXd::Constant(rows, two_sided ? -1.0 : -inf);
  return p;
}

}  // namespace

TEST(InequalityQp, MatchesExhaustiveActiveSetEnumeration) {
  struct Case {
    int n, rank, rows;
    bool two_sided;
  };
  for (const Case& k :
       {Case{3, 3, 6, false}, Case{3, 3, 5, true}, Case{4, 2, 6, true}, Case{4, 4, 8, false}, Case{2, 1, 6, true}}) {
    for (unsigned seed = 1; seed <= 4; ++seed) {
      const auto p = random_problem(k.n, k.rank, k.rows, k.two_sided, seed * 31 + k.n);
      const auto result = contact::solve_inequality_qp(p.s, p.d, p.c, p.lo, p.hi);
      EXPECT_TRUE(result.report.converged);
      EXPECT_LT(result.report.kkt_residual, 1e-12);
      const double exact = brute_force_minimum(p.s, p.d, p.c, p.lo, p.hi);
      EXPECT_NEAR(objective(p.s, p.d, result.x), exact, 1e-9 * (1.0 + std::abs(exact)))
          << "n " << k.n << " rank " << k.rank << " rows " << k.rows << " seed " << seed;
    }
  }
}

TEST(InequalityQp, AgreesWithBoxQpWhenTheConstraintsAreBounds) {
  for (const bool two_sided : {false, true}) {
    const int n = 40;
    const auto p = random_problem(n, n, n, two_sided, two_sided ? 7 : 8);
    const auto interior = contact::solve_inequality_qp(p.s, p.d, p.c, p.lo, p.hi);
    const auto active_set = contact::solve_box_qp(p.s, p.d, p.lo, p.hi);
    EXPECT_LT((interior.x - active_set.x).lpNorm<Eigen::Infinity>(), 1e-9 * (1.0 + active_set.x.norm()));
    EXPECT_LT(interior.report.iterations, 40);
  }
}

TEST(InequalityQp, EqualityRowsAndSingularHessian) {
  // Rows with lo = hi (λ = 0 where s vanishes) are equalities; S of rank 3 out of 12.
  auto p = random_problem(12, 3, 30, true, 5);
  p.lo(0) = p.hi(0) = 0.0;
  p.lo(17) = p.hi(17) = 0.25;
  const auto result = contact::solve_inequality_qp(p.s, p.d, p.c, p.lo, p.hi);
  EXPECT_LT(result.report.kkt_residual, 1e-12);
  EXPECT_NEAR(result.x(0), 0.0, 1e-12);
  EXPECT_NEAR((p.c.row(17) * result.x)(0), 0.25, 1e-11);
}

TEST(InequalityQp, DependentEqualityRowsOfAVanishingBound) {
  // A segment where the bound is 0 with more constraint points (5) than coefficients (3): five
  // equality rows on three unknowns, rank 3. The Newton system with all five was singular
  // (stationarity residual inf); reduced to the row space they fix x = 0 there. A fourth unknown
  // keeps a box row.
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(6, 4);
  // Legendre values at five points, two of them repeated exactly (as the nodal points recur among
  // Chebyshev–Lobatto points).
  const double points[] = {-1.0, 0.0, 1.0, -1.0, 0.0};
  for (int j = 0; j < 5; ++j) {
    const double t = points[j];
    c.row(j) << 1.0, t, 0.5 * (3 * t * t - 1), 0.0;
  }
  c(5, 3) = 1.0;
  Eigen::VectorXd lo = Eigen::VectorXd::Zero(6), hi = Eigen::VectorXd::Zero(6);
  lo(5) = -1.0;
  hi(5) = 1.0;
  const Eigen::MatrixXd s = Eigen::MatrixXd::Identity(4, 4);
  const Eigen::VectorXd d = (Eigen::VectorXd(4) << 1.0, 2.0, 3.0, 5.0).finished();
  const auto result = contact::solve_inequality_qp(s, d, c, lo, hi);
  EXPECT_LT(result.report.kkt_residual, 1e-12);
  EXPECT_LT(result.x.head(3).lpNorm<Eigen::Infinity>(), 1e-12);
  EXPECT_NEAR(result.x(3), 1.0, 1e-12);
  // Stationarity with the multipliers of every row: S x − d + Cᵀ y = 0.
  EXPECT_LT((s * result.x - d + c.transpose() * result.y).lpNorm<Eigen::Infinity>(), 1e-10);
}

TEST(InequalityQp, ScalingTheDataScalesTheSolutionWithTheSameIterations) {
  const auto p = random_problem(20, 20, 50, true, 11);
  const auto reference = contact::solve_inequality_qp(p.s, p.d, p.c, p.lo, p.hi);
  for (const double t : {1e-6, 1e6}) {
    const auto scaled = contact::solve_inequality_qp(p.s, t * p.d, p.c, t * p.lo, t * p.hi);
    EXPECT_EQ(scaled.report.iterations, reference.report.iterations) << "t = " << t;
    EXPECT_LT((scaled.x / t - reference.x).lpNorm<Eigen::Infinity>(), 1e-9 * (1.0 + reference.x.norm()));
  }
}

TEST(InequalityQp, InfeasibleBoundsAndExhaustedIterationsAreReported) {
  auto p = random_problem(4, 4, 8, true, 3);
  p.lo(5) = 2.0;
  p.hi(5) = 1.0;
  EXPECT_THROW(contact::solve_inequality_qp(p.s, p.d, p.c, p.lo, p.hi), NumericalError);
  const auto q = random_problem(10, 10, 30, true, 4);
  try {
    contact::solve_inequality_qp(q.s, q.d, q.c, q.lo, q.hi, {.tolerance = 1e-12, .max_iterations = 2});
    FAIL() << "two iterations cannot reach 1e-12";
  } catch (const NumericalError& error) {
    EXPECT_NE(std::string(error.what()).find("complementarity"), std::string::npos) << error.what();
  }
}
