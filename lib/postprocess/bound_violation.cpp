// bound_violation: one pass for the largest distance outside the bounds, one for the free boundary.
#include "postprocess/bound_violation.hpp"

#include <algorithm>
#include <cmath>

namespace hpcontact::postprocess {

BoundViolation bound_violation(const std::vector<double>& s, const std::vector<int>& zone,
                               const std::vector<double>& value,
                               const std::function<std::pair<double, double>(std::size_t)>& bounds) {
  BoundViolation out;
  double scale = 0.0;
  for (const double v : value) scale = std::max(scale, std::abs(v));
  if (!(scale > 0.0)) return out;
  std::size_t worst = 0;
  double largest = 0.0;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const auto [lower, upper] = bounds(i);
    const double outside = std::max({lower - value[i], value[i] - upper, 0.0});
    if (outside > largest) largest = outside, worst = i;
  }
  if (largest == 0.0) return out;
  out.relative = largest / scale;
  out.s = s[worst];
  // The free boundary: where the value turns zero or non-zero between neighbouring samples.
  const auto nonzero = [&](std::size_t i) { return std::abs(value[i]) > 1e-10 * scale; };
  for (std::size_t i = 0; i + 1 < value.size(); ++i)
    if (zone[i] == zone[i + 1] && zone[i] == zone[worst] && nonzero(i) != nonzero(i + 1)) {
      const double distance = std::abs(0.5 * (s[i] + s[i + 1]) - out.s);
      if (!out.to_free_boundary || distance < *out.to_free_boundary) out.to_free_boundary = distance;
    }
  return out;
}

}  // namespace hpcontact::postprocess
