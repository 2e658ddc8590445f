// Polynomials carried with their gradient through recurrences (forward-mode differentiation in
// D reference coordinates), and the two recurrences the simplex bases are made of: scaled Jacobi
// polynomials and the edge kernels κ_k of the Lobatto functions.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace hpcontact::basis {

/// A polynomial's value at one point and its D reference derivatives.
template <int D>
struct Dual {
  double v = 0.0;
  std::array<double, D> d{};
  static Dual constant(double value) { return {value, {}}; }
};

template <int D>
Dual<D> operator+(const Dual<D>& a, const Dual<D>& b) {
  Dual<D> c{a.v + b.v, {}};
  for (int k = 0; k < D; ++k) c.d[k] = a.d[k] + b.d[k];
  return c;
}
template <int D>
Dual<D> operator-(const Dual<D>& a, const Dual<D>& b) {
  Dual<D> c{a.v - b.v, {}};
  for (int k = 0; k < D; ++k) c.d[k] = a.d[k] - b.d[k];
  return c;
}
template <int D>
Dual<D> operator*(const Dual<D>& a, const Dual<D>& b) {
  Dual<D> c{a.v * b.v, {}};
  for (int k = 0; k < D; ++k) c.d[k] = a.d[k] * b.v + a.v * b.d[k];
  return c;
}
template <int D>
Dual<D> operator*(double s, const Dual<D>& a) {
  Dual<D> c{s * a.v, {}};
  for (int k = 0; k < D; ++k) c.d[k] = s * a.d[k];
  return c;
}

/// Scaled Jacobi polynomials Q_n(x, s) = s^n P_n^{(α,β)}(x / s), n = 0…n_max: polynomials in
/// (x, s) even where s = 0 (a simplex's apex for the collapsed factors of its bubbles).
/// @return shape (max(n_max + 1, 1)).
template <int D>
std::vector<Dual<D>> scaled_jacobi(int n_max, double alpha, double beta, const Dual<D>& x, const Dual<D>& s) {
  std::vector<Dual<D>> q(std::max(n_max + 1, 1));
  q[0] = Dual<D>::constant(1.0);
  if (n_max >= 1) q[1] = ((alpha + 1.0) * s) + (0.5 * (alpha + beta + 2.0)) * (x - s);
  const Dual<D> s2 = s * s;
  for (int n = 2; n <= n_max; ++n) {
    const double c = 2.0 * n + alpha + beta;
    const double denominator = 2.0 * n * (n + alpha + beta) * (c - 2.0);
    const Dual<D> linear = (c * (c - 2.0)) * x + (alpha * alpha - beta * beta) * s;
    q[n] = (1.0 / denominator) *
           ((c - 1.0) * (linear * q[n - 1]) - (2.0 * (n + alpha - 1.0) * (n + beta - 1.0) * c) * (s2 * q[n - 2]));
  }
  return q;
}

/// κ_k(t) = 4 N_k(t)/(1 − t²) = −4 √((2k−1)/2) P'_{k−1}(t) / (k(k−1)), k = 2…p (index k − 2),
/// from (P_k − P_{k−2}) = −(2k−1)/(k(k−1)) (1 − t²) P'_{k−1} and P'_{n+1} = P'_{n−1} + (2n+1) P_n,
/// so that λ_a λ_b κ_k(λ_b − λ_a) is the Lobatto function N_k on the edge a → b.
/// @return shape (max(p − 1, 0)).
template <int D>
std::vector<Dual<D>> edge_kernels(int p, const Dual<D>& t) {
  std::vector<Dual<D>> kernels;
  if (p < 2) return kernels;
  std::vector<Dual<D>> legendre(p + 1), derivative(p + 1);
  legendre[0] = Dual<D>::constant(1.0);
  legendre[1] = t;
  for (int n = 2; n <= p; ++n)
    legendre[n] = (1.0 / n) * ((2.0 * n - 1.0) * (t * legendre[n - 1]) - (n - 1.0) * legendre[n - 2]);
  derivative[0] = Dual<D>::constant(0.0);
  derivative[1] = Dual<D>::constant(1.0);
  for (int n = 1; n + 1 <= p; ++n) derivative[n + 1] = derivative[n - 1] + (2.0 * n + 1.0) * legendre[n];
  for (int k = 2; k <= p; ++k)
    kernels.push_back((-4.0 * std::sqrt((2.0 * k - 1.0) / 2.0) / (k * (k - 1.0))) * derivative[k - 1]);
  return kernels;
}

}  // namespace hpcontact::basis
