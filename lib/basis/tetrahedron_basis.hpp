// The hierarchical H¹-conforming shape functions of degree ≤ p on the reference tetrahedron
// v0 = (−1,−1,−1), v1 = (1,−1,−1), v2 = (−1,1,−1), v3 = (−1,−1,1), in barycentric coordinates λ_v:
//   vertex v:                   λ_v
//   edge a→b (a < b), k = 2…p:  λ_a λ_b κ_k(λ_b − λ_a)                      (κ_k: basis/polynomial_dual.hpp)
//   face a<b<c, (n1, n2):       the triangle's bubble (basis/triangle_basis.hpp) in (λ_a, λ_b, λ_c),
//                               n1 + n2 ≤ p − 3
//   interior (n1, n2, n3):      λ0 λ1 λ2 λ3 Q^{(2,2)}_{n1}(λ1 − λ0, λ0 + λ1) Q^{(2n1+5,2)}_{n2}(λ2 − λ0 − λ1, λ0 + λ1 +
//   λ2)
//                               P^{(2n1+2n2+8,2)}_{n3}(2λ3 − 1), n1 + n2 + n3 ≤ p − 4  (Q scaled Jacobi)
// On an edge the edge mode is the Lobatto function N_k from the edge's first vertex, as on the
// hexahedron and the triangle; on a face the face's modes and the traces of its edge and vertex
// modes are the triangle's in the face's vertex order. Meshes list each tetrahedron's vertices
// in ascending global numbers (mesh/solid_mesh.hpp), so neighbours order a shared edge or face
// alike and share its traces without signs.
#pragma once

#include <array>
#include <vector>

#include "basis/polynomial_dual.hpp"
#include "basis/solid_cell_topology.hpp"

namespace hpcontact::basis {

/// A shape's value and reference gradient (∂/∂ξ, ∂/∂η, ∂/∂ζ) at one point.
using SolidShapeValue = Dual<3>;

class TetrahedronShapes {
 public:
  /// Every shape of degree ≤ p at the reference point (ξ, η, ζ). p ≥ 1.
  TetrahedronShapes(int p, double xi, double eta, double zeta);

  const SolidShapeValue& vertex(int v) const { return vertex_[v]; }
  /// Mode k (2 ≤ k ≤ p) of local edge `local_edge` (kTetEdgeVertices).
  const SolidShapeValue& edge(int local_edge, int k) const { return edge_[local_edge][k - 2]; }
  /// Mode (n1, n2), n1 + n2 ≤ p − 3, of local face `local_face` (kTetFaceVertices).
  const SolidShapeValue& face(int local_face, int n1, int n2) const {
    return face_[local_face][n1 * (degree_ - 2) + n2];
  }
  /// Interior mode (n1, n2, n3), n1 + n2 + n3 ≤ p − 4.
  const SolidShapeValue& interior(int n1, int n2, int n3) const {
    return interior_[(n1 * (degree_ - 3) + n2) * (degree_ - 3) + n3];
  }

 private:
  int degree_;
  std::array<SolidShapeValue, 4> vertex_;
  std::array<std::vector<SolidShapeValue>, 6> edge_;
  std::array<std::vector<SolidShapeValue>, 4> face_;
  std::vector<SolidShapeValue> interior_;
};

/// Number of shapes of degree ≤ p on a tetrahedron: (p + 1)(p + 2)(p + 3)/6.
inline int tetrahedron_shape_count(int p) { return (p + 1) * (p + 2) * (p + 3) / 6; }
/// Modes of a triangular face and interior modes of a tetrahedron of degree p.
inline int triangle_face_mode_count(int p) { return (p - 1) * (p - 2) / 2; }
inline int tetrahedron_interior_mode_count(int p) { return (p - 1) * (p - 2) * (p - 3) / 6; }

}  // namespace hpcontact::basis
