// TetrahedronShapes: the recurrences of the tetrahedron basis, differentiated exactly by carrying
// the three reference derivatives through them (basis/polynomial_dual.hpp).
#include "basis/tetrahedron_basis.hpp"

#include "core/error.hpp"

namespace hpcontact::basis {

TetrahedronShapes::TetrahedronShapes(int p, double xi, double eta, double zeta) : degree_(p) {
  HPC_VERIFY(p >= 1, "tetrahedron degree >= 1");
  using D3 = SolidShapeValue;
  const std::array<D3, 4> lambda{D3{-0.5 * (1.0 + xi + eta + zeta), {-0.5, -0.5, -0.5}},
                                 D3{0.5 * (1.0 + xi), {0.5, 0.0, 0.0}}, D3{0.5 * (1.0 + eta), {0.0, 0.5, 0.0}},
                                 D3{0.5 * (1.0 + zeta), {0.0, 0.0, 0.5}}};
  vertex_ = lambda;
  for (int e = 0; e < 6; ++e) {
    const D3 &a = lambda[kTetEdgeVertices[e][0]], &b = lambda[kTetEdgeVertices[e][1]];
    const D3 product = a * b;
    for (const D3& kernel : edge_kernels(p, b - a)) edge_[e].push_back(product * kernel);
  }
  const D3 one = D3::constant(1.0);
  if (p >= 3) {
    // The triangle's bubbles in the face's barycentrics (basis/triangle_basis.cpp, same order).
    const int n_max = p - 3;
    for (int f = 0; f < 4; ++f) {
      const D3 &a = lambda[kTetFaceVertices[f][0]], &b = lambda[kTetFaceVertices[f][1]];
      const D3& c = lambda[kTetFaceVertices[f][2]];
      face_[f].resize(static_cast<std::size_t>(p - 2) * (p - 2));
      const D3 cubic = a * b * c;
      const auto first = scaled_jacobi(n_max, 2.0, 2.0, b - a, a + b);
      const D3 y = 2.0 * c - one;
      for (int n1 = 0; n1 <= n_max; ++n1) {
        const auto second = scaled_jacobi(n_max - n1, 2.0 * n1 + 5.0, 2.0, y, one);
        const D3 head = cubic * first[n1];
        for (int n2 = 0; n1 + n2 <= n_max; ++n2) face_[f][n1 * (p - 2) + n2] = head * second[n2];
      }
    }
  }
  if (p >= 4) {
    const int n_max = p - 4;
    interior_.resize(static_cast<std::size_t>(p - 3) * (p - 3) * (p - 3));
    const D3 quartic = lambda[0] * lambda[1] * lambda[2] * lambda[3];
    const D3 s1 = lambda[0] + lambda[1], s2 = s1 + lambda[2];
    const auto first = scaled_jacobi(n_max, 2.0, 2.0, lambda[1] - lambda[0], s1);
    for (int n1 = 0; n1 <= n_max; ++n1) {
      const auto second = scaled_jacobi(n_max - n1, 2.0 * n1 + 5.0, 2.0, lambda[2] - s1, s2);
      for (int n2 = 0; n1 + n2 <= n_max; ++n2) {
        const auto third = scaled_jacobi(n_max - n1 - n2, 2.0 * (n1 + n2) + 8.0, 2.0, 2.0 * lambda[3] - one, one);
        const D3 head = quartic * first[n1] * second[n2];
        for (int n3 = 0; n1 + n2 + n3 <= n_max; ++n3) interior_[(n1 * (p - 3) + n2) * (p - 3) + n3] = head * third[n3];
      }
    }
  }
}

}  // namespace hpcontact::basis
