// How far a multiplier sampled along Γ_C leaves its bounds between the points where they are
// imposed (Remark 3's constraint points, a family's nodes): λ ≤ 0 of (9), |λ| ≤ 1 of (13),
// |λ| ≤ s of (15), the elastic pressure ≥ 0.
#pragma once

#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "mesh/mesh.hpp"

namespace hpcontact::postprocess {

struct BoundViolation {
  /// max over the samples of the distance of the value outside [lower, upper], over max |value|
  /// (0 if it stays inside everywhere).
  double relative = 0.0;
  double s = 0.0;                        ///< the arc length of the sample with that distance
  mesh::Point at = mesh::Point::Zero();  ///< its point (set by the caller, who knows Γ_C)
  /// Arc length from there to the nearest end of the set where the value is not zero (the free
  /// boundary) in the same zone; none without one.
  std::optional<double> to_free_boundary;
};

/// @param s, zone, value one entry per sample, in order of s; @param bounds [lower, upper] of
/// sample i. A value counts as zero below 1e-10 max |value|.
BoundViolation bound_violation(const std::vector<double>& s, const std::vector<int>& zone,
                               const std::vector<double>& value,
                               const std::function<std::pair<double, double>(std::size_t)>& bounds);

}  // namespace hpcontact::postprocess
