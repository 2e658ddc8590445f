// The width of a contact set as a functional of the pressure: the half-width of the Hertz profile
// with the same spread, a_m = 2σ, σ² the variance of the arc length s under the weight p(s) ds
// (for p ∝ √(a² − (s − c)²), σ² = a²/4: a_m = a). Unlike the end of {p > threshold}, which the
// multiplier's oscillations between its constraint points move (1 % of max p on the Hertz
// problem at the free boundary), a_m converges with the solution.
#pragma once

#include <Eigen/Core>

#include "space/multiplier_space.hpp"

namespace hpcontact::postprocess {

/// a_m of the pressure p ∈ M^{p_C}(T_{C,H}) (Legendre coefficients), integrated exactly (Gauss on each
/// segment); NaN where ∫ p ≤ 0.
double moment_half_width(const space::MultiplierSpace& multipliers, const Eigen::VectorXd& pressure);

}  // namespace hpcontact::postprocess
