// The gap to a rigid obstacle along Γ_C's normal: closed forms for the shapes, Newton for φ, and
// the location of a point of Γ_C on its edge (for the normal there).
#include "contact/obstacle_gap.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include "core/error.hpp"
#include "core/expression.hpp"

namespace hpcontact::contact {
namespace {

using mesh::Point;

// The root of a t² + b t + c (a ≥ 0) nearest to 0 on the side c gives: the first t > 0 where the
// body starts outside (c > 0), the last t < 0 where it starts inside (c < 0). Written without the
// cancellation of −b ± √D (q = −(b + sign(b)√D)/2; the roots are q/a and c/q).
std::optional<double> nearest_root(double a, double b, double c) {
  if (c == 0.0) return 0.0;
  std::vector<double> roots;
  if (a == 0.0) {
    if (b != 0.0) roots.push_back(-c / b);
  } else {
    const double discriminant = b * b - 4.0 * a * c;
    if (discriminant < 0.0) return std::nullopt;
    const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
    if (q != 0.0) roots.insert(roots.end(), {q / a, c / q});
  }
  std::optional<double> best;
  for (double t : roots)
    if ((c > 0.0 ? t > 0.0 : t < 0.0) && (!best || std::abs(t) < std::abs(*best))) best = t;
  return best;
}

// A local frame at the obstacle's point: ξ along the surface's tangent, η along its normal.
std::optional<double> parabola_gap(const RigidObstacle& o, const Point& x, const Point& n) {
  const Point tangent(-o.normal.y(), o.normal.x());
  const double xi = (x - o.point).dot(tangent), eta = (x - o.point).dot(o.normal);
  const double n_t = n.dot(tangent), n_m = n.dot(o.normal);
  // η(t) + ξ(t)²/(2R) = 0 on the surface V + ξτ − ξ²/(2R)·m.
  return nearest_root(n_t * n_t / (2.0 * o.radius), n_m + xi * n_t / o.radius, eta + xi * xi / (2.0 * o.radius));
}

std::optional<double> circle_gap(const RigidObstacle& o, const Point& x, const Point& n) {
  const Point d = x - o.point;
  return nearest_root(1.0, 2.0 * n.dot(d), d.squaredNorm() - o.radius * o.radius);
}

std::optional<double> plane_gap(const RigidObstacle& o, const Point& x, const Point& n) {
  return nearest_root(0.0, n.dot(o.normal), (x - o.point).dot(o.normal));
}

// Newton on f(t) = φ(X + t n) from t = 0, f' by central differences (their error slows the
// iteration, it does not move the root), steps relative to `length` (the size of the problem, so
// that a body measured in micrometres gets steps of its own size). The root must lie on the side
// φ(X) gives, as the shapes' do: ahead (t > 0) from outside, behind from inside; one on the other
// side means the normal turns away from the obstacle there.
std::optional<double> distance_gap(const Expression& phi, const Point& x, const Point& n, double length) {
  auto f = [&](double t) {
    const Point y = x + t * n;
    return phi(y.x(), y.y());
  };
  const double start = f(0.0);
  if (start == 0.0) return 0.0;
  double t = 0.0;
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double scale = std::max(length, std::abs(t)), delta = 1e-7 * scale;
    const double slope = (f(t + delta) - f(t - delta)) / (2.0 * delta);
    if (!(std::abs(slope) > 0.0) || !std::isfinite(slope)) return std::nullopt;
    const double step = f(t) / slope;
    t -= step;
    if (!std::isfinite(t)) return std::nullopt;
    if (std::abs(step) <= 1e-14 * scale) {
      if ((start > 0.0) != (t > 0.0) || t == 0.0) return std::nullopt;
      return t;
    }
  }
  return std::nullopt;
}

// Finds the edge of Γ_C holding a point, starting from the last edge found.
class EdgeLocator {
 public:
  explicit EdgeLocator(const mesh::ContactBoundary& contact) : contact_(contact) {}

  /// Γ_C's outward unit normal at x (a point of Γ_C, up to round-off).
  Point normal_at(const Point& x) {
    const int count = static_cast<int>(contact_.edges().size());
    const double tolerance = 1e-9 * contact_.length();
    for (int k : {hint_, hint_ + 1, hint_ - 1})
      if (k >= 0 && k < count)
        if (const auto [distance, s] = nearest_on_edge(k, x); distance <= tolerance) return normal_on(k, s);
    double best = std::numeric_limits<double>::infinity(), best_s = 0.0;
    for (int k = 0; k < count; ++k)
      if (const auto [distance, s] = nearest_on_edge(k, x); distance < best) {
        best = distance, best_s = s, hint_ = k;
      }
    return normal_on(hint_, best_s);
  }

 private:
  Point normal_on(int k, double s) {
    hint_ = k;
    const auto& edge = contact_.edges()[static_cast<std::size_t>(k)];
    return contact_.mesh().boundary_normal(edge.edge, edge.local_parameter(s)).normalized();
  }

  // The distance from x to edge k and the arc length of its nearest point: the chord's projection
  // for a straight edge; for a curved one the nearest of 9 samples, then Gauss–Newton in s (the
  // tangent is of unit length in arc length).
  std::pair<double, double> nearest_on_edge(int k, const Point& x) const {
    const auto& edge = contact_.edges()[static_cast<std::size_t>(k)];
    const double length = edge.s_end - edge.s_begin;
    if (!edge.arc) {
      const Point a = contact_.point_on_edge(k, edge.s_begin), b = contact_.point_on_edge(k, edge.s_end);
      const double fraction = std::clamp((x - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      return {(a + fraction * (b - a) - x).norm(), edge.s_begin + fraction * length};
    }
    double s = edge.s_begin, best = std::numeric_limits<double>::infinity();
    for (int j = 0; j <= 8; ++j) {
      const double candidate = edge.s_begin + length * j / 8.0;
      if (const double d = (contact_.point_on_edge(k, candidate) - x).norm(); d < best) best = d, s = candidate;
    }
    for (int iteration = 0; iteration < 30; ++iteration) {
      const double step = (contact_.point_on_edge(k, s) - x).dot(contact_.tangent_on_edge(k, s));
      s = std::clamp(s - step, edge.s_begin, edge.s_end);
      if (std::abs(step) <= 1e-15 * length) break;
    }
    return {(contact_.point_on_edge(k, s) - x).norm(), s};
  }

  const mesh::ContactBoundary& contact_;
  int hint_ = 0;
};

}  // namespace

const char* to_string(ObstacleType type) {
  switch (type) {
    case ObstacleType::plane:
      return "plane";
    case ObstacleType::circle:
      return "circle";
    case ObstacleType::parabola:
      return "parabola";
    case ObstacleType::distance:
      return "distance";
  }
  return "?";
}

namespace {

// The gap, or an input error naming the point where the normal misses the obstacle.
double checked_gap(const RigidObstacle& obstacle, const Point& x, const Point& n, const Expression* phi,
                   double length) {
  std::optional<double> gap;
  switch (obstacle.type) {
    case ObstacleType::plane:
      gap = plane_gap(obstacle, x, n);
      break;
    case ObstacleType::circle:
      gap = circle_gap(obstacle, x, n);
      break;
    case ObstacleType::parabola:
      gap = parabola_gap(obstacle, x, n);
      break;
    case ObstacleType::distance:
      gap = distance_gap(*phi, x, n, length);
      break;
  }
  if (gap) return *gap;
  if (obstacle.type == ObstacleType::distance)
    throw InputError(fmt::format(
        "{}: key 'obstacle.distance' = \"{}\": along the outward normal ({:.6g}, {:.6g}) of Γ_C at ({:.6g}, {:.6g}) "
        "Newton finds no zero of φ on the side φ there gives (ahead where φ > 0, behind where φ < 0): φ must be > 0 "
        "on the body's side and 0 on the obstacle's surface, and the normal must meet that surface; restrict Γ_C "
        "(boundary.contact) to the part of the boundary that faces the obstacle",
        obstacle.origin, obstacle.distance, n.x(), n.y(), x.x(), x.y()));
  throw InputError(
      fmt::format("{}: the outward normal ({:.6g}, {:.6g}) of Γ_C at ({:.6g}, {:.6g}) does not meet the obstacle (type "
                  "\"{}\"): restrict Γ_C (boundary.contact) to the part of the boundary that faces the obstacle",
                  obstacle.origin, n.x(), n.y(), x.x(), x.y(), to_string(obstacle.type)));
}

}  // namespace

double gap_along(const RigidObstacle& obstacle, const Point& x, const Point& n, double length) {
  if (obstacle.type != ObstacleType::distance) return checked_gap(obstacle, x, n, nullptr, length);
  const Expression phi(obstacle.distance, obstacle.origin + ": key 'obstacle.distance'");
  return checked_gap(obstacle, x, n, &phi, length);
}

std::function<double(const Point&)> obstacle_gap(const RigidObstacle& obstacle, const mesh::ContactBoundary& contact) {
  auto locator = std::make_shared<EdgeLocator>(contact);
  // φ parsed once: the Newton iteration evaluates it a few times per point.
  std::shared_ptr<const Expression> phi;
  if (obstacle.type == ObstacleType::distance)
    phi = std::make_shared<const Expression>(obstacle.distance, obstacle.origin + ": key 'obstacle.distance'");
  return [obstacle, locator, phi, length = contact.length()](const Point& x) {
    return checked_gap(obstacle, x, locator->normal_at(x), phi.get(), length);
  };
}

}  // namespace hpcontact::contact
