// The generalized eigenproblem S x = λ G x behind α² = λ_min: SLEPc (shift-and-invert,
// options -infsup_*) against the dense Eigen solver, on pencils with known spectra, singular and
// nearly singular S, other EPS types selected at run time, and broken input.
#include "infsup/generalized_eigen.hpp"

#include <gtest/gtest.h>
#include <slepcsys.h>

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <cmath>
#include <functional>
#include <random>
#include <string>

#include "core/error.hpp"
#include "support/slepc_test_environment.hpp"

using namespace hpcontact;
using infsup::SmallestEigenpair;

namespace {

/// Sets a PETSc option for one scope, as if given on the command line.
class ScopedPetscOption {
 public:
  ScopedPetscOption(std::string name, const std::string& value) : name_(std::move(name)) {
    EXPECT_EQ(PetscOptionsSetValue(nullptr, name_.c_str(), value.c_str()), 0);
  }
  ~ScopedPetscOption() { PetscOptionsClearValue(nullptr, name_.c_str()); }
  ScopedPetscOption(const ScopedPetscOption&) = delete;
  ScopedPetscOption& operator=(const ScopedPetscOption&) = delete;

 private:
  std::string name_;
};

Eigen::MatrixXd random_matrix(int rows, int cols, unsigned seed) {
  std::mt19937 generator(seed);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd a(rows, cols);
  for (int j = 0; j < cols; ++j)
    for (int i = 0; i < rows; ++i) a(i, j) = normal(generator);
  return a;
}

/// Well conditioned SPD matrix, shape (n, n): AᵀA/n + I.
Eigen::MatrixXd random_spd(int n, unsigned seed) {
  const Eigen::MatrixXd a = random_matrix(n, n, seed);
  return a.transpose() * a / n + Eigen::MatrixXd::Identity(n, n);
}

/// A pencil with prescribed eigenvalues: G = L Lᵀ random SPD, Q orthogonal, S = L Q Λ Qᵀ Lᵀ.
/// Then S V = G V Λ with V = L⁻ᵀ Q, VᵀGV = I, so (Λ_i, column i of V) are its eigenpairs.
struct KnownPencil {
  Eigen::MatrixXd s, g;
  Eigen::MatrixXd vectors;  ///< shape (n, n), G-orthonormal eigenvectors by column
};

KnownPencil pencil_with_spectrum(const Eigen::VectorXd& values, unsigned seed) {
  const int n = static_cast<int>(values.size());
  KnownPencil p;
  p.g = random_spd(n, seed);
  const Eigen::MatrixXd l = p.g.llt().matrixL();
  const Eigen::MatrixXd q = random_matrix(n, n, seed + 1).householderQr().householderQ();
  const Eigen::MatrixXd lq = l * q;
  p.s = lq * values.asDiagonal() * lq.transpose();
  p.s = 0.5 * (p.s + p.s.transpose());
  p.vectors = l.transpose().triangularView<Eigen::Upper>().solve(q);
  return p;
}

/// Eigenvalues 0.5, ..., 20 spread geometrically, the first one replaced by `smallest`.
Eigen::VectorXd spectrum(int n, double smallest) {
  Eigen::VectorXd values(n);
  for (int i = 0; i < n; ++i) values(i) = 0.5 * std::pow(40.0, static_cast<double>(i) / (n - 1));
  values(0) = smallest;
  return values;
}

/// |xᵀ G y| for G-normalized x, y: 1 when they span the same line.
double g_cosine(const Eigen::VectorXd& x, const Eigen::VectorXd& y, const Eigen::MatrixXd& g) {
  return std::abs(x.dot(g * y));
}

/// Both results are well-formed: G-normalized, sign rule, small residual, λ_min within range.
void expect_well_formed(const SmallestEigenpair& pair, const Eigen::MatrixXd& g) {
  SCOPED_TRACE(pair.method);
  EXPECT_NEAR(pair.eigenvector.dot(g * pair.eigenvector), 1.0, 1e-12);
  Eigen::Index largest = 0;
  pair.eigenvector.cwiseAbs().maxCoeff(&largest);
  EXPECT_GT(pair.eigenvector(largest), 0.0);
  EXPECT_LT(pair.residual, 1e-11);
  EXPECT_GE(pair.eigenvalue, 0.0);
  EXPECT_LE(pair.eigenvalue, pair.largest_eigenvalue);
}

void expect_agree(const SmallestEigenpair& slepc, const SmallestEigenpair& dense, const Eigen::MatrixXd& g) {
  SCOPED_TRACE(slepc.method);
  EXPECT_NEAR(slepc.eigenvalue, dense.eigenvalue, 1e-8 * dense.eigenvalue);
  EXPECT_NEAR(slepc.largest_eigenvalue, dense.largest_eigenvalue, 1e-6 * dense.largest_eigenvalue);
  EXPECT_NEAR(g_cosine(slepc.eigenvector, dense.eigenvector, g), 1.0, 1e-8);
  // The sign rule makes them equal, not only parallel.
  EXPECT_LT((slepc.eigenvector - dense.eigenvector).norm(), 1e-6 * dense.eigenvector.norm());
}

std::string numerical_error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const NumericalError& error) {
    return error.what();
  }
  return "(no NumericalError thrown)";
}

}  // namespace

TEST(GeneralizedEigen, RandomSpdPencilSlepcAgreesWithDense) {
  const Eigen::MatrixXd s = random_spd(50, 1);
  const Eigen::MatrixXd g = random_spd(50, 2);
  const auto dense = infsup::smallest_eigenpair_dense(s, g);
  const auto slepc = infsup::smallest_eigenpair_slepc(s, g);
  expect_well_formed(dense, g);
  expect_well_formed(slepc, g);
  expect_agree(slepc, dense, g);
  EXPECT_EQ(dense.iterations, 0);
  EXPECT_GE(slepc.iterations, 1);
  EXPECT_NE(slepc.method.find("eps krylovschur, st sinvert"), std::string::npos) << slepc.method;
  EXPECT_NE(slepc.method.find("pc cholesky"), std::string::npos) << slepc.method;
}

TEST(GeneralizedEigen, KnownSpectrumIsFoundByBothPaths) {
  const Eigen::VectorXd values = spectrum(50, 0.3);
  const auto p = pencil_with_spectrum(values, 3);
  for (const auto& pair : {infsup::smallest_eigenpair_dense(p.s, p.g), infsup::smallest_eigenpair_slepc(p.s, p.g)}) {
    SCOPED_TRACE(pair.method);
    expect_well_formed(pair, p.g);
    EXPECT_NEAR(pair.eigenvalue, 0.3, 1e-12);
    EXPECT_NEAR(pair.largest_eigenvalue, 20.0, 1e-7);
    EXPECT_NEAR(g_cosine(pair.eigenvector, p.vectors.col(0), p.g), 1.0, 1e-10);
  }
}

TEST(GeneralizedEigen, SingularLowRankSIsZeroWithNullVector) {
  // S = BᵀB with B of 45 rows: a null space of dimension 5.
  const int n = 50;
  const Eigen::MatrixXd b = random_matrix(45, n, 4);
  const Eigen::MatrixXd s = b.transpose() * b;
  const Eigen::MatrixXd g = random_spd(n, 5);
  const auto dense = infsup::smallest_eigenpair_dense(s, g);
  const auto slepc = infsup::smallest_eigenpair_slepc(s, g);
  EXPECT_NEAR(slepc.largest_eigenvalue, dense.largest_eigenvalue, 1e-6 * dense.largest_eigenvalue);
  for (const auto& pair : {dense, slepc}) {
    SCOPED_TRACE(pair.method);
    expect_well_formed(pair, g);
    EXPECT_LE(pair.eigenvalue, infsup::kRoundOffZero * pair.largest_eigenvalue);
    // x lies in the null space of S (equivalently of B).
    EXPECT_LT((s * pair.eigenvector).norm(), 1e-12 * s.norm() * pair.eigenvector.norm());
  }
}

TEST(GeneralizedEigen, SingularSWithKnownNullVector) {
  const auto p = pencil_with_spectrum(spectrum(50, 0.0), 6);
  const auto dense = infsup::smallest_eigenpair_dense(p.s, p.g);
  const auto slepc = infsup::smallest_eigenpair_slepc(p.s, p.g);
  for (const auto& pair : {dense, slepc}) {
    SCOPED_TRACE(pair.method);
    expect_well_formed(pair, p.g);
    EXPECT_LE(pair.eigenvalue, infsup::kRoundOffZero * pair.largest_eigenvalue);
    EXPECT_NEAR(g_cosine(pair.eigenvector, p.vectors.col(0), p.g), 1.0, 1e-10);
  }
  EXPECT_LT((slepc.eigenvector - dense.eigenvector).norm(), 1e-6 * dense.eigenvector.norm());
}

TEST(GeneralizedEigen, NearlySingularSAgreesToRelativeOrAbsoluteTolerance) {
  const double lambda_min = 1e-10 * 20.0;
  const auto p = pencil_with_spectrum(spectrum(50, lambda_min), 7);
  const auto dense = infsup::smallest_eigenpair_dense(p.s, p.g);
  const auto slepc = infsup::smallest_eigenpair_slepc(p.s, p.g);
  const double tolerance = std::max(1e-8 * lambda_min, 1e-12 * dense.largest_eigenvalue);
  for (const auto& pair : {dense, slepc}) {
    SCOPED_TRACE(pair.method);
    expect_well_formed(pair, p.g);
    EXPECT_NEAR(pair.eigenvalue, lambda_min, tolerance);
    EXPECT_NEAR(g_cosine(pair.eigenvector, p.vectors.col(0), p.g), 1.0, 1e-10);
  }
  EXPECT_NEAR(slepc.eigenvalue, dense.eigenvalue, tolerance);
}

TEST(GeneralizedEigen, RunTimeOptionsSelectLapackAndArpack) {
  const Eigen::MatrixXd s = random_spd(50, 8);
  const Eigen::MatrixXd g = random_spd(50, 9);
  const auto dense = infsup::smallest_eigenpair_dense(s, g);
  const auto singular = pencil_with_spectrum(spectrum(50, 0.0), 10);
  const auto dense_singular = infsup::smallest_eigenpair_dense(singular.s, singular.g);
  for (const std::string type : {"lapack", "arpack"}) {
    SCOPED_TRACE(type);
    const ScopedPetscOption option("-infsup_eps_type", type);
    const auto slepc = infsup::smallest_eigenpair_slepc(s, g);
    EXPECT_NE(slepc.method.find("eps " + type), std::string::npos) << slepc.method;
    if (type == "lapack") {  // all eigenvalues computed: λ_max needs no second solve
      EXPECT_NE(slepc.method.find("lambda_max from the same solve"), std::string::npos);
    }
    expect_well_formed(slepc, g);
    expect_agree(slepc, dense, g);

    const auto slepc_singular = infsup::smallest_eigenpair_slepc(singular.s, singular.g);
    expect_well_formed(slepc_singular, singular.g);
    EXPECT_LE(slepc_singular.eigenvalue, infsup::kRoundOffZero * slepc_singular.largest_eigenvalue);
    EXPECT_NEAR(g_cosine(slepc_singular.eigenvector, dense_singular.eigenvector, singular.g), 1.0, 1e-8);
  }
  // Cleared again: back to the default.
  const auto slepc = infsup::smallest_eigenpair_slepc(s, g);
  EXPECT_NE(slepc.method.find("eps krylovschur"), std::string::npos) << slepc.method;
}

TEST(GeneralizedEigen, ClusteredTopOfSpectrumStillGivesLambdaMaxScale) {
  // Neumann 1D Laplacian against the P1 mass matrix: singular (constants), and the top of the
  // spectrum clusters below 12, where Lanczos residuals converge slowly. λ_max is then the
  // largest Ritz value after the restart budget: a lower bound, good to a few digits.
  const int n = 200;
  Eigen::MatrixXd s = Eigen::MatrixXd::Zero(n, n), g = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    s(i, i) = (i == 0 || i == n - 1) ? 1.0 : 2.0;
    g(i, i) = (i == 0 || i == n - 1) ? 2.0 / 6.0 : 4.0 / 6.0;
    if (i + 1 < n) {
      s(i, i + 1) = s(i + 1, i) = -1.0;
      g(i, i + 1) = g(i + 1, i) = 1.0 / 6.0;
    }
  }
  const auto dense = infsup::smallest_eigenpair_dense(s, g);
  const auto slepc = infsup::smallest_eigenpair_slepc(s, g);
  EXPECT_LE(slepc.largest_eigenvalue, dense.largest_eigenvalue * (1.0 + 1e-12));
  EXPECT_NEAR(slepc.largest_eigenvalue, dense.largest_eigenvalue, 1e-3 * dense.largest_eigenvalue);
  const Eigen::VectorXd constant = Eigen::VectorXd::Ones(n) / std::sqrt(g.sum());
  for (const auto& pair : {dense, slepc}) {
    SCOPED_TRACE(pair.method);
    expect_well_formed(pair, g);
    EXPECT_LE(pair.eigenvalue, infsup::kRoundOffZero * pair.largest_eigenvalue);
    EXPECT_LT((pair.eigenvector - constant).norm(), 1e-8 * constant.norm());
  }
}

TEST(GeneralizedEigen, OptionsPrefixIsHonoured) {
  const Eigen::MatrixXd s = random_spd(30, 11);
  const Eigen::MatrixXd g = random_spd(30, 12);
  const ScopedPetscOption option("-other_eps_type", "lapack");
  EXPECT_NE(infsup::smallest_eigenpair_slepc(s, g, "other_").method.find("eps lapack"), std::string::npos);
  EXPECT_NE(infsup::smallest_eigenpair_slepc(s, g).method.find("eps krylovschur"), std::string::npos);
}

TEST(GeneralizedEigen, TinyPencils) {
  for (int n : {1, 2, 3, 5}) {
    SCOPED_TRACE(n);
    const Eigen::MatrixXd s = random_spd(n, 13);
    const Eigen::MatrixXd g = random_spd(n, 14);
    const auto dense = infsup::smallest_eigenpair_dense(s, g);
    const auto slepc = infsup::smallest_eigenpair_slepc(s, g);
    expect_well_formed(slepc, g);
    expect_agree(slepc, dense, g);
  }
}

TEST(GeneralizedEigen, ZeroSHasZeroEigenvalue) {
  const Eigen::MatrixXd s = Eigen::MatrixXd::Zero(10, 10);
  const Eigen::MatrixXd g = random_spd(10, 15);
  for (const auto& pair : {infsup::smallest_eigenpair_dense(s, g), infsup::smallest_eigenpair_slepc(s, g)}) {
    SCOPED_TRACE(pair.method);
    EXPECT_EQ(pair.eigenvalue, 0.0);
    EXPECT_NEAR(pair.eigenvector.dot(g * pair.eigenvector), 1.0, 1e-12);
  }
}

TEST(GeneralizedEigen, RoundOffNegativeIsReportedAsZeroLargerNegativeIsAnError) {
  // λ_min = −1e-14 λ_max: round-off size, reported as exactly 0.
  const auto tiny = pencil_with_spectrum(spectrum(40, -1e-14 * 20.0), 16);
  EXPECT_EQ(infsup::smallest_eigenpair_dense(tiny.s, tiny.g).eigenvalue, 0.0);
  EXPECT_EQ(infsup::smallest_eigenpair_slepc(tiny.s, tiny.g).eigenvalue, 0.0);
  // λ_min = −1e-6 λ_max: S is indefinite.
  const auto indefinite = pencil_with_spectrum(spectrum(40, -1e-6 * 20.0), 17);
  for (const auto& message :
       {numerical_error_of([&] { infsup::smallest_eigenpair_dense(indefinite.s, indefinite.g); }),
        numerical_error_of([&] { infsup::smallest_eigenpair_slepc(indefinite.s, indefinite.g); })})
    EXPECT_NE(message.find("S is not positive semi-definite"), std::string::npos) << message;
}

TEST(GeneralizedEigen, NonDefiniteGIsANumericalError) {
  const int n = 20;
  const Eigen::MatrixXd s = random_spd(n, 18);
  // G with one negative eigenvalue, and G singular (semi-definite).
  const Eigen::MatrixXd q = random_matrix(n, n, 19).householderQr().householderQ();
  Eigen::VectorXd values = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  values(3) = -0.5;
  const Eigen::MatrixXd indefinite = q * values.asDiagonal() * q.transpose();
  Eigen::MatrixXd singular = Eigen::MatrixXd::Identity(n, n);
  singular(n - 1, n - 1) = 0.0;
  for (const Eigen::MatrixXd& g : {indefinite, singular}) {
    for (const auto& message : {numerical_error_of([&] { infsup::smallest_eigenpair_dense(s, g); }),
                                numerical_error_of([&] { infsup::smallest_eigenpair_slepc(s, g); })})
      EXPECT_NE(message.find("G (20x20) is not positive definite"), std::string::npos) << message;
  }
}

TEST(GeneralizedEigen, NonSymmetricOrNonFiniteInputIsANumericalError) {
  Eigen::MatrixXd s = random_spd(10, 20);
  const Eigen::MatrixXd g = random_spd(10, 21);
  s(0, 1) += 1e-3;
  const std::string asymmetric = numerical_error_of([&] { infsup::smallest_eigenpair_slepc(s, g); });
  EXPECT_NE(asymmetric.find("S is not symmetric"), std::string::npos) << asymmetric;
  s(0, 1) = s(1, 0) = std::nan("");
  const std::string not_finite = numerical_error_of([&] { infsup::smallest_eigenpair_dense(s, g); });
  EXPECT_NE(not_finite.find("S has non-finite entries"), std::string::npos) << not_finite;
  EXPECT_THROW(infsup::smallest_eigenpair_dense(Eigen::MatrixXd::Identity(3, 3), g), std::logic_error);
}

TEST(GeneralizedEigen, NoConvergenceIsANumericalErrorWithEstimates) {
  const Eigen::MatrixXd s = random_spd(50, 22);
  const Eigen::MatrixXd g = random_spd(50, 23);
  const ScopedPetscOption max_it("-infsup_eps_max_it", "1");
  const ScopedPetscOption ncv("-infsup_eps_ncv", "3");
  const std::string message = numerical_error_of([&] { infsup::smallest_eigenpair_slepc(s, g); });
  EXPECT_NE(message.find("converged 0 of 1 eigenpairs after 1 of at most 1 iterations"), std::string::npos) << message;
  EXPECT_NE(message.find("error estimate"), std::string::npos) << message;
}

TEST(GeneralizedEigen, PetscErrorsCarryPetscsMessage) {
  const Eigen::MatrixXd s = random_spd(10, 24);
  const Eigen::MatrixXd g = random_spd(10, 25);
  const ScopedPetscOption option("-infsup_eps_type", "no_such_solver");
  const std::string message = numerical_error_of([&] { infsup::smallest_eigenpair_slepc(s, g); });
  EXPECT_NE(message.find("EPSSetFromOptions"), std::string::npos) << message;
  EXPECT_NE(message.find("no_such_solver"), std::string::npos) << message;
}
