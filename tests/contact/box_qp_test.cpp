// Contact core: the box-constrained QP of the condensed contact problem. Every
// solution is checked by its KKT residual and against the objective value of an independent
// projected-gradient solve; singular S (unstable pairings) and degenerate complementarity included.
#include "contact/box_qp.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "core/error.hpp"

using namespace hpcontact;

namespace {

double objective(const Eigen::MatrixXd& s, const Eigen::VectorXd& d, const Eigen::VectorXd& x) {
  return 0.5 * x.dot(s * x) - d.dot(x);
}

// Accelerated projected gradient (FISTA), slow but independent of the active-set logic.
Eigen::VectorXd projected_gradient(const Eigen::MatrixXd& s, const Eigen::VectorXd& d, const Eigen::VectorXd& lo,
                                   const Eigen::VectorXd& hi) {
  const double lipschitz = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(s).eigenvalues().maxCoeff();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(d.size()).cwiseMax(lo).cwiseMin(hi), y = x;
  double t = 1.0;
  for (int k = 0; k < 200000; ++k) {
    const Eigen::VectorXd next = (y - (s * y - d) / lipschitz).cwiseMax(lo).cwiseMin(hi);
    const double t_next = 0.5 * (1.0 + std::sqrt(1.0 + 4.0 * t * t));
    y = next + (t - 1.0) / t_next * (next - x);
    x = next;
    t = t_next;
  }
  return x;
}

struct Problem {
  Eigen::MatrixXd s;
  Eigen::VectorXd d, lo, hi;
};

Problem random_problem(int n, int rank, bool box, unsigned seed) {
  std::mt19937 generator(seed);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd b(rank, n);
  for (auto& v : b.reshaped()) v = normal(generator);
  Problem p{b.transpose() * b / n, Eigen::VectorXd(n), Eigen::VectorXd(n), Eigen::VectorXd(n)};
  for (auto& v : p.d) v = normal(generator);
  p.hi.setZero();
  p.lo =
      box ? Eigen::VectorXd::Constant(n, -1.0) : Eigen::VectorXd::Constant(n, -std::numeric_limits<double>::infinity());
  return p;
}

}  // namespace

TEST(BoxQp, FullRankAndSingularProblemsReachKktPoints) {
  for (const auto& [n, rank, box] : std::vector<std::tuple<int, int, bool>>{
           {20, 20, false}, {20, 20, true}, {30, 12, true}, {30, 29, true}, {40, 40, false}}) {
    const auto p = random_problem(n, rank, box, static_cast<unsigned>(n + rank));
    // A sign condition alone with singular S can be unbounded below; those are box problems.
    const auto result = contact::solve_box_qp(p.s, p.d, p.lo, p.hi);
    EXPECT_TRUE(result.report.converged);
    EXPECT_LT(result.report.kkt_residual, 1e-12) << "n " << n << " rank " << rank;
    EXPECT_TRUE((result.x.array() <= p.hi.array()).all() && (result.x.array() >= p.lo.array()).all());
    const Eigen::VectorXd reference = projected_gradient(p.s, p.d, p.lo, p.hi);
    EXPECT_NEAR(objective(p.s, p.d, result.x), objective(p.s, p.d, reference),
                1e-8 * (1.0 + std::abs(objective(p.s, p.d, reference))));
    EXPECT_LT(result.report.iterations, 60);
  }
}

// Degenerate complementarity: components with zero gradient exactly at the bound.
TEST(BoxQp, DegenerateComplementarity) {
  const Eigen::MatrixXd s = Eigen::MatrixXd::Identity(4, 4);
  const Eigen::VectorXd d = (Eigen::VectorXd(4) << 0.0, 1.0, -1.0, 0.0).finished();
  const auto result = contact::solve_box_qp(s, d, Eigen::VectorXd::Constant(4, -5.0), Eigen::VectorXd::Zero(4));
  EXPECT_LT(result.report.kkt_residual, 1e-14);
  EXPECT_NEAR(result.x(0), 0.0, 1e-15);
  EXPECT_NEAR(result.x(1), 0.0, 1e-15);
  EXPECT_NEAR(result.x(2), -1.0, 1e-14);
}

TEST(BoxQp, ScalingTheDataScalesTheSolutionWithTheSameSteps) {
  const auto p = random_problem(25, 25, true, 9);
  const auto reference = contact::solve_box_qp(p.s, p.d, p.lo, p.hi);
  for (double factor : {1e-6, 1e6}) {
    const auto scaled = contact::solve_box_qp(p.s, factor * p.d, factor * p.lo, factor * p.hi);
    EXPECT_LT((scaled.x / factor - reference.x).norm(), 1e-9 * (1.0 + reference.x.norm()));
    EXPECT_EQ(scaled.report.iterations, reference.report.iterations);
  }
}

TEST(BoxQp, EmptyFeasibleSetIsReported) {
  const Eigen::MatrixXd s = Eigen::MatrixXd::Identity(2, 2);
  EXPECT_THROW(contact::solve_box_qp(s, Eigen::VectorXd::Ones(2), Eigen::VectorXd::Ones(2), Eigen::VectorXd::Zero(2)),
               NumericalError);
}
