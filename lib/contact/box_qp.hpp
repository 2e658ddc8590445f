// The condensed contact problem on Γ_C: a convex quadratic program with box constraints,
//     minimise ½ xᵀ S x − dᵀ x   subject to   lo ≤ x ≤ hi,
// S symmetric positive SEMI-definite (singular where the inf-sup condition fails), dense and small.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "contact/qp_report.hpp"

namespace hpcontact::contact {

struct BoxQpOptions {
  double tolerance = 1e-12;  ///< on the relative KKT residual (see BoxQpResult::kkt_residual)
  int max_newton = 500;      ///< active-set steps per proximal subproblem
  int max_proximal = 50;     ///< outer proximal steps
  double proximal = 1e-10;   ///< ρ relative to max diag(S)
};

struct BoxQpResult {
  Eigen::VectorXd x;
  /// method "active-set" or "active-set+proximal"; iterations: Newton (active-set) steps;
  /// kkt_residual: ‖x − P_[lo,hi](x − c (S x − d))‖_∞ / (‖x‖_∞ + c ‖d‖_∞), c = 1/‖S‖_∞, of the
  /// Jacobi-scaled problem (x = D y, D = diag(S)^{-1/2}, see solve_box_qp): zero exactly at a KKT
  /// point, and unchanged when (S, d) or the bounds are scaled; log: active_set_changes are the
  /// indices flipped after the step.
  QpReport report;
};

/// Active-set method (primal-dual active set = semismooth Newton steps, safeguarded by Murty's
/// least-index pivoting so that it cannot cycle) on the proximal regularization
///     minimise ½ xᵀ S x − dᵀ x + (ρ/2) ‖x − x_k‖²,
/// repeated from x_k = the previous solution until the KKT residual of the original problem is
/// below tolerance. Each subproblem is strictly convex, so the method is well defined even for singular
/// S; components in the null space of S stay where the previous iterate put them (x_0 = 0), which
/// selects one of the many solutions when S is singular. The method works on the Jacobi-scaled
/// problem (x = D y, D = diag(S)^{-1/2}), so that unknowns of very different curvature (multipliers
/// on the segments of a geometric mesh) are resolved alike.
/// @throws NumericalError with the residuals if it does not converge.
BoxQpResult solve_box_qp(const Eigen::MatrixXd& s, const Eigen::VectorXd& d, const Eigen::VectorXd& lo,
                         const Eigen::VectorXd& hi, const BoxQpOptions& options = {});

/// The relative KKT residual of x (see BoxQpResult).
double box_qp_kkt_residual(const Eigen::MatrixXd& s, const Eigen::VectorXd& d, const Eigen::VectorXd& lo,
                           const Eigen::VectorXd& hi, const Eigen::VectorXd& x);

}  // namespace hpcontact::contact
