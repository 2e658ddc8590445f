// The sign-and-disc QP of 3-D Tresca contact against its optimality conditions, checked one by one
// on random problems: P ≥ 0 with (S x − d)_P ≥ 0 and complementarity; inside a disc the tangential
// gradient vanishes, on its rim it points outward along t (−∇ = μ t/|t|, μ ≥ 0); and the solution
// turns with the tangential axes (the disc has no preferred direction, as a box would).
#include "contact/disc_qp.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.hpp"

namespace hpcontact::contact {
namespace {

struct Problem {
  Eigen::MatrixXd s;
  Eigen::VectorXd d, radius;
};

/// S = AᵀA + 0.1 I for a random A (definite), d random, radii in (0.05, 0.5).
Problem random_problem(int m, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.05, 0.5);
  const Eigen::MatrixXd a = Eigen::MatrixXd::NullaryExpr(3 * m, 3 * m, [&] { return normal(random); });
  Problem p{a.transpose() * a / (3 * m) + 0.1 * Eigen::MatrixXd::Identity(3 * m, 3 * m),
            Eigen::VectorXd::NullaryExpr(3 * m, [&] { return normal(random); }),
            Eigen::VectorXd::NullaryExpr(m, [&] { return uniform(random); })};
  return p;
}

TEST(DiscQp, SolutionMeetsTheOptimalityConditions) {
  int on_rim = 0, inside = 0, pressed = 0;  // over all seeds: every kind of node occurs
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const int m = 6;
    const Problem p = random_problem(m, seed);
    const DiscQpSolution solution = solve_disc_qp(p.s, p.d, p.radius);
    ASSERT_TRUE(solution.report.converged);
    const Eigen::VectorXd& x = solution.x;
    const Eigen::VectorXd gradient = p.s * x - p.d;
    const double tolerance = 1e-9 * std::max(1.0, p.d.lpNorm<Eigen::Infinity>());
    for (int i = 0; i < m; ++i) {
      EXPECT_GE(x(i), 0.0);
      pressed += x(i) > 0.0;
      EXPECT_GE(gradient(i), -tolerance);
      EXPECT_LT(std::abs(x(i) * gradient(i)), tolerance);
      const Eigen::Vector2d t(x(m + i), x(2 * m + i)), g(gradient(m + i), gradient(2 * m + i));
      EXPECT_LE(t.norm(), p.radius(i) * (1 + 1e-12));
      if (t.norm() < p.radius(i) * (1 - 1e-8)) {
        ++inside;
        EXPECT_LT(g.norm(), tolerance) << "seed " << seed << " node " << i;
      } else {
        ++on_rim;
        // −g = μ t / |t| with μ ≥ 0: no component across t, none along +t
        EXPECT_LT(std::abs(g.x() * t.y() - g.y() * t.x()) / t.norm(), tolerance) << seed << " " << i;
        EXPECT_LE(g.dot(t), tolerance);
      }
    }
  }
  EXPECT_GT(on_rim, 0);
  EXPECT_GT(inside, 0);
  EXPECT_GT(pressed, 0);
}

TEST(DiscQp, SolutionTurnsWithTheTangentialAxes) {
  const int m = 5;
  const Problem p = random_problem(m, 11);
  const double angle = 0.7;
  // Q turns every tangential pair by `angle`; the problem in the turned axes is (Q S Qᵀ, Q d).
  Eigen::MatrixXd q = Eigen::MatrixXd::Identity(3 * m, 3 * m);
  for (int i = 0; i < m; ++i) {
    q(m + i, m + i) = std::cos(angle), q(m + i, 2 * m + i) = -std::sin(angle);
    q(2 * m + i, m + i) = std::sin(angle), q(2 * m + i, 2 * m + i) = std::cos(angle);
  }
  const Eigen::VectorXd x = solve_disc_qp(p.s, p.d, p.radius).x;
  const Eigen::VectorXd turned = solve_disc_qp(q * p.s * q.transpose(), q * p.d, p.radius).x;
  EXPECT_LT((turned - q * x).lpNorm<Eigen::Infinity>(), 1e-9);
}

TEST(DiscQp, NegativeRadiusIsRefused) {
  Problem p = random_problem(2, 3);
  p.radius(1) = -0.1;
  EXPECT_THROW(solve_disc_qp(p.s, p.d, p.radius), InputError);
}

}  // namespace
}  // namespace hpcontact::contact
