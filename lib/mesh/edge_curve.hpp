// A curved cell edge as a polynomial curve γ : [-1, 1] → R², held by its values at the
// Chebyshev–Lobatto points and evaluated by barycentric interpolation (stable for any degree).
// Made from the exact geometry (sampled through the Gmsh API) or from a high-order mesh's nodes.
#pragma once

#include <functional>
#include <vector>

#include "mesh/mesh.hpp"

namespace hpcontact::mesh {

class EdgeCurve {
 public:
  /// The interpolant of `curve` at the degree + 1 Chebyshev–Lobatto points. Sampling a smooth
  /// curve this way converges exponentially in the degree: an arc of a circle spanning 1 rad is
  /// reproduced to 1e-16 at degree 16.
  static EdgeCurve interpolate(const std::function<Point(double)>& curve, int degree);
  /// The interpolant of the given values at chebyshev_lobatto(values.size() - 1).
  static EdgeCurve from_values(std::vector<Point> values) { return EdgeCurve(std::move(values)); }
  /// The n + 1 Chebyshev–Lobatto points -cos(kπ/n), ascending, ends exactly ±1.
  static std::vector<double> chebyshev_lobatto(int n);
  /// The polynomial through `nodes` at equally spaced parameters t_k = -1 + 2k/q (a Gmsh line of
  /// order q lists its nodes in this order after reordering: first end, interior nodes, last end).
  static EdgeCurve through_equispaced(const std::vector<Point>& nodes);

  int degree() const { return static_cast<int>(values_.size()) - 1; }
  /// γ at the interpolation points (from_values of them gives this curve again).
  const std::vector<Point>& values() const { return values_; }
  Point point(double t) const;
  /// dγ/dt.
  Point derivative(double t) const;
  /// The largest distance of the curve from the line through its ends at the interpolation points,
  /// relative to the chord's length: zero (to round-off) for a straight edge, however its points
  /// are spaced along it.
  double relative_deviation_from_chord() const;

 private:
  explicit EdgeCurve(std::vector<Point> values);
  Point barycentric(const std::vector<Point>& values, double t) const;

  std::vector<double> nodes_;    ///< Chebyshev–Lobatto points -cos(kπ/n), ascending
  std::vector<double> weights_;  ///< barycentric weights (-1)^k, halved at the ends
  std::vector<Point> values_;    ///< γ at the nodes
  std::vector<Point> slopes_;    ///< γ' at the nodes (the differentiation matrix applied to values_)
};

}  // namespace hpcontact::mesh
