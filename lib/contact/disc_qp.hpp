// The dual problem of 3-D Tresca contact: min ½ xᵀ S x − dᵀ x over x = (P; t₁; t₂) (three blocks
// of m nodal coefficients) with P_i ≥ 0 and |(t₁_i, t₂_i)| ≤ s_i at every node i: a sign and a disc
// per node (the tangential bound is a second-order cone of fixed radius, not a box).
//
// Method: accelerated projected gradient (FISTA) with step 1/L, L the largest eigenvalue of S, and
// the adaptive restart of O'Donoghue and Candès (the momentum is dropped when it points uphill),
// which makes it converge linearly where S is definite. The projection onto the set is exact node
// by node (a sign clamp, and the radial scaling of the tangential pair into its disc). It stops on
// the KKT residual ‖x − Π(x − (S x − d))‖_∞ / max(‖d‖_∞, ‖S‖_max ‖x‖_∞), the fixed-point residual
// of the projected gradient step of unit length, zero exactly at a solution.
#pragma once

#include <Eigen/Core>

#include "contact/qp_report.hpp"
#include "contact/trace_operator.hpp"

namespace hpcontact::contact {

struct DiscQpOptions {
  double tolerance = 1e-12;     ///< on the relative KKT residual
  int max_iterations = 200000;  ///< FISTA steps
};

struct DiscQpSolution {
  Eigen::VectorXd x;
  QpReport report;  ///< method "projected-gradient"; the log holds every 100th step and the last
};

/// @param s  shape (3m, 3m), symmetric positive semi-definite
/// @param d  shape (3m)
/// @param radius  s_i ≥ 0, shape (m)
/// @throws NumericalError (with the residual reached) if the residual does not fall below the
///         tolerance within max_iterations.
DiscQpSolution solve_disc_qp(const Eigen::MatrixXd& s, const Eigen::VectorXd& d, const Eigen::VectorXd& radius,
                             const DiscQpOptions& options = {});

/// The same with products by S only (contact/trace_operator.hpp): L from the Lanczos estimate,
/// raised whenever a step's Rayleigh quotient exceeds it, and L in place of max |S_ij| in the
/// residual's scale (L ≥ max S_ii, so the stop is up to L / max S_ii looser in the dense measure).
DiscQpSolution solve_disc_qp_by_products(const TraceOperator& s, const Eigen::VectorXd& d,
                                         const Eigen::VectorXd& radius, const DiscQpOptions& options = {});

}  // namespace hpcontact::contact
