// Sparse direct solver: CHOLMOD with a trailing (trace) set ordered last. The Schur
// complement B A⁻¹ Bᵀ through the trailing block of the factor must equal a dense computation,
// and so must the fallback by solves when B reaches outside the trailing set.
#include "linalg/sparse_cholesky.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <random>

#include "assembly/coupling.hpp"
#include "assembly/poisson_assembly.hpp"
#include "core/error.hpp"
#include "mesh/contact_boundary.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "space/multiplier_space.hpp"

using namespace hpcontact;

namespace {

struct Operators {
  Eigen::SparseMatrix<double> a;
  linalg::Coupling b;
};

// A = K + M of S^p on the §7 square, B the coupling with M^{p_C} on m segments of Γ_C.
Operators paper_operators(int n, int p, int pc, int m) {
  const auto mesh = mesh::make_paper_square_mesh(n);
  const space::H1Space space(mesh, p);
  const mesh::ContactBoundary contact(mesh);
  const auto boundary = mesh::BoundaryMesh::uniform(2.0, m);  // MultiplierSpace keeps a reference
  const space::MultiplierSpace multipliers(boundary, pc);
  const auto matrices = assembly::assemble_volume_matrices(space, {.stiffness = true, .mass = true});
  return {matrices.stiffness + matrices.mass, assembly::assemble_coupling(space, contact, multipliers)};
}

Eigen::MatrixXd dense_schur(const Operators& o) {
  const Eigen::MatrixXd a = o.a;
  const Eigen::MatrixXd bt = Eigen::MatrixXd(o.b.transpose());
  return Eigen::MatrixXd(o.b) * a.llt().solve(bt);
}

}  // namespace

TEST(SparseCholesky, TrailingBlockSchurComplementEqualsDense) {
  for (const auto& [n, p, pc, m] : {std::tuple{8, 1, 0, 4}, {8, 3, 2, 8}, {6, 5, 4, 3}, {4, 8, 7, 4}}) {
    const auto o = paper_operators(n, p, pc, m);
    const auto trace = linalg::nonzero_columns(o.b);
    const linalg::SparseCholesky factor(o.a, trace);
    EXPECT_EQ(factor.n_trailing(), static_cast<int>(trace.size()));
    const Eigen::MatrixXd expected = dense_schur(o);
    const Eigen::MatrixXd condensed = factor.schur_complement(o.b);
    EXPECT_LT((condensed - expected).norm(), 1e-12 * expected.norm()) << "n " << n << " p " << p;
    EXPECT_EQ((condensed - condensed.transpose()).norm(), 0.0);
    // The same without a trailing set (solves with the full factor).
    const linalg::SparseCholesky plain(o.a);
    EXPECT_EQ(plain.n_trailing(), 0);
    EXPECT_LT((plain.schur_complement(o.b) - expected).norm(), 1e-12 * expected.norm());
  }
}

TEST(SparseCholesky, FallsBackToSolvesWhenBLeavesTheTrailingSet) {
  const auto o = paper_operators(8, 2, 1, 4);
  auto trace = linalg::nonzero_columns(o.b);
  trace.pop_back();  // one column of B now lies outside the trailing set
  const linalg::SparseCholesky factor(o.a, trace);
  const Eigen::MatrixXd expected = dense_schur(o);
  EXPECT_LT((factor.schur_complement(o.b) - expected).norm(), 1e-12 * expected.norm());
}

TEST(SparseCholesky, SolvesMatchDenseAndNonDefiniteIsAnError) {
  const auto o = paper_operators(6, 3, 1, 3);
  const linalg::SparseCholesky factor(o.a, linalg::nonzero_columns(o.b));
  std::mt19937 generator(3);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd rhs(o.a.rows(), 3);
  for (auto& v : rhs.reshaped()) v = normal(generator);
  const Eigen::MatrixXd expected = Eigen::MatrixXd(o.a).llt().solve(rhs);
  EXPECT_LT((factor.solve(rhs) - expected).norm(), 1e-12 * expected.norm());
  EXPECT_LT((factor.solve(Eigen::VectorXd(rhs.col(1))) - expected.col(1)).norm(), 1e-12 * expected.norm());
  EXPECT_GT(factor.factor_nonzeros(), o.a.rows());
  Eigen::SparseMatrix<double> indefinite = o.a;
  indefinite.coeffRef(5, 5) = -1.0;
  EXPECT_THROW(linalg::SparseCholesky(indefinite, {0, 1}), NumericalError);
  EXPECT_THROW(linalg::SparseCholesky{indefinite}, NumericalError);
}
