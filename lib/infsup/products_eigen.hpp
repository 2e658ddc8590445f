// The smallest eigenpair of S x = λ G x from products only (S = B A_G⁻¹ Bᵀ one solve with A_G's
// factor each, G by its moments): SLEPc's Generalized Davidson on shell matrices, preconditioned by
// T ≈ G⁻¹.
// Neither S nor G is formed, so the memory is that of a few vectors per multiplier, where the
// dense paths (generalized_eigen.hpp) hold n² doubles and take n³ operations.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>

#include "infsup/generalized_eigen.hpp"

namespace hpcontact::infsup {

/// The pencil as products: S positive semi-definite, G positive definite, T ≈ G⁻¹ (or ≈ S⁻¹)
/// symmetric positive definite, all of `size` rows.
struct PencilProducts {
  using Product = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;
  Eigen::Index size = 0;
  Product s, g, preconditioner;
};

/// λ_max of the pencil from below and a start for λ_min: Rayleigh–Ritz of (S, G) on the Krylov
/// space of T S from a fixed vector, at most `max_steps` products by S, fewer once the largest
/// Ritz value changes by less than 1e-6 relative. (A scale for the zero and convergence tests: a
/// few digits are all it needs.)
struct RitzEstimate {
  double largest = 0.0;
  double g_norm = 0.0;  ///< ‖G‖₂ from below: the largest Ritz value of G on the same space
  Eigen::VectorXd smallest_vector;
  int steps = 0;
};
RitzEstimate krylov_ritz_estimate(const PencilProducts& pencil, int max_steps = 30);

/// EPS on PETSC_COMM_SELF with MATSHELL operators, problem type GHEP, Generalized Davidson (EPSGD:
/// each product enters its search space once; LOBPCG, -infsup_products_eps_type lobpcg, took 3.7×
/// the products of Davidson on the 3-D cube of docs/three_d.md) preconditioned by T through
/// STPRECOND + PCSHELL, smallest real part; converged when Davidson's residual norm is below
/// `tolerance` · λ_max ‖G‖ (`estimate`: krylov_ritz_estimate of this pencil or of a nearby one, the
/// ladder's first level; a test in the pencil's own units that holds for a singular S too, where
/// one relative to λ would never). `initial` (optional, size rows) starts the iteration: the
/// eigenvector of a nearby pencil; without it, the estimate's smallest Ritz vector. Then
/// EPSSetFromOptions with `options_prefix` + "products_", e.g. -infsup_products_eps_max_it,
/// -infsup_products_eps_view. The residual reported is ‖S x − λ G x‖₂ / (λ_max ‖G x‖₂) (no ‖S‖_F
/// without S), λ_max the estimate's. SLEPc must be initialized.
/// @throws NumericalError if the eigensolve does not converge, λ_min < −kRoundOffZero λ_max, or
///         xᵀ G x ≤ 0.
SmallestEigenpair smallest_eigenpair_products(const PencilProducts& pencil, const RitzEstimate& estimate,
                                              const Eigen::VectorXd& initial = {}, double tolerance = 1e-10,
                                              const std::string& options_prefix = "infsup_");

}  // namespace hpcontact::infsup
