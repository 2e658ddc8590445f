// The condensed multiplier problem  min ½ λᵀ S λ − dᵀ λ  over lo ≤ C λ ≤ hi, whichever contact
// problem posed it (scalar (9), (13), (15), or the normal and tangential multipliers of
// elasticity stacked).
#pragma once

#include <Eigen/Core>

#include "contact/box_qp.hpp"
#include "contact/inequality_qp.hpp"
#include "contact/multiplier_constraints.hpp"
#include "contact/qp_report.hpp"

namespace hpcontact::contact {

struct MultiplierQpSolution {
  Eigen::VectorXd x;
  /// Multipliers of the constraint rows (interior-point method); empty after the active-set
  /// method, where they are the gap d − S x itself.
  Eigen::VectorXd y;
  QpReport report;
};

/// Bounds on the coefficients (C = I): the active-set method, which ends in a few steps with an
/// exact active set; should it stall (strongly singular S, e.g. a multiplier mesh much finer
/// than the trace space), the interior-point method takes over on the same problem. General rows:
/// the interior-point method. @throws NumericalError (with both methods' reasons) if neither
/// converges.
MultiplierQpSolution solve_multiplier_qp(const Eigen::MatrixXd& s, const Eigen::VectorXd& d,
                                         const MultiplierConstraints& constraints, const BoxQpOptions& box,
                                         const InequalityQpOptions& interior_point);

/// The constraints of two multipliers side by side, [λ_a; λ_b]: every matrix block diagonal.
MultiplierConstraints stack_constraints(const MultiplierConstraints& a, const MultiplierConstraints& b);

}  // namespace hpcontact::contact
