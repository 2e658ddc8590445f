// Γ_C as seen from T_h: the boundary edges with part `contact`, in zones (each an open or a closed
// curve), ordered end to end and parametrized by arc length s ∈ [0, L], the zones one after the
// other (along curved edges too: the local edge parameter is then a non-linear function of s,
// inverted by Newton). Shared by the inf-sup analysis and the contact solver.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "mesh/boundary_mesh.hpp"
#include "mesh/mesh.hpp"

namespace hpcontact::mesh {

class EdgeArcLength;

/// One edge of T_h on Γ_C: arc-length interval [s_begin, s_end] and how to reach it from its cell.
struct TraceEdge {
  int edge = -1;
  int cell = -1;
  int local_edge = -1;
  int zone = 0;  ///< index into ContactBoundary::zones()
  double s_begin = 0.0, s_end = 0.0;
  /// The cell's local edge parameter t ∈ [-1,1] runs against s (t = -1 at s_end).
  bool reversed = false;
  /// Arc length along a curved edge (nullptr: straight, s affine in t).
  std::shared_ptr<const EdgeArcLength> arc;
  /// Local edge parameter t of arc length s in [s_begin, s_end].
  double local_parameter(double s) const;
};

/// One connected piece of Γ_C: the arc [s_begin, s_end] of s, edges [first_edge, end_edge).
struct ContactZone {
  double s_begin = 0.0, s_end = 0.0;
  int first_edge = 0, end_edge = 0;
  bool closed = false;  ///< a closed curve (a hole, a whole circle): s_end is s_begin again
  double length() const { return s_end - s_begin; }
};

class ContactBoundary {
 public:
  /// Orders the contact edges into zones, each a chain of edges. An open zone starts at its end
  /// with the smaller x (then smaller y): on the paper's square s = x + 1; a closed zone at its
  /// lexicographically first vertex, running with Ω on its left. Zones follow one another in the
  /// order of their start points.
  /// @throws InputError if Γ_C is empty or branches (a vertex with three or more contact edges).
  explicit ContactBoundary(const Mesh& mesh);

  const Mesh& mesh() const { return *mesh_; }
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
  /// The point and the unit tangent of trace edge k at arc length s ∈ [s_begin, s_end] of that edge
  /// (at a vertex shared by two edges, the one asked for).
  Point point_on_edge(int k, double s) const;
  Point tangent_on_edge(int k, double s) const;
  /// The same at the cell's local edge parameter t ∈ [-1, 1] of trace edge k, and the arc length
  /// there: a search along a curved edge in t costs one cell-map evaluation per point, where one
  /// in s costs an inversion of the arc length each.
  Point point_at_parameter(int k, double t) const;
  Point tangent_at_parameter(int k, double t) const;
  double arc_length_at_parameter(int k, double t) const;
  /// Whether some edge of Γ_C is curved.
  bool is_curved() const;
  const std::vector<ContactZone>& zones() const { return zones_; }
  /// The zone containing s (the left one where two meet).
  int zone_at(double s) const;
  /// The zones as a boundary mesh sees them (BoundaryMesh::set_zones).
  std::vector<BoundaryZone> boundary_zones() const;
  /// T_h|Γ_C as a boundary mesh: one segment per edge, with Γ_C's zones.
  BoundaryMesh edge_mesh() const;
  /// Index of the trace edge containing s (the left one at a shared vertex).
  int edge_index_at(double s) const;

 private:
  const Mesh* mesh_;
  std::vector<TraceEdge> edges_;
  std::vector<std::array<Point, 2>> edge_ends_;  ///< each trace edge's ends in the direction of s
  std::vector<ContactZone> zones_;
  double length_ = 0.0;
};

}  // namespace hpcontact::mesh
