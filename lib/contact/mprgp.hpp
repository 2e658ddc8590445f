// The condensed contact problem with bounds, solved with products by S only:
//     minimise ½ xᵀ S x − dᵀ x   subject to   lo ≤ x ≤ hi   (entries ±∞ allowed, lo = hi fixes),
// by MPRGP (Dostál's modified proportioning with reduced gradient projections): conjugate
// gradients on the free set while the free gradient dominates the chopped one, proportioning steps
// off the active bounds otherwise, and expansion steps (a projected gradient step of length
// ᾱ = 1/L, L ≥ λ_max(S)) where CG would leave the box. One product by S per step (two on an
// expansion step), no matrix, no factorization: for the 3-D trace problems whose dense S would not
// fit (contact/trace_operator.hpp).
#pragma once

#include <Eigen/Core>

#include "contact/box_qp.hpp"
#include "contact/trace_operator.hpp"

namespace hpcontact::contact {

struct MprgpOptions {
  /// On the relative KKT residual ‖x − P(x − c (S x − d))‖_∞ / (‖x‖_∞ + c ‖d‖_∞), c = 1/L: the
  /// form of the dense active-set method's residual (BoxQpResult), with L in place of ‖S‖_∞ and
  /// on the unscaled problem (the dense method scales by diag(S)^{-1/2}, which products do not give).
  double tolerance = 1e-12;
  long max_products = 200000;
  /// Γ: a proportioning step when ‖β‖² > Γ² φ̃ᵀφ (chopped against reduced free gradient).
  double proportioning = 1.0;
};

/// @param s  S as products, symmetric positive semi-definite, size n
/// @param d, lo, hi  shape (n), lo ≤ hi
/// @return x and the report: method "mprgp", iterations its steps, products those by S (the
///         Lanczos estimate's included), the log every 50th step and the last
///         (active_set_changes: bounds taken or released since the entry before)
/// @throws NumericalError with the residual reached if it does not converge within max_products,
///         or if the objective is unbounded below on the box (a direction of zero curvature that
///         no bound stops).
BoxQpResult solve_box_qp_by_products(const TraceOperator& s, const Eigen::VectorXd& d, const Eigen::VectorXd& lo,
                                     const Eigen::VectorXd& hi, const MprgpOptions& options = {});

}  // namespace hpcontact::contact
