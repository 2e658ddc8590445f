// smallest_eigenpair_dense (Eigen) and smallest_eigenpair_slepc (SLEPc EPS, shift-and-invert)
// for S x = λ G x, with the checks and normalizations both share.
#include "infsup/generalized_eigen.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <slepceps.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/petsc_check.hpp"
#include "core/petsc_handle.hpp"
#include "core/petsc_session.hpp"
#include "core/petsc_vector.hpp"

namespace hpcontact::infsup {
namespace {

static_assert(std::is_same_v<PetscScalar, double>, "hpcontact needs PETSc built with real double-precision scalars");

/// Largest asymmetry max|A_ij − A_ji| accepted, relative to max|A_ij|. Assembled Schur complements
/// and Gram matrices are symmetric to round-off; more than this is a bug upstream.
constexpr double kSymmetryTolerance = 1e-10;
constexpr double kSmallestTolerance = 1e-12;  ///< EPS tolerance for λ_min
// λ_max is only a scale (zero tests), needed to a few digits. Lanczos finds the *value* of the
// top eigenvalue fast, but when the top of the spectrum is clustered (typical: S_G and G are
// spectrally equivalent) the *residual* converges slowly: for a 1D Laplacian pencil of n = 1000
// the default 125 restarts end at an error estimate 1.3e-4 while the Ritz value is already good
// to 2e-5. Hence a small restart budget, after which the largest Ritz value is accepted (it is a
// Rayleigh quotient, so ≤ λ_max, and within its error estimate of an eigenvalue) if its estimate
// is below kLargestAcceptedEstimate; `method` then says so.
constexpr double kLargestTolerance = 1e-8;
constexpr PetscInt kLargestMaxRestarts = 10;
constexpr double kLargestAcceptedEstimate = 1e-2;

// ---------------------------------------------------------------------------------------------
// Checks and normalizations shared by both paths.

/// The pencil as both solvers see it: exactly symmetric copies of S and G.
struct Pencil {
  Eigen::MatrixXd s;
  Eigen::MatrixXd g;
};

Eigen::MatrixXd checked_symmetric(const Eigen::MatrixXd& a, const char* name, const std::string& where) {
  if (!a.allFinite()) throw NumericalError(fmt::format("{}: {} has non-finite entries", where, name));
  const double scale = a.cwiseAbs().maxCoeff();
  const double asymmetry = (a - a.transpose()).cwiseAbs().maxCoeff();
  if (asymmetry > kSymmetryTolerance * scale)
    throw NumericalError(
        fmt::format("{}: {} is not symmetric: max|{}_ij - {}_ji| = {:.3e} > {:.0e} * max|{}_ij| = {:.3e}", where, name,
                    name, name, asymmetry, kSymmetryTolerance, name, scale));
  // Round-off asymmetry below the tolerance: the dense solver reads one triangle, SLEPc the whole
  // matrix; the symmetric part makes both solve the same problem.
  return 0.5 * (a + a.transpose());
}

Pencil checked_pencil(const Eigen::MatrixXd& S, const Eigen::MatrixXd& G, const std::string& where) {
  HPC_VERIFY(S.rows() > 0 && S.rows() == S.cols() && G.rows() == G.cols() && G.rows() == S.rows(),
             fmt::format("{}: S ({}x{}) and G ({}x{}) must be square, non-empty, of one size", where, S.rows(),
                         S.cols(), G.rows(), G.cols()));
  Pencil pencil{checked_symmetric(S, "S", where), checked_symmetric(G, "G", where)};
  // Without a positive definite G, xᵀGx is no norm and the pencil's spectrum can be anything (a
  // shifted S − σG may even stay definite, so SLEPc would not notice). One Cholesky
  // factorization, n³/3 flops, decides it; small beside either eigensolver.
  const Eigen::LLT<Eigen::MatrixXd> cholesky(pencil.g);
  if (cholesky.info() != Eigen::Success)
    throw NumericalError(
        fmt::format("{}: G ({}x{}) is not positive definite: its Cholesky factorization breaks down "
                    "(min diagonal entry {:.3e})",
                    where, G.rows(), G.cols(), pencil.g.diagonal().minCoeff()));
  return pencil;
}

/// Applies the zero rule to λ_min, G-normalizes x, fixes its sign and computes the residual.
SmallestEigenpair finish(const Pencil& pencil, double lambda, Eigen::VectorXd x, double lambda_max, int iterations,
                         std::string method, const std::string& where) {
  const double scale = std::max(std::abs(lambda_max), std::abs(lambda));
  if (lambda < 0.0) {
    // S is positive semi-definite, so λ_min ≥ 0 exactly; S and G carry round-off of order ε‖S‖,
    // ε‖G‖, which moves a zero eigenvalue by about that much to either side. A negative λ_min
    // within kRoundOffZero·λ_max is therefore reported as the exact value 0 (deliberately, see
    // kRoundOffZero); anything more negative means S is indefinite, and that is an error.
    if (-lambda > kRoundOffZero * scale)
      throw NumericalError(
          fmt::format("{}: S is not positive semi-definite: lambda_min = {:.6e} < -{:.0e} * lambda_max "
                      "(lambda_max = {:.6e}; method {})",
                      where, lambda, kRoundOffZero, lambda_max, method));
    lambda = 0.0;
  }

  const double g_norm_squared = x.dot(pencil.g * x);
  if (!std::isfinite(g_norm_squared) || !(g_norm_squared > 0.0))
    throw NumericalError(
        fmt::format("{}: eigenvector has x^T G x = {:.3e} (method {})", where, g_norm_squared, method));
  x /= std::sqrt(g_norm_squared);
  Eigen::Index largest = 0;
  x.cwiseAbs().maxCoeff(&largest);  // first index among equal magnitudes
  if (x(largest) < 0.0) x = -x;

  SmallestEigenpair pair;
  const double s_norm = pencil.s.norm();  // Frobenius
  const double r_norm = (pencil.s * x - lambda * (pencil.g * x)).norm();
  pair.residual = r_norm / ((s_norm > 0.0 ? s_norm : 1.0) * x.norm());
  pair.eigenvalue = lambda;
  pair.eigenvector = std::move(x);
  pair.largest_eigenvalue = lambda_max;
  pair.iterations = iterations;
  pair.method = std::move(method);
  return pair;
}

// ---------------------------------------------------------------------------------------------
// PETSc/SLEPc helpers.

using MatHandle = PetscHandle<Mat, MatDestroy>;
using VecHandle = PetscHandle<Vec, VecDestroy>;
using EpsHandle = PetscHandle<EPS, EPSDestroy>;

/// A MATSEQDENSE copy of the symmetric matrix a, flagged symmetric (and SPD if asked).
MatHandle dense_matrix(const Eigen::MatrixXd& a, bool positive_definite) {
  MatHandle matrix;
  const auto n = static_cast<PetscInt>(a.rows());
  HPC_PETSC_CALL(MatCreateSeqDense(PETSC_COMM_SELF, n, n, nullptr, matrix.out()));
  PetscInt lda = 0;
  HPC_PETSC_CALL(MatDenseGetLDA(matrix.get(), &lda));
  PetscScalar* values = nullptr;
  HPC_PETSC_CALL(MatDenseGetArrayWrite(matrix.get(), &values));
  for (Eigen::Index j = 0; j < a.cols(); ++j)  // both column-major
    std::copy_n(a.col(j).data(), a.rows(), values + j * static_cast<Eigen::Index>(lda));
  HPC_PETSC_CALL(MatDenseRestoreArrayWrite(matrix.get(), &values));
  HPC_PETSC_CALL(MatAssemblyBegin(matrix.get(), MAT_FINAL_ASSEMBLY));
  HPC_PETSC_CALL(MatAssemblyEnd(matrix.get(), MAT_FINAL_ASSEMBLY));
  HPC_PETSC_CALL(MatSetOption(matrix.get(), MAT_SYMMETRIC, PETSC_TRUE));
  HPC_PETSC_CALL(MatSetOption(matrix.get(), MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
  if (positive_definite) HPC_PETSC_CALL(MatSetOption(matrix.get(), MAT_SPD, PETSC_TRUE));
  return matrix;
}

/// The spectral transformation solves with one dense factorization: KSPPREONLY + PCCHOLESKY.
void use_direct_solver(EPS eps) {
  ST st = nullptr;
  KSP ksp = nullptr;
  PC pc = nullptr;
  HPC_PETSC_CALL(EPSGetST(eps, &st));
  HPC_PETSC_CALL(STGetKSP(st, &ksp));
  HPC_PETSC_CALL(KSPSetType(ksp, KSPPREONLY));
  HPC_PETSC_CALL(KSPGetPC(ksp, &pc));
  HPC_PETSC_CALL(PCSetType(pc, PCCHOLESKY));
}

/// A fixed starting vector (1 + ½ sin k in component k) instead of SLEPc's random one, so that a
/// point gives the same α whatever was solved before it in the process: sweeps distributed over
/// MPI ranks then reproduce the serial numbers. It has a component along every eigenvector of the
/// pencils that occur here (none is orthogonal to it to working precision in practice).
void use_fixed_start(EPS eps, Mat s) {
  Vec start = nullptr;
  HPC_PETSC_CALL(MatCreateVecs(s, &start, nullptr));
  PetscInt first = 0, end = 0;
  HPC_PETSC_CALL(VecGetOwnershipRange(start, &first, &end));
  for (PetscInt k = first; k < end; ++k)
    HPC_PETSC_CALL(VecSetValue(start, k, 1.0 + 0.5 * std::sin(static_cast<double>(k)), INSERT_VALUES));
  HPC_PETSC_CALL(VecAssemblyBegin(start));
  HPC_PETSC_CALL(VecAssemblyEnd(start));
  const PetscErrorCode code = EPSSetInitialSpace(eps, 1, &start);
  VecDestroy(&start);
  HPC_PETSC_CALL(code);
}

/// "eps krylovschur, st sinvert (shift -1.2e-05), ksp preonly, pc cholesky", after EPSSolve.
std::string describe(EPS eps) {
  EPSType eps_type = nullptr;
  ST st = nullptr;
  STType st_type = nullptr;
  PetscScalar shift = 0.0;
  KSP ksp = nullptr;
  KSPType ksp_type = nullptr;
  PC pc = nullptr;
  PCType pc_type = nullptr;
  HPC_PETSC_CALL(EPSGetType(eps, &eps_type));
  HPC_PETSC_CALL(EPSGetST(eps, &st));
  HPC_PETSC_CALL(STGetType(st, &st_type));
  HPC_PETSC_CALL(STGetShift(st, &shift));
  HPC_PETSC_CALL(STGetKSP(st, &ksp));
  HPC_PETSC_CALL(KSPGetType(ksp, &ksp_type));
  HPC_PETSC_CALL(KSPGetPC(ksp, &pc));
  HPC_PETSC_CALL(PCGetType(pc, &pc_type));
  const auto name = [](const char* text) { return text != nullptr ? text : "(none)"; };
  return fmt::format("eps {}, st {} (shift {:.3e}), ksp {}, pc {}", name(eps_type), name(st_type), shift,
                     name(ksp_type), name(pc_type));
}

/// The last iteration seen by the EPS monitor, for the message when nothing converged.
struct LastIteration {
  PetscInt iteration = 0;
  PetscInt n_converged = 0;
  std::vector<double> eigenvalues;
  std::vector<double> error_estimates;
};

/// EPS monitor. The values it receives are those of the transformed problem (θ = 1/(λ − σ) for
/// shift-and-invert); they are mapped back to λ. Error estimates exist for the converged pairs
/// and the first unconverged one only; later entries are stale.
PetscErrorCode record_last_iteration(EPS eps, PetscInt iteration, PetscInt n_converged, PetscScalar* eigenvalues_real,
                                     PetscScalar* eigenvalues_imag, PetscReal* error_estimates, PetscInt n_estimates,
                                     void* context) {
  try {  // no exception may cross SLEPc's C frames
    auto& last = *static_cast<LastIteration*>(context);
    last.iteration = iteration;
    last.n_converged = n_converged;
    last.eigenvalues.clear();
    last.error_estimates.clear();
    ST st = nullptr;
    const PetscErrorCode code = EPSGetST(eps, &st);
    if (code != 0) return code;
    for (PetscInt i = 0; i < std::min(n_estimates, n_converged + 1); ++i) {
      PetscScalar real = eigenvalues_real[i], imag = eigenvalues_imag[i];
      const PetscErrorCode back = STBackTransform(st, 1, &real, &imag);
      if (back != 0) return back;
      last.eigenvalues.push_back(real);
      last.error_estimates.push_back(error_estimates[i]);
    }
  } catch (...) {
    return PETSC_ERR_MEM;
  }
  return 0;
}

[[noreturn]] void throw_not_converged(EPS eps, const LastIteration& last, const std::string& what,
                                      const std::string& where) {
  EPSConvergedReason reason = EPS_CONVERGED_ITERATING;
  PetscInt iterations = 0, max_iterations = 0;
  PetscReal tolerance = 0.0;
  HPC_PETSC_CALL(EPSGetConvergedReason(eps, &reason));
  HPC_PETSC_CALL(EPSGetIterationNumber(eps, &iterations));
  HPC_PETSC_CALL(EPSGetTolerances(eps, &tolerance, &max_iterations));
  std::string estimates;
  for (std::size_t i = 0; i < last.error_estimates.size(); ++i)
    estimates += fmt::format("{}lambda ~ {:.6e} (error estimate {:.3e})", i > 0 ? ", " : "", last.eigenvalues[i],
                             last.error_estimates[i]);
  throw NumericalError(
      fmt::format("{}: SLEPc EPS for {} converged {} of 1 eigenpairs after {} of at most {} iterations "
                  "(reason {}, tolerance {:.1e}; {}); last iterate: {}",
                  where, what, last.n_converged, iterations, max_iterations, EPSConvergedReasons[reason], tolerance,
                  describe(eps), estimates.empty() ? std::string("no estimates") : estimates));
}

/// λ_max by a second EPS: largest real part, STSHIFT without shift, i.e. Krylov–Schur on G⁻¹S
/// with one Cholesky factorization of G. Only a scale for zero tests, so a loose tolerance.
double largest_eigenvalue_slepc(Mat s, Mat g, const std::string& options_prefix, const std::string& where,
                                std::string& method) {
  EpsHandle eps;
  LastIteration last;
  HPC_PETSC_CALL(EPSCreate(PETSC_COMM_SELF, eps.out()));
  HPC_PETSC_CALL(EPSSetOperators(eps.get(), s, g));
  HPC_PETSC_CALL(EPSSetProblemType(eps.get(), EPS_GHEP));
  HPC_PETSC_CALL(EPSSetType(eps.get(), EPSKRYLOVSCHUR));
  HPC_PETSC_CALL(EPSSetDimensions(eps.get(), 1, PETSC_DEFAULT, PETSC_DEFAULT));
  HPC_PETSC_CALL(EPSSetWhichEigenpairs(eps.get(), EPS_LARGEST_REAL));
  use_direct_solver(eps.get());
  use_fixed_start(eps.get(), s);
  HPC_PETSC_CALL(EPSSetTolerances(eps.get(), kLargestTolerance, kLargestMaxRestarts));
  HPC_PETSC_CALL(EPSMonitorSet(eps.get(), record_last_iteration, &last, nullptr));
  HPC_PETSC_CALL(EPSSetOptionsPrefix(eps.get(), options_prefix.c_str()));
  HPC_PETSC_CALL(EPSAppendOptionsPrefix(eps.get(), "max_"));
  HPC_PETSC_CALL(EPSSetFromOptions(eps.get()));
  HPC_PETSC_CALL(EPSSolve(eps.get()));
  PetscInt n_converged = 0;
  HPC_PETSC_CALL(EPSGetConverged(eps.get(), &n_converged));
  if (n_converged >= 1) {
    PetscScalar lambda_max = 0.0;
    HPC_PETSC_CALL(EPSGetEigenvalue(eps.get(), 0, &lambda_max, nullptr));
    method = "separate EPS (" + describe(eps.get()) + ")";
    return lambda_max;
  }
  // Not converged within the budget: the largest Ritz value, if its estimate is good enough.
  if (last.eigenvalues.empty() || !(last.error_estimates[0] <= kLargestAcceptedEstimate))
    throw_not_converged(eps.get(), last, "lambda_max", where);
  PetscInt restarts = 0;
  HPC_PETSC_CALL(EPSGetIterationNumber(eps.get(), &restarts));
  method = fmt::format(
      "separate EPS ({}), not converged to {:.0e} in {} restarts: largest Ritz value, error "
      "estimate {:.1e}",
      describe(eps.get()), kLargestTolerance, restarts, last.error_estimates[0]);
  return last.eigenvalues[0];
}

// The EPS for λ_min: generalized Hermitian, Krylov–Schur with shift-and-invert at the target σ,
// a direct inner solve, a fixed start vector, then the user's options (prefix) on top.
void configure_smallest(EpsHandle& eps, Mat s, Mat g, double sigma, PetscInt n, const std::string& options_prefix,
                        LastIteration& last) {
  HPC_PETSC_CALL(EPSCreate(PETSC_COMM_SELF, eps.out()));
  HPC_PETSC_CALL(EPSSetOperators(eps.get(), s, g));
  HPC_PETSC_CALL(EPSSetProblemType(eps.get(), EPS_GHEP));
  HPC_PETSC_CALL(EPSSetType(eps.get(), EPSKRYLOVSCHUR));
  // A wider Krylov space than SLEPc's default (16): for stable pairings the spectrum of
  // (S_G, G) clusters in [α², 1], and at 1e6 dofs the default did not separate λ_min to 1e-12 in
  // 100 restarts. The operators are small and dense, so 64 vectors cost little.
  HPC_PETSC_CALL(EPSSetDimensions(eps.get(), 1, std::min<PetscInt>(n, 64), PETSC_DEFAULT));
  HPC_PETSC_CALL(EPSSetWhichEigenpairs(eps.get(), EPS_TARGET_MAGNITUDE));
  HPC_PETSC_CALL(EPSSetTarget(eps.get(), sigma));
  ST st = nullptr;
  HPC_PETSC_CALL(EPSGetST(eps.get(), &st));
  HPC_PETSC_CALL(STSetType(st, STSINVERT));
  use_direct_solver(eps.get());
  use_fixed_start(eps.get(), s);
  HPC_PETSC_CALL(EPSSetTolerances(eps.get(), kSmallestTolerance, PETSC_DEFAULT));
  HPC_PETSC_CALL(EPSMonitorSet(eps.get(), record_last_iteration, &last, nullptr));
  HPC_PETSC_CALL(EPSSetOptionsPrefix(eps.get(), options_prefix.c_str()));
  HPC_PETSC_CALL(EPSSetFromOptions(eps.get()));
}

}  // namespace

// ---------------------------------------------------------------------------------------------

SmallestEigenpair smallest_eigenpair_dense(const Eigen::MatrixXd& S, const Eigen::MatrixXd& G) {
  const std::string where = "smallest_eigenpair_dense";
  const Pencil pencil = checked_pencil(S, G, where);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(pencil.s, pencil.g,
                                                                         Eigen::ComputeEigenvectors | Eigen::Ax_lBx);
  if (solver.info() != Eigen::Success)
    throw NumericalError(fmt::format("{}: the tridiagonal QR iteration did not converge (n = {})", where, S.rows()));
  const Eigen::Index n = pencil.s.rows();
  // Eigenvalues come sorted ascending.
  return finish(pencil, solver.eigenvalues()(0), solver.eigenvectors().col(0), solver.eigenvalues()(n - 1), 0,
                "dense: Eigen::GeneralizedSelfAdjointEigenSolver (Cholesky of G, tridiagonal QR)", where);
}

SmallestEigenpair smallest_eigenpair_slepc(const Eigen::MatrixXd& S, const Eigen::MatrixXd& G,
                                           const std::string& options_prefix) {
  const std::string where = "smallest_eigenpair_slepc";
  if (!ensure_petsc_initialized())
    throw std::logic_error(where + ": SLEPc is not initialized (create a PetscSession first)");
  const Pencil pencil = checked_pencil(S, G, where);
  const Eigen::Index n = pencil.s.rows();

  // 1. Shift. tr(S)/tr(G) is a typical eigenvalue of the pencil (exact for G = cI). A target
  //    σ = −10⁻² tr(S)/(n tr(G)) < 0 keeps S − σG positive definite for singular S, and lies
  //    close enough to 0 that shift-and-invert (θ = 1/(λ − σ)) separates a zero or tiny λ_min
  //    well from the rest. For S ⪰ 0, tr(S) ≥ 0 with equality only for S = 0, where any σ < 0
  //    does.
  const double trace_s = pencil.s.trace();
  const double trace_g = pencil.g.trace();  // > 0, G is positive definite
  const bool s_is_zero = pencil.s.isZero(0.0);
  if (trace_s < 0.0 || (trace_s == 0.0 && !s_is_zero))
    throw NumericalError(
        fmt::format("{}: S is not positive semi-definite: tr(S) = {:.6e} (and S is not zero)", where, trace_s));
  const double sigma = trace_s > 0.0 ? -1e-2 * trace_s / (static_cast<double>(n) * trace_g) : -1.0;

  // PETSc errors become NumericalError through HPC_PETSC_CALL; no traceback on stderr meanwhile.
  const ScopedPetscErrorsAsCodes errors_as_codes;
  MatHandle s = dense_matrix(pencil.s, false);
  MatHandle g = dense_matrix(pencil.g, true);

  // 2. λ_min: Create → SetOperators → defaults → SetFromOptions → Solve.
  EpsHandle eps;
  LastIteration last;
  configure_smallest(eps, s.get(), g.get(), sigma, static_cast<PetscInt>(n), options_prefix, last);
  HPC_PETSC_CALL(EPSSolve(eps.get()));

  PetscInt n_converged = 0, iterations = 0;
  HPC_PETSC_CALL(EPSGetConverged(eps.get(), &n_converged));
  HPC_PETSC_CALL(EPSGetIterationNumber(eps.get(), &iterations));
  if (n_converged < 1) throw_not_converged(eps.get(), last, "lambda_min", where);
  VecHandle x;
  HPC_PETSC_CALL(MatCreateVecs(s.get(), x.out(), nullptr));
  PetscScalar lambda_min = 0.0;
  HPC_PETSC_CALL(EPSGetEigenpair(eps.get(), 0, &lambda_min, nullptr, x.get(), nullptr));
  std::string method = "slepc: " + describe(eps.get());

  // 3. λ_max: from the same solve if it computed the whole spectrum (-eps_type lapack does),
  //    else from a second EPS.
  double lambda_max = lambda_min;
  if (n_converged >= static_cast<PetscInt>(n)) {
    for (PetscInt i = 0; i < n_converged; ++i) {
      PetscScalar lambda = 0.0;
      HPC_PETSC_CALL(EPSGetEigenvalue(eps.get(), i, &lambda, nullptr));
      lambda_max = std::max(lambda_max, lambda);
    }
    method += "; lambda_max from the same solve";
  } else {
    std::string max_method;
    lambda_max = largest_eigenvalue_slepc(s.get(), g.get(), options_prefix, where, max_method);
    method += "; lambda_max by " + max_method;
  }

  if (s_is_zero) {
    // Every eigenvalue of (0, G) is exactly 0; the computed ones are σ + 1/θ with θ ≈ −1/σ,
    // round-off of size ε|σ| that no relative test against λ_max (itself round-off) can judge.
    lambda_min = lambda_max = 0.0;
    method += "; S = 0, so every eigenvalue is exactly 0";
  }
  return finish(pencil, lambda_min, to_eigen(x.get()), lambda_max, static_cast<int>(iterations), std::move(method),
                where);
}

}  // namespace hpcontact::infsup
