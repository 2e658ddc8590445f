// EdgeCurve: Chebyshev–Lobatto interpolation of a curved edge and its derivative.
#include "mesh/edge_curve.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace hpcontact::mesh {

std::vector<double> EdgeCurve::chebyshev_lobatto(int n) {
  std::vector<double> t(n + 1);
  for (int k = 0; k <= n; ++k) t[k] = -std::cos(std::numbers::pi * k / n);
  t.front() = -1.0;
  t.back() = 1.0;
  return t;
}

namespace {

// Lagrange interpolation through (s_k, v_k) evaluated at t, O(n²): only used to convert a Gmsh
// line's equispaced nodes to Chebyshev values once per edge.
Point lagrange(const std::vector<double>& s, const std::vector<Point>& v, double t) {
  Point sum = Point::Zero();
  for (std::size_t i = 0; i < s.size(); ++i) {
    double basis = 1.0;
    for (std::size_t j = 0; j < s.size(); ++j)
      if (j != i) basis *= (t - s[j]) / (s[i] - s[j]);
    sum += basis * v[i];
  }
  return sum;
}

}  // namespace

EdgeCurve::EdgeCurve(std::vector<Point> values) : values_(std::move(values)) {
  const int n = static_cast<int>(values_.size()) - 1;
  HPC_VERIFY(n >= 1, "an edge curve needs at least two points");
  nodes_ = chebyshev_lobatto(n);
  weights_.resize(n + 1);
  for (int k = 0; k <= n; ++k) weights_[k] = (k % 2 == 0 ? 1.0 : -1.0) * ((k == 0 || k == n) ? 0.5 : 1.0);
  // γ'(t_i) = Σ_j D_ij γ(t_j) with the barycentric differentiation matrix
  // D_ij = (w_j / w_i) / (t_i - t_j) for i ≠ j and D_ii = -Σ_{j≠i} D_ij.
  slopes_.assign(n + 1, Point::Zero());
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      if (j != i) slopes_[i] += (weights_[j] / weights_[i]) / (nodes_[i] - nodes_[j]) * (values_[j] - values_[i]);
}

EdgeCurve EdgeCurve::interpolate(const std::function<Point(double)>& curve, int degree) {
  HPC_VERIFY(degree >= 1, "edge curve degree must be at least 1");
  std::vector<Point> values;
  for (double t : chebyshev_lobatto(degree)) values.push_back(curve(t));
  return EdgeCurve(std::move(values));
}

EdgeCurve EdgeCurve::through_equispaced(const std::vector<Point>& nodes) {
  const int q = static_cast<int>(nodes.size()) - 1;
  HPC_VERIFY(q >= 1, "an edge curve needs at least two nodes");
  std::vector<double> s(q + 1);
  for (int k = 0; k <= q; ++k) s[k] = -1.0 + 2.0 * k / q;
  std::vector<Point> values;
  for (double t : chebyshev_lobatto(q)) values.push_back(lagrange(s, nodes, t));
  values.front() = nodes.front();
  values.back() = nodes.back();
  return EdgeCurve(std::move(values));
}

Point EdgeCurve::barycentric(const std::vector<Point>& values, double t) const {
  Point numerator = Point::Zero();
  double denominator = 0.0;
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    const double difference = t - nodes_[k];
    if (difference == 0.0) return values[k];
    const double w = weights_[k] / difference;
    numerator += w * values[k];
    denominator += w;
  }
  return numerator / denominator;
}

Point EdgeCurve::point(double t) const { return barycentric(values_, t); }

Point EdgeCurve::derivative(double t) const { return barycentric(slopes_, t); }

double EdgeCurve::relative_deviation_from_chord() const {
  const Point a = values_.front(), b = values_.back();
  const double length = (b - a).norm();
  const Point normal = Point(-(b - a).y(), (b - a).x()) / length;
  double deviation = 0.0;
  for (const Point& value : values_) deviation = std::max(deviation, std::abs((value - a).dot(normal)));
  return deviation / length;
}

}  // namespace hpcontact::mesh
