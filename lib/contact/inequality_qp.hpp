// The condensed contact problem when there are more constraint points than multiplier
// coefficients per segment (Remark 3 with |𝒞| > p_C + 1): a convex QP with general inequalities,
//     minimise ½ xᵀ S x − dᵀ x   subject to   lo ≤ C x ≤ hi   (entries of lo/hi may be ±∞),
// S symmetric positive SEMI-definite, C of full column rank (so that S + Cᵀ D C is definite for
// every positive diagonal D, which is what makes the interior-point method below well defined even
// where the inf-sup condition fails and S is singular).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "contact/qp_report.hpp"

namespace hpcontact::contact {

struct InequalityQpOptions {
  double tolerance = 1e-12;  ///< on every part of the relative KKT residual
  int max_iterations = 200;
};

/// Relative KKT residuals of x with constraint multipliers y (y > 0 pushes Cx down, y < 0 up):
///   stationarity    ‖S x − d + Cᵀ y‖_∞ / (‖d‖_∞ + ‖S‖_∞ ‖x‖_∞ + ‖Cᵀ‖_∞ ‖y‖_∞)
///   feasibility     max_j dist((C x)_j, [lo_j, hi_j]) / (1 + ‖C‖_∞ ‖x‖_∞)
///   complementarity max_j |y_j| · dist((C x)_j, the bound y_j pushes against), relative to
///                   ‖y‖_∞ (1 + ‖C‖_∞ ‖x‖_∞); and y_j must have the sign of an active bound.
struct InequalityKkt {
  double stationarity = 0.0, feasibility = 0.0, complementarity = 0.0, sign = 0.0;
  double max() const;
};

struct InequalityQpResult {
  Eigen::VectorXd x;
  Eigen::VectorXd y;  ///< multipliers of the constraint rows (see InequalityKkt)
  InequalityKkt kkt;
  /// method "interior-point"; kkt_residual: InequalityKkt::max(), also in the log after each step.
  QpReport report;
};

/// Mehrotra predictor-corrector primal-dual interior-point method. Every iteration solves one
/// dense SPD system of the size of x. Where S is singular the iterates follow the central path,
/// so x converges to the analytic centre of the solution set: a valid, not a spurious, multiplier.
/// @throws NumericalError with the residuals if it does not converge.
InequalityQpResult solve_inequality_qp(const Eigen::MatrixXd& s, const Eigen::VectorXd& d, const Eigen::MatrixXd& c,
                                       const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                                       const InequalityQpOptions& options = {});

InequalityKkt inequality_qp_kkt(const Eigen::MatrixXd& s, const Eigen::VectorXd& d, const Eigen::MatrixXd& c,
                                const Eigen::VectorXd& lo, const Eigen::VectorXd& hi, const Eigen::VectorXd& x,
                                const Eigen::VectorXd& y);

}  // namespace hpcontact::contact
