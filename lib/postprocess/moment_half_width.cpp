// moment_half_width: ∫ p, ∫ p s, ∫ p s² by Gauss quadrature on each segment of T_{C,H}.
#include "postprocess/moment_half_width.hpp"

#include <cmath>

#include "basis/quadrature.hpp"
#include "core/error.hpp"

namespace hpcontact::postprocess {

double moment_half_width(const space::MultiplierSpace& multipliers, const Eigen::VectorXd& pressure) {
  HPC_VERIFY(pressure.size() == multipliers.n_dofs(), "moment_half_width: coefficients of another space");
  const auto& boundary = multipliers.boundary_mesh();
  // Moments about the middle of Γ_C keep the variance's cancellation small.
  const double centre = 0.5 * (boundary.segment_begin(0) + boundary.segment_end(multipliers.n_segments() - 1));
  double m0 = 0.0, m1 = 0.0, m2 = 0.0;
  for (int k = 0; k < multipliers.n_segments(); ++k) {
    const int p = multipliers.segment_degree(k), first = multipliers.first_dof(k);
    const auto& rule = basis::gauss_legendre(p / 2 + 2);  // exact for p s²
    const double s0 = boundary.segment_begin(k), half = 0.5 * (boundary.segment_end(k) - s0);
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const double tau = rule.points[q], s = s0 + half * (tau + 1.0) - centre, w = rule.weights[q] * half;
      const double value = multipliers.basis_values(k, tau).dot(pressure.segment(first, p + 1));
      m0 += w * value, m1 += w * value * s, m2 += w * value * s * s;
    }
  }
  if (!(m0 > 0.0)) return NAN;
  const double mean = m1 / m0;
  return 2.0 * std::sqrt(std::max(m2 / m0 - mean * mean, 0.0));
}

}  // namespace hpcontact::postprocess
