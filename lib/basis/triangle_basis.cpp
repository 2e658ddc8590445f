// TriangleShapes: the recurrences of the triangle basis (basis/polynomial_dual.hpp), differentiated
// exactly by carrying (value, ∂/∂ξ, ∂/∂η) through them.
#include "basis/triangle_basis.hpp"

#include <cmath>

#include "basis/polynomial_dual.hpp"
#include "core/error.hpp"

namespace hpcontact::basis {
namespace {

using Dual2 = Dual<2>;

ShapeValue to_shape(const Dual2& d) { return {d.v, d.d[0], d.d[1]}; }

}  // namespace

TriangleShapes::TriangleShapes(int p, double xi, double eta) : degree_(p) {
  HPC_VERIFY(p >= 1, "triangle degree >= 1");
  const std::array<Dual2, 3> lambda{Dual2{-0.5 * (xi + eta), {-0.5, -0.5}}, Dual2{0.5 * (1.0 + xi), {0.5, 0.0}},
                                    Dual2{0.5 * (1.0 + eta), {0.0, 0.5}}};
  for (int v = 0; v < 3; ++v) vertex_[v] = to_shape(lambda[v]);

  constexpr std::array<std::array<int, 2>, 3> kEdges{{{0, 1}, {1, 2}, {0, 2}}};
  for (int e = 0; e < 3; ++e) {
    const Dual2 &a = lambda[kEdges[e][0]], &b = lambda[kEdges[e][1]];
    const Dual2 product = a * b;
    edge_[e].clear();
    for (const Dual2& kernel : edge_kernels(p, b - a)) edge_[e].push_back(to_shape(product * kernel));
  }

  bubble_.clear();
  if (p >= 3) {
    const int n_max = p - 3;
    bubble_.resize(static_cast<std::size_t>(p - 2) * (p - 2));
    const Dual2 cubic = lambda[0] * lambda[1] * lambda[2];
    const auto first = scaled_jacobi(n_max, 2.0, 2.0, lambda[1] - lambda[0], lambda[0] + lambda[1]);
    const Dual2 y = 2.0 * lambda[2] - Dual2::constant(1.0);
    for (int n1 = 0; n1 <= n_max; ++n1) {
      const auto second = scaled_jacobi(n_max - n1, 2.0 * n1 + 5.0, 2.0, y, Dual2::constant(1.0));
      const Dual2 head = cubic * first[n1];
      for (int n2 = 0; n1 + n2 <= n_max; ++n2) bubble_[n1 * (p - 2) + n2] = to_shape(head * second[n2]);
    }
  }
}

}  // namespace hpcontact::basis
