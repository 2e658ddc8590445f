// compare_with_hertz: P and the profile error by Gauss quadrature on the segments of T_{C,H}, each
// split where the Hertz profile has its square-root end points; the half-width by sampling.
#include "postprocess/hertz_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "basis/quadrature.hpp"
#include "core/error.hpp"
#include "postprocess/elastic_boundary_samples.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::postprocess {

HertzComparison compare_with_hertz(const contact::ElasticContactSetup& setup,
                                   const contact::ElasticContactSolution& solution, double radius,
                                   double plane_strain_modulus, double centre) {
  const auto& contact = setup.operators->contact();
  const mesh::Point start = contact.point_at(0.0), end = contact.point_at(contact.length());
  if (std::abs(end.y() - start.y()) > 1e-12 * contact.length() ||
      std::abs(std::abs(end.x() - start.x()) - contact.length()) > 1e-12 * contact.length())
    throw InputError("the Hertz comparison needs Γ_C on a line y = const");
  const space::MultiplierSpace multipliers(*setup.boundary_mesh, setup.segment_degrees);
  auto x_at = [&](double s) { return contact.point_at(s).x(); };
  auto pressure_at = [&](int k, double s) {
    return multipliers.basis_values(k, multipliers.local_coordinate(k, s))
        .dot(solution.pressure.segment(multipliers.first_dof(k), multipliers.segment_degree(k) + 1));
  };
  HertzComparison out;
  out.total_force = total_force(multipliers, solution.pressure);
  if (!(out.total_force > 0.0)) throw InputError("the Hertz comparison needs a contact force P > 0");
  const double a = std::sqrt(4.0 * out.total_force * radius / (std::numbers::pi * plane_strain_modulus));
  out.hertz_half_width = a;
  auto hertz = [&](double x) {
    const double r = a * a - (x - centre) * (x - centre);
    return r > 0 ? 2.0 * out.total_force / (std::numbers::pi * a * a) * std::sqrt(r) : 0.0;
  };
  // max p_h and the support {p_h > 1e-2 max p_h} from 2000 samples per segment.
  constexpr int kSamples = 2000;
  auto sample = [&](const std::function<void(int, double)>& visit) {
    for (int k = 0; k < multipliers.n_segments(); ++k) {
      const double s0 = setup.boundary_mesh->segment_begin(k), s1 = setup.boundary_mesh->segment_end(k);
      for (int j = 0; j <= kSamples; ++j) visit(k, s0 + (s1 - s0) * j / kSamples);
    }
  };
  double scale = 0.0, lowest = contact.length(), highest = 0.0;
  sample([&](int k, double s) { scale = std::max(scale, pressure_at(k, s)); });
  sample([&](int k, double s) {
    if (pressure_at(k, s) > 1e-2 * scale) {
      lowest = std::min(lowest, s);
      highest = std::max(highest, s);
    }
  });
  // The profile error.
  const auto& rule = basis::gauss_legendre(40);
  double error = 0.0, norm = 0.0;
  for (int k = 0; k < multipliers.n_segments(); ++k) {
    const double s0 = setup.boundary_mesh->segment_begin(k), s1 = setup.boundary_mesh->segment_end(k);
    std::vector<double> cuts{s0, s1};
    for (double s_end : {centre - a, centre + a}) {  // x = s_end, on the arc-length scale of Γ_C
      const double s = s_end - start.x();            // s = 0 is the end of Γ_C with the smaller x
      if (s > s0 && s < s1) cuts.push_back(s);
    }
    std::sort(cuts.begin(), cuts.end());
    for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
      const double half = 0.5 * (cuts[c + 1] - cuts[c]);
      for (std::size_t q = 0; q < rule.points.size(); ++q) {
        const double s = cuts[c] + half * (rule.points[q] + 1.0), w = rule.weights[q] * half;
        const double exact = hertz(x_at(s));
        error += w * std::pow(pressure_at(k, s) - exact, 2);
        norm += w * exact * exact;
      }
    }
  }
  out.profile_error = std::sqrt(error / norm);
  out.half_width = 0.5 * (highest - lowest);
  return out;
}

}  // namespace hpcontact::postprocess
