// Constrained solves by projected CG (BddcSolver::constrained with GAMG and BDDC, one rank): on a
// 3-D grid Laplacian with mortar-like rows on one face, x and μ equal the dense KKT solve of
// [A Cᵀ; C 0], the projected CG takes at most about twice the unconstrained one's iterations, a
// warm start from the answer takes none, and dependent rows are refused.
#include <gtest/gtest.h>

#include <Eigen/SparseLU>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "linalg/bddc_solver.hpp"
#include "support/slepc_test_environment.hpp"

namespace hpcontact::linalg {
namespace {

constexpr int kGrid = 14;  // nodes per axis; the face z = 0 is held by the constraints' rows only

int node(int i, int j, int k) { return i + kGrid * (j + kGrid * k); }

// The 7-point Laplacian, zero outside the grid (SPD), lower triangle.
std::vector<Eigen::Triplet<double>> laplacian() {
  std::vector<Eigen::Triplet<double>> lower;
  for (int k = 0; k < kGrid; ++k)
    for (int j = 0; j < kGrid; ++j)
      for (int i = 0; i < kGrid; ++i) {
        const int row = node(i, j, k);
        lower.emplace_back(row, row, 6.0);
        if (i > 0) lower.emplace_back(row, node(i - 1, j, k), -1.0);
        if (j > 0) lower.emplace_back(row, node(i, j - 1, k), -1.0);
        if (k > 0) lower.emplace_back(row, node(i, j, k - 1), -1.0);
      }
  return lower;
}

// Rows on the face k = 0, each a tent over 3 × 3 nodes centred at (2a + 1, 2b + 1) (overlapping
// like P_1 mortar rows on a coarser mesh), plus `duplicate` copies of the first row.
Coupling face_rows(int duplicate = 0) {
  std::vector<Eigen::Triplet<double>> entries;
  int row = 0;
  auto add_tent = [&](int ci, int cj) {
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di)
        entries.emplace_back(row, node(ci + di, cj + dj, 0), (2.0 - std::abs(di)) * (2.0 - std::abs(dj)) / 4.0);
    ++row;
  };
  for (int b = 0; 2 * b + 2 < kGrid; ++b)
    for (int a = 0; 2 * a + 2 < kGrid; ++a) add_tent(2 * a + 1, 2 * b + 1);
  for (int d = 0; d < duplicate; ++d) add_tent(1, 1);
  Coupling c(row, kGrid * kGrid * kGrid);
  c.setFromTriplets(entries.begin(), entries.end());
  return c;
}

struct Reference {
  Eigen::VectorXd x, mu;
};

Reference dense_kkt(const std::vector<Eigen::Triplet<double>>& lower, const Coupling& c, const std::vector<int>& active,
                    const Eigen::VectorXd& values, const Eigen::VectorXd& rhs) {
  const int n = static_cast<int>(c.cols()), k = static_cast<int>(active.size());
  std::vector<Eigen::Triplet<double>> entries;
  for (const auto& e : lower) {
    entries.emplace_back(e.row(), e.col(), e.value());
    if (e.row() != e.col()) entries.emplace_back(e.col(), e.row(), e.value());
  }
  for (int a = 0; a < k; ++a)
    for (Coupling::InnerIterator it(c, active[a]); it; ++it) {
      entries.emplace_back(n + a, static_cast<int>(it.col()), it.value());
      entries.emplace_back(static_cast<int>(it.col()), n + a, it.value());
    }
  Eigen::SparseMatrix<double> kkt(n + k, n + k);
  kkt.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(kkt);
  Eigen::VectorXd b(n + k);
  b << rhs, values;
  const Eigen::VectorXd solution = lu.solve(b);
  return {solution.head(n), solution.tail(k)};
}

TEST(ProjectedCg, EqualsTheDenseKktSolveWithGamgAndBddc) {
  const auto lower = laplacian();
  const Coupling c = face_rows();
  const int n = kGrid * kGrid * kGrid;
  // Every other row active, pressed in by values of both signs.
  std::vector<int> active;
  for (int i = 0; i < c.rows(); i += 2) active.push_back(i);
  Eigen::VectorXd values(static_cast<Eigen::Index>(active.size()));
  for (Eigen::Index a = 0; a < values.size(); ++a) values(a) = -0.1 + 0.02 * std::sin(1.0 + a);
  const Eigen::VectorXd rhs = Eigen::VectorXd::Constant(n, 1e-3);
  const Reference reference = dense_kkt(lower, c, active, values, rhs);
  for (const auto preconditioner : {KrylovPreconditioner::gamg, KrylovPreconditioner::bddc}) {
    const BddcSolver solver(MPI_COMM_WORLD, n, lower, 1e-12, {}, preconditioner);
    (void)solver.solve(Eigen::MatrixXd(rhs));
    const long unconstrained = solver.iterations()->total;
    const auto constrained = solver.constrained(c);
    ASSERT_NE(constrained, nullptr);
    EXPECT_EQ(constrained->relative_tolerance(), 1e-12);
    const ConstrainedSolution out = constrained->solve(rhs, active, values, Eigen::VectorXd::Zero(n), 1e-12);
    EXPECT_LT((out.x - reference.x).lpNorm<Eigen::Infinity>(), 1e-9 * reference.x.lpNorm<Eigen::Infinity>());
    EXPECT_LT((out.multipliers - reference.mu).lpNorm<Eigen::Infinity>(),
              1e-8 * reference.mu.lpNorm<Eigen::Infinity>());
    EXPECT_LE(out.relative_residual, 1e-12);
    // (the projection in D's metric costs iterations over the unconstrained solve: 16 against 14
    // with GAMG here, 10 against 1 with BDDC, exact on one subdomain)
    EXPECT_LE(out.iterations, 2 * unconstrained + 10);
    EXPECT_GE(constrained->preconditioner_applications(), out.iterations);
    // From the answer: no iteration.
    const ConstrainedSolution again = constrained->solve(rhs, active, values, out.x, 1e-10);
    EXPECT_EQ(again.iterations, 0);
    EXPECT_LT((again.multipliers - reference.mu).lpNorm<Eigen::Infinity>(),
              1e-8 * reference.mu.lpNorm<Eigen::Infinity>());
  }
}

TEST(ProjectedCg, RefusesLinearlyDependentRows) {
  const auto lower = laplacian();
  const Coupling c = face_rows(1);
  const int n = kGrid * kGrid * kGrid;
  const BddcSolver solver(MPI_COMM_WORLD, n, lower, 1e-12, {}, KrylovPreconditioner::gamg);
  const auto constrained = solver.constrained(c);
  const std::vector<int> active{0, static_cast<int>(c.rows()) - 1};  // the first row and its copy
  EXPECT_THROW((void)constrained->solve(Eigen::VectorXd::Zero(n), active, Eigen::Vector2d(-0.1, -0.1),
                                        Eigen::VectorXd::Zero(n), 1e-12),
               NumericalError);
}

}  // namespace
}  // namespace hpcontact::linalg
