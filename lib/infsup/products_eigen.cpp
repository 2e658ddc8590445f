// smallest_eigenpair_products: Generalized Davidson on MATSHELL operators, the products of the pencil through
// C callbacks that never let an exception cross SLEPc's frames.
#include "infsup/products_eigen.hpp"

#include <fmt/format.h>
#include <slepceps.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <exception>
#include <stdexcept>

#include "core/error.hpp"
#include "core/petsc_check.hpp"
#include "core/petsc_handle.hpp"
#include "core/petsc_session.hpp"
#include "core/petsc_vector.hpp"

namespace hpcontact::infsup {
namespace {

using MatHandle = PetscHandle<Mat, MatDestroy>;
using VecHandle = PetscHandle<Vec, VecDestroy>;
using EpsHandle = PetscHandle<EPS, EPSDestroy>;

/// One product behind a shell matrix or PC; the first exception it threw, rethrown after the solve.
struct Callback {
  const PencilProducts::Product* product = nullptr;
  std::exception_ptr error;
};

PetscErrorCode apply(Callback& callback, Vec x, Vec y) {
  try {
    const Eigen::VectorXd out = (*callback.product)(to_eigen(x));
    copy_into(out, y);
  } catch (...) {
    if (!callback.error) callback.error = std::current_exception();
    return PETSC_ERR_LIB;
  }
  return 0;
}

PetscErrorCode shell_mult(Mat matrix, Vec x, Vec y) {
  void* context = nullptr;
  const PetscErrorCode code = MatShellGetContext(matrix, &context);
  return code != 0 ? code : apply(*static_cast<Callback*>(context), x, y);
}

PetscErrorCode shell_precondition(PC pc, Vec x, Vec y) {
  void* context = nullptr;
  const PetscErrorCode code = PCShellGetContext(pc, &context);
  return code != 0 ? code : apply(*static_cast<Callback*>(context), x, y);
}

void make_shell_matrix(Eigen::Index size, Callback& callback, MatHandle& matrix) {
  const auto n = static_cast<PetscInt>(size);
  HPC_PETSC_CALL(MatCreateShell(PETSC_COMM_SELF, n, n, n, n, &callback, matrix.out()));
  HPC_PETSC_CALL(MatShellSetOperation(matrix.get(), MATOP_MULT, reinterpret_cast<void (*)(void)>(shell_mult)));
  HPC_PETSC_CALL(MatSetOption(matrix.get(), MAT_SYMMETRIC, PETSC_TRUE));
  HPC_PETSC_CALL(MatSetOption(matrix.get(), MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
}

/// Residuals relative to a scale (λ_max) instead of to λ: a singular S has λ_min = 0.
PetscErrorCode relative_to_scale(EPS, PetscScalar, PetscScalar, PetscReal residual, PetscReal* estimate,
                                 void* context) {
  *estimate = residual / *static_cast<double*>(context);
  return 0;
}

struct Eigensolve {
  double lambda = 0.0;
  Eigen::VectorXd x;
  int iterations = 0;
  std::string method;
};

struct Operators {
  Callback s, g, t;
  MatHandle s_matrix, g_matrix;
};

void rethrow_callback_errors(const Operators& operators) {
  for (const Callback* callback : {&operators.s, &operators.g, &operators.t})
    if (callback->error) std::rethrow_exception(callback->error);
}

/// Generalized Davidson (or the -…eps_type given) for the smallest eigenvalue, its residual norm
/// tested relative to `scale` (λ_max ‖G‖).
Eigensolve run_eigensolver(Operators& operators, double tolerance, double scale, const Eigen::VectorXd& start,
                           const std::string& prefix) {
  EpsHandle eps;
  HPC_PETSC_CALL(EPSCreate(PETSC_COMM_SELF, eps.out()));
  HPC_PETSC_CALL(EPSSetOperators(eps.get(), operators.s_matrix.get(), operators.g_matrix.get()));
  HPC_PETSC_CALL(EPSSetProblemType(eps.get(), EPS_GHEP));
  HPC_PETSC_CALL(EPSSetType(eps.get(), EPSGD));
  HPC_PETSC_CALL(EPSSetWhichEigenpairs(eps.get(), EPS_SMALLEST_REAL));
  HPC_PETSC_CALL(EPSSetDimensions(eps.get(), 1, PETSC_DEFAULT, PETSC_DEFAULT));
  HPC_PETSC_CALL(EPSSetTolerances(eps.get(), tolerance, 2000));
  HPC_PETSC_CALL(EPSSetConvergenceTestFunction(eps.get(), relative_to_scale, &scale, nullptr));
  ST st = nullptr;
  KSP ksp = nullptr;
  PC pc = nullptr;
  HPC_PETSC_CALL(EPSGetST(eps.get(), &st));
  HPC_PETSC_CALL(STSetType(st, STPRECOND));
  HPC_PETSC_CALL(STGetKSP(st, &ksp));
  HPC_PETSC_CALL(KSPSetType(ksp, KSPPREONLY));
  HPC_PETSC_CALL(KSPGetPC(ksp, &pc));
  HPC_PETSC_CALL(PCSetType(pc, PCSHELL));
  HPC_PETSC_CALL(PCShellSetContext(pc, &operators.t));
  HPC_PETSC_CALL(PCShellSetApply(pc, shell_precondition));
  VecHandle initial;
  HPC_PETSC_CALL(MatCreateVecs(operators.s_matrix.get(), initial.out(), nullptr));
  copy_into(start, initial.get());
  Vec initial_vec = initial.get();
  HPC_PETSC_CALL(EPSSetInitialSpace(eps.get(), 1, &initial_vec));
  HPC_PETSC_CALL(EPSSetOptionsPrefix(eps.get(), prefix.c_str()));
  HPC_PETSC_CALL(EPSSetFromOptions(eps.get()));
  // (a callback's exception ends the solve with an error code: returned quietly, then rethrown)
  HPC_PETSC_CALL(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
  const PetscErrorCode solved = EPSSolve(eps.get());
  PetscPopErrorHandler();
  rethrow_callback_errors(operators);
  HPC_PETSC_CALL(solved);
  PetscInt converged = 0, iterations = 0;
  HPC_PETSC_CALL(EPSGetConverged(eps.get(), &converged));
  HPC_PETSC_CALL(EPSGetIterationNumber(eps.get(), &iterations));
  if (converged < 1) {
    PetscReal tol = 0.0;
    PetscInt max_iterations = 0;
    HPC_PETSC_CALL(EPSGetTolerances(eps.get(), &tol, &max_iterations));
    throw NumericalError(
        fmt::format("α by products: the eigensolver for the smallest eigenvalue of (S_G, G) did not converge in {} "
                    "iterations (tolerance {:.1e}; raise -{}eps_max_it or -{}eps_tol)",
                    iterations, tol, prefix, prefix));
  }
  Eigensolve out;
  VecHandle vector;
  HPC_PETSC_CALL(MatCreateVecs(operators.s_matrix.get(), vector.out(), nullptr));
  PetscScalar lambda = 0.0, imaginary = 0.0;
  HPC_PETSC_CALL(EPSGetEigenpair(eps.get(), 0, &lambda, &imaginary, vector.get(), nullptr));
  out.lambda = lambda;
  out.x = to_eigen(vector.get());
  out.iterations = static_cast<int>(iterations);
  EPSType type = nullptr;
  HPC_PETSC_CALL(EPSGetType(eps.get(), &type));
  out.method = fmt::format("slepc: eps {} ({} iterations), st precond, pc shell T ≈ G⁻¹, products only",
                           type != nullptr ? type : "(none)", iterations);
  return out;
}

Eigen::VectorXd fixed_start(Eigen::Index n) {
  return Eigen::VectorXd::NullaryExpr(n, [](Eigen::Index k) { return 1.0 + 0.5 * std::sin(static_cast<double>(k)); });
}

}  // namespace

RitzEstimate krylov_ritz_estimate(const PencilProducts& pencil, int max_steps) {
  const Eigen::Index n = pencil.size;
  const int steps = static_cast<int>(std::min<Eigen::Index>(max_steps, n));
  Eigen::MatrixXd basis(n, steps), s_basis(n, steps), g_basis(n, steps);
  Eigen::VectorXd v = fixed_start(n).normalized();
  RitzEstimate out;
  double previous = 0.0;
  for (int k = 0; k < steps; ++k) {
    basis.col(k) = v;
    s_basis.col(k) = pencil.s(v);
    g_basis.col(k) = pencil.g(v);
    const auto used = k + 1;
    const Eigen::MatrixXd a = basis.leftCols(used).transpose() * s_basis.leftCols(used);
    const Eigen::MatrixXd b = basis.leftCols(used).transpose() * g_basis.leftCols(used);
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ritz(0.5 * (a + a.transpose()),
                                                                         0.5 * (b + b.transpose()));
    if (ritz.info() != Eigen::Success) {
      if (k == 0) throw NumericalError("α by products: vᵀ G v ≤ 0 for the start vector: G is not positive definite");
      break;  // (a nearly dependent basis: keep the previous step's estimate)
    }
    out.largest = ritz.eigenvalues()(k);
    out.g_norm = std::max(out.g_norm, b.selfadjointView<Eigen::Lower>().eigenvalues().maxCoeff());
    out.smallest_vector = basis.leftCols(used) * ritz.eigenvectors().col(0);
    out.steps = used;
    if (k > 2 && std::abs(out.largest - previous) <= 1e-6 * std::abs(out.largest)) break;
    previous = out.largest;
    // the next direction T S v, orthonormalized against the basis (twice: it stays orthonormal)
    Eigen::VectorXd w = pencil.preconditioner(s_basis.col(k));
    const double before = w.norm();
    for (int pass = 0; pass < 2; ++pass) w -= basis.leftCols(used) * (basis.leftCols(used).transpose() * w);
    const double norm = w.norm();
    if (!(norm > 1e-10 * before)) break;  // an invariant subspace
    v = w / norm;
  }
  return out;
}

SmallestEigenpair smallest_eigenpair_products(const PencilProducts& pencil, const RitzEstimate& estimate,
                                              const Eigen::VectorXd& initial, double tolerance,
                                              const std::string& options_prefix) {
  HPC_VERIFY(pencil.size > 0 && pencil.s && pencil.g && pencil.preconditioner,
             "smallest_eigenpair_products: an empty pencil or a missing product");
  HPC_VERIFY(initial.size() == 0 || initial.size() == pencil.size, "smallest_eigenpair_products: start of wrong size");
  if (!ensure_petsc_initialized())
    throw std::logic_error("α by products: SLEPc is not initialized (create a PetscSession first)");
  Operators operators;
  operators.s.product = &pencil.s;
  operators.g.product = &pencil.g;
  operators.t.product = &pencil.preconditioner;
  make_shell_matrix(pencil.size, operators.s, operators.s_matrix);
  make_shell_matrix(pencil.size, operators.g, operators.g_matrix);
  const std::string prefix = options_prefix + "products_";
  const double lambda_max = estimate.largest;
  if (!(lambda_max > 0.0) || !(estimate.g_norm > 0.0))
    throw NumericalError(fmt::format("α by products: λ_max of (S_G, G) is {:.3e}: S_G vanishes", lambda_max));
  const Eigen::VectorXd& start = initial.size() > 0 ? initial : estimate.smallest_vector;
  Eigensolve smallest = run_eigensolver(operators, tolerance, lambda_max * estimate.g_norm, start, prefix);
  double lambda = smallest.lambda;
  if (lambda < 0.0) {
    // As the dense paths: a zero eigenvalue moved by round-off is 0, a clearly negative one an error.
    if (-lambda > kRoundOffZero * lambda_max)
      throw NumericalError(fmt::format(
          "α by products: S is not positive semi-definite: lambda_min = {:.6e} < -{:.0e} * lambda_max = {:.6e}", lambda,
          kRoundOffZero, lambda_max));
    lambda = 0.0;
  }
  Eigen::VectorXd x = std::move(smallest.x);
  const Eigen::VectorXd gx = pencil.g(x);
  const double g_norm_squared = x.dot(gx);
  if (!std::isfinite(g_norm_squared) || !(g_norm_squared > 0.0))
    throw NumericalError(fmt::format("α by products: eigenvector has x^T G x = {:.3e}", g_norm_squared));
  const double norm = std::sqrt(g_norm_squared);
  x /= norm;
  Eigen::Index largest_entry = 0;
  x.cwiseAbs().maxCoeff(&largest_entry);
  const double sign = x(largest_entry) < 0.0 ? -1.0 : 1.0;
  x *= sign;
  SmallestEigenpair pair;
  pair.residual = (pencil.s(x) - lambda * (sign / norm) * gx).norm() / (lambda_max * (gx / norm).norm());
  pair.eigenvalue = lambda;
  pair.eigenvector = std::move(x);
  pair.largest_eigenvalue = lambda_max;
  pair.iterations = smallest.iterations;
  pair.method = smallest.method;
  return pair;
}

}  // namespace hpcontact::infsup
