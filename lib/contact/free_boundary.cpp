// Locating the free boundary of a discrete contact solution from its constraint points.
#include "contact/free_boundary.hpp"

#include <algorithm>
#include <cmath>

namespace hpcontact::contact {

std::vector<FreeBoundaryPoint> locate_free_boundary(const ContactSolution& solution, double tolerance) {
  const Eigen::VectorXd values = solution.constraint_matrix * solution.lambda;  // λ(τ_j)
  const int n = static_cast<int>(values.size());
  double scale = values.cwiseAbs().maxCoeff();
  for (int j = 0; j < n; ++j)
    for (double bound : {solution.lower[j], solution.upper[j]})
      if (std::isfinite(bound)) scale = std::max(scale, std::abs(bound));
  const double held_within = tolerance * std::max(scale, 1e-300);
  // Which bound λ(τ_j) is held at (-1 lower, +1 upper) or 0 when it is free.
  auto status = [&](int j) {
    if (std::isfinite(solution.lower[j]) && values[j] - solution.lower[j] <= held_within) return -1;
    if (std::isfinite(solution.upper[j]) && solution.upper[j] - values[j] <= held_within) return 1;
    return 0;
  };
  auto distance_to = [&](int j, int bound) {
    return std::abs(values[j] - (bound < 0 ? solution.lower[j] : solution.upper[j]));
  };
  std::vector<int> order(n);
  for (int j = 0; j < n; ++j) order[j] = j;
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return solution.constraint_s[a] < solution.constraint_s[b]; });

  std::vector<FreeBoundaryPoint> points;
  for (int k = 0; k + 1 < n; ++k) {
    const int a = order[k], b = order[k + 1], status_a = status(a), status_b = status(b);
    if (status_a == status_b || (status_a != 0 && status_b != 0)) continue;
    const double s_a = solution.constraint_s[a], s_b = solution.constraint_s[b];
    FreeBoundaryPoint point{s_a, std::min(s_a, s_b), std::max(s_a, s_b)};
    if (s_b - s_a > 1e-14 * std::max(1.0, std::abs(s_b))) {
      // The free side walks away from the held point: its two nearest free points at distinct s.
      const int held_bound = status_a != 0 ? status_a : status_b;
      const int step = status_a == 0 ? -1 : 1;
      const int first = status_a == 0 ? k : k + 1;
      int second = first + step;
      while (second >= 0 && second < n &&
             std::abs(solution.constraint_s[order[second]] - solution.constraint_s[order[first]]) <= 1e-14)
        second += step;
      const double s_held = status_a == 0 ? s_b : s_a, s_free = solution.constraint_s[order[first]];
      double estimate = 0.5 * (s_a + s_b);
      if (second >= 0 && second < n && status(order[second]) == 0) {
        const double m1 = distance_to(order[first], held_bound), m2 = distance_to(order[second], held_bound);
        const double s2 = solution.constraint_s[order[second]];
        // m² ∝ |s − s*|: linear in s through (s_free, m1²) and (s2, m2²), zero at s*.
        if (m2 > m1) estimate = (m2 * m2 * s_free - m1 * m1 * s2) / (m2 * m2 - m1 * m1);
      }
      point.s = std::clamp(estimate, std::min(s_free, s_held), std::max(s_free, s_held));
    }
    points.push_back(point);
  }
  return points;
}

}  // namespace hpcontact::contact
