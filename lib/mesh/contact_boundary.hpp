// Γ_C as seen from T_h: the chain of boundary edges with part `contact`, ordered end to end and
// parametrized by arc length s ∈ [0, L] (along curved edges too: the local edge parameter is then
// a non-linear function of s, inverted by Newton). Shared by the inf-sup analysis and the contact
// solver.
#pragma once

#include <memory>
#include <vector>

#include "mesh/quad_mesh.hpp"

namespace hpcontact::mesh {

class EdgeArcLength;

/// One edge of T_h on Γ_C: arc-length interval [s_begin, s_end] and how to reach it from its cell.
struct TraceEdge {
  int edge = -1;
  int cell = -1;
  int local_edge = -1;
  double s_begin = 0.0, s_end = 0.0;
  /// The cell's local edge parameter t ∈ [-1,1] runs against s (t = -1 at s_end).
  bool reversed = false;
  /// Arc length along a curved edge (nullptr: straight, s affine in t).
  std::shared_ptr<const EdgeArcLength> arc;
  /// Local edge parameter t of arc length s in [s_begin, s_end].
  double local_parameter(double s) const;
};

class ContactBoundary {
 public:
  /// Orders the contact edges into one open chain. s = 0 is the chain end with the smaller
  /// x (then smaller y): on the paper's square s = x + 1.
  /// @throws InputError if Γ_C is empty, not connected, closed, or branches.
  explicit ContactBoundary(const QuadMesh& mesh);

  const QuadMesh& mesh() const { return *mesh_; }
  double length() const { return length_; }
  const std::vector<TraceEdge>& edges() const { return edges_; }
  /// Arc lengths of the trace vertices: 0 = s_0 < ... < s_k = L.
  std::vector<double> breakpoints() const;
  /// Physical point at arc length s.
  Point point_at(double s) const;
  /// Outward unit normal of Ω at arc length s.
  Point normal_at(double s) const;
  /// Unit tangent at arc length s, pointing towards increasing s.
  Point tangent_at(double s) const;
  /// Whether some edge of Γ_C is curved.
  bool is_curved() const;
  /// Index of the trace edge containing s (the left one at a shared vertex).
  int edge_index_at(double s) const;

 private:
  const QuadMesh* mesh_;
  std::vector<TraceEdge> edges_;
  std::vector<Point> chain_vertices_;
  double length_ = 0.0;
};

}  // namespace hpcontact::mesh
