// The hierarchical H¹-conforming shape functions of degree ≤ p on the reference triangle
// (-1,-1), (1,-1), (-1,1), in barycentric coordinates λ0, λ1, λ2 (λ_v = 1 at local vertex v):
//   vertex v:            λ_v
//   edge a→b, k = 2…p:   λ_a λ_b κ_k(λ_b − λ_a),  κ_k(t) = 4 N_k(t) / (1 − t²)
//   bubble (n1, n2):     λ0 λ1 λ2 (λ0+λ1)^{n1} P^{(2,2)}_{n1}((λ1−λ0)/(λ0+λ1)) P^{(2n1+5,2)}_{n2}(2λ2 − 1),
//                        n1 + n2 ≤ p − 3
// On edge a→b (parameter t from a to b) the edge mode is exactly the Lobatto function N_k(t) of
// the quadrilateral basis (basis/lobatto.hpp) and every other mode of that edge's degree vanishes
// or is a vertex function: so triangles and quadrilaterals share edge traces, and mixed meshes are
// conforming with the same orientation rule (N_k(−t) = (−1)^k N_k(t)). The bubbles' Jacobi
// weights follow the collapsed-coordinate (Dubiner) construction, which keeps the interior block
// well conditioned as p grows (tests/test_29_triangles.cpp measures it against the square's).
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

namespace hpcontact::basis {

/// A shape function's value and reference gradient at one point.
struct ShapeValue {
  double value = 0.0, d_xi = 0.0, d_eta = 0.0;
};

class TriangleShapes {
 public:
  /// Every shape of degree ≤ p at the reference point (ξ, η). p ≥ 1.
  TriangleShapes(int p, double xi, double eta);

  const ShapeValue& vertex(int v) const { return vertex_[v]; }
  /// Mode k (2 ≤ k ≤ p) of local edge `local_edge` (0: v0→v1, 1: v1→v2, 2: v0→v2).
  const ShapeValue& edge(int local_edge, int k) const { return edge_[local_edge][k - 2]; }
  /// Bubble (n1, n2), n1 + n2 ≤ p − 3.
  const ShapeValue& bubble(int n1, int n2) const { return bubble_[n1 * (degree_ - 2) + n2]; }

 private:
  int degree_;
  std::array<ShapeValue, 3> vertex_;
  std::array<std::vector<ShapeValue>, 3> edge_;
  std::vector<ShapeValue> bubble_;
};

/// Number of shapes of degree ≤ p on a triangle: (p + 1)(p + 2)/2.
inline int triangle_shape_count(int p) { return (p + 1) * (p + 2) / 2; }

}  // namespace hpcontact::basis
