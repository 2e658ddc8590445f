// TriangleShapes: the recurrences of the triangle basis, differentiated exactly by carrying
// (value, ∂/∂ξ, ∂/∂η) through them.
#include "basis/triangle_basis.hpp"

#include <cmath>

#include "core/error.hpp"

namespace hpcontact::basis {
namespace {

// A polynomial in (ξ, η) at one point with its gradient: forward-mode differentiation, so that
// every recurrence below yields derivatives without a second set of formulas.
struct Dual {
  double v = 0.0, x = 0.0, y = 0.0;
};
Dual operator+(const Dual& a, const Dual& b) { return {a.v + b.v, a.x + b.x, a.y + b.y}; }
Dual operator-(const Dual& a, const Dual& b) { return {a.v - b.v, a.x - b.x, a.y - b.y}; }
Dual operator*(const Dual& a, const Dual& b) { return {a.v * b.v, a.x * b.v + a.v * b.x, a.y * b.v + a.v * b.y}; }
Dual operator*(double s, const Dual& a) { return {s * a.v, s * a.x, s * a.y}; }

ShapeValue to_shape(const Dual& d) { return {d.v, d.x, d.y}; }

// Scaled Jacobi polynomials Q_n(x, s) = s^n P_n^{(α,β)}(x / s), n = 0…n_max: polynomials in (x, s)
// even where s = 0 (the triangle's top vertex for the bubbles' first factor).
std::vector<Dual> scaled_jacobi(int n_max, double alpha, double beta, const Dual& x, const Dual& s) {
  std::vector<Dual> q(std::max(n_max + 1, 1));
  q[0] = {1.0, 0.0, 0.0};
  if (n_max >= 1) q[1] = ((alpha + 1.0) * s) + (0.5 * (alpha + beta + 2.0)) * (x - s);
  const Dual s2 = s * s;
  for (int n = 2; n <= n_max; ++n) {
    const double c = 2.0 * n + alpha + beta;
    const double denominator = 2.0 * n * (n + alpha + beta) * (c - 2.0);
    const Dual linear = (c * (c - 2.0)) * x + (alpha * alpha - beta * beta) * s;
    q[n] = (1.0 / denominator) *
           ((c - 1.0) * (linear * q[n - 1]) - (2.0 * (n + alpha - 1.0) * (n + beta - 1.0) * c) * (s2 * q[n - 2]));
  }
  return q;
}

// κ_k(t) = 4 N_k(t)/(1 − t²) = −4 √((2k−1)/2) P'_{k−1}(t) / (k(k−1)), k = 2…p (index k − 2),
// from (P_k − P_{k−2}) = −(2k−1)/(k(k−1)) (1 − t²) P'_{k−1} and P'_{n+1} = P'_{n−1} + (2n+1) P_n.
std::vector<Dual> edge_kernels(int p, const Dual& t) {
  std::vector<Dual> kernels;
  if (p < 2) return kernels;
  std::vector<Dual> legendre(p + 1), derivative(p + 1);
  legendre[0] = {1.0, 0.0, 0.0};
  legendre[1] = t;
  for (int n = 2; n <= p; ++n)
    legendre[n] = (1.0 / n) * ((2.0 * n - 1.0) * (t * legendre[n - 1]) - (n - 1.0) * legendre[n - 2]);
  derivative[0] = {0.0, 0.0, 0.0};
  derivative[1] = {1.0, 0.0, 0.0};
  for (int n = 1; n + 1 <= p; ++n) derivative[n + 1] = derivative[n - 1] + (2.0 * n + 1.0) * legendre[n];
  for (int k = 2; k <= p; ++k)
    kernels.push_back((-4.0 * std::sqrt((2.0 * k - 1.0) / 2.0) / (k * (k - 1.0))) * derivative[k - 1]);
  return kernels;
}

}  // namespace

TriangleShapes::TriangleShapes(int p, double xi, double eta) : degree_(p) {
  HPC_VERIFY(p >= 1, "triangle degree >= 1");
  const std::array<Dual, 3> lambda{Dual{-0.5 * (xi + eta), -0.5, -0.5}, Dual{0.5 * (1.0 + xi), 0.5, 0.0},
                                   Dual{0.5 * (1.0 + eta), 0.0, 0.5}};
  for (int v = 0; v < 3; ++v) vertex_[v] = to_shape(lambda[v]);

  constexpr std::array<std::array<int, 2>, 3> kEdges{{{0, 1}, {1, 2}, {0, 2}}};
  for (int e = 0; e < 3; ++e) {
    const Dual &a = lambda[kEdges[e][0]], &b = lambda[kEdges[e][1]];
    const Dual product = a * b;
    edge_[e].clear();
    for (const Dual& kernel : edge_kernels(p, b - a)) edge_[e].push_back(to_shape(product * kernel));
  }

  bubble_.clear();
  if (p >= 3) {
    const int n_max = p - 3;
    bubble_.resize(static_cast<std::size_t>(p - 2) * (p - 2));
    const Dual cubic = lambda[0] * lambda[1] * lambda[2];
    const auto first = scaled_jacobi(n_max, 2.0, 2.0, lambda[1] - lambda[0], lambda[0] + lambda[1]);
    const Dual y = 2.0 * lambda[2] - Dual{1.0, 0.0, 0.0};
    for (int n1 = 0; n1 <= n_max; ++n1) {
      const auto second = scaled_jacobi(n_max - n1, 2.0 * n1 + 5.0, 2.0, y, Dual{1.0, 0.0, 0.0});
      const Dual head = cubic * first[n1];
      for (int n2 = 0; n1 + n2 <= n_max; ++n2) bubble_[n1 * (p - 2) + n2] = to_shape(head * second[n2]);
    }
  }
}

}  // namespace hpcontact::basis
