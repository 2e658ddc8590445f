// Smallest eigenpair of the symmetric pencil  S x = λ G x  (S positive semi-definite, possibly
// singular; G positive definite; both small and dense): α² = λ_min is the inf-sup constant.
// Two independent solvers: dense (Eigen, LAPACK-type) and SLEPc (EPS, shift-and-invert).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace hpcontact::infsup {

/// Eigenvalues λ with |λ| ≤ kRoundOffZero · λ_max are zero to working precision: a slightly
/// negative λ_min of that size is reported as exactly 0; a more negative one is an error
/// (S is not positive semi-definite).
inline constexpr double kRoundOffZero = 1e-12;

struct SmallestEigenpair {
  double eigenvalue = 0.0;  ///< λ_min ≥ 0 (see kRoundOffZero)
  /// Shape (n); G-normalized, xᵀ G x = 1; sign fixed so that its largest-magnitude entry (the
  /// first one among equals) is positive.
  Eigen::VectorXd eigenvector;
  double largest_eigenvalue = 0.0;  ///< λ_max of the same pencil, scale for relative zero tests
  int iterations = 0;               ///< outer iterations of the eigensolver for λ_min; 0 for the dense path
  double residual = 0.0;            ///< ‖S x − λ G x‖₂ / (‖S‖_F ‖x‖₂), with the reported λ and x
  std::string method;               ///< solver description, e.g. "slepc: eps krylovschur, st sinvert, ..."
};

/// Dense path: Cholesky G = L Lᵀ, then all eigenpairs of L⁻¹ S L⁻ᵀ by Householder
/// tridiagonalization and implicit QR (Eigen::GeneralizedSelfAdjointEigenSolver). O(n³) flops,
/// about 9 n³ with eigenvectors; every eigenvalue is computed, λ_max comes for free.
/// @param S  shape (n, n), symmetric positive semi-definite
/// @param G  shape (n, n), symmetric positive definite
/// @throws NumericalError if S or G is not symmetric (relative 1e-10), has non-finite entries,
///         G is not positive definite, or λ_min < −kRoundOffZero · λ_max.
SmallestEigenpair smallest_eigenpair_dense(const Eigen::MatrixXd& S, const Eigen::MatrixXd& G);

/// SLEPc path: EPS on PETSC_COMM_SELF with MATSEQDENSE copies of S and G, problem type GHEP,
/// Krylov–Schur, shift-and-invert with target σ = −10⁻² tr(S) / (n tr(G)) < 0, so that S − σ G
/// is positive definite even for singular S (factored once by dense Cholesky, KSPPREONLY +
/// PCCHOLESKY), EPS_TARGET_MAGNITUDE, tolerance 1e-12. Then EPSSetFromOptions with
/// `options_prefix`, so that -infsup_eps_type krylovschur|arpack|lapack, -infsup_st_type,
/// -infsup_eps_tol, -infsup_eps_view, ... apply.
/// λ_max, a scale only: taken from the same solve when it computed all n eigenvalues
/// (-infsup_eps_type lapack); otherwise from a second, cheap EPS (largest real, STSHIFT with a
/// Cholesky factorization of G, tolerance 1e-8 within at most 10 restarts, else the largest Ritz
/// value if its error estimate is below 1e-2, noted in `method`; its options carry the prefix
/// `options_prefix` + "max_", e.g. -infsup_max_eps_max_it 100, -infsup_max_eps_view).
/// SLEPc must be initialized (SlepcInitialize / PetscSession).
/// @param S, G as for smallest_eigenpair_dense
/// @throws NumericalError as smallest_eigenpair_dense; also if a PETSc/SLEPc call fails (with
///         PETSc's message) or the EPS converges no eigenpair (with the error estimates).
SmallestEigenpair smallest_eigenpair_slepc(const Eigen::MatrixXd& S, const Eigen::MatrixXd& G,
                                           const std::string& options_prefix = "infsup_");

}  // namespace hpcontact::infsup

namespace hpcontact::infsup {

/// Checks the PETSc/SLEPc options of the command line (`arguments`: names and values as split off
/// by split_petsc_options, program name first) before any work: every name must be one that the
/// toolkit reads (`options_prefix`, a few global PETSc options: -help, -info, -log_view,
/// -options_left, -malloc_*, -on_error_*, -mat_mumps_*; -bddc_* of linalg/bddc_solver.hpp), and
/// the eigensolvers' values are set on blank EPS objects. @throws InputError naming the option
/// (for an unprefixed one, the prefixed name).
void check_petsc_options(const std::vector<std::string>& arguments, const std::string& options_prefix = "infsup_");

}  // namespace hpcontact::infsup
