// The boundary mesh T_{C,H} of Γ_C, independent of T_h: segments given by breakpoints in the
// arc length s of ContactBoundary (uniform, graded, or explicit), grouped by the zones of Γ_C.
#pragma once

#include <string>
#include <vector>

namespace hpcontact::mesh {

/// A connected piece of Γ_C as seen by T_{C,H}: the arc [begin, end] of s.
struct BoundaryZone {
  double begin = 0.0, end = 0.0;
  bool closed = false;
};

class BoundaryMesh {
 public:
  /// @param nodes strictly increasing, nodes.front() = 0, nodes.back() = length of Γ_C.
  /// @throws InputError otherwise (naming `origin`).
  BoundaryMesh(std::vector<double> nodes, const std::string& origin = "boundary mesh");

  /// m equal segments of [0, length].
  static BoundaryMesh uniform(double length, int m);
  /// m segments graded geometrically towards both ends with ratio q ∈ (0, 1] between
  /// neighbouring segments (q = 1: uniform).
  static BoundaryMesh graded(double length, int m, double ratio);

  int n_segments() const { return static_cast<int>(nodes_.size()) - 1; }
  double length() const { return nodes_.back(); }
  const std::vector<double>& nodes() const { return nodes_; }
  double segment_begin(int k) const { return nodes_[k]; }
  double segment_end(int k) const { return nodes_[k + 1]; }
  /// Largest segment length H.
  double mesh_size() const;
  /// Segment containing s (the left one at a breakpoint).
  int segment_at(double s) const;

  /// The zones, one after the other from 0 to the length (default: one open zone).
  const std::vector<BoundaryZone>& zones() const { return zones_; }
  /// @throws InputError naming `origin` unless the zones run from 0 to the length end to end and
  /// every zone end is a breakpoint.
  void set_zones(std::vector<BoundaryZone> zones, const std::string& origin);
  /// The zone of segment k.
  int zone_of_segment(int k) const;

 private:
  std::vector<double> nodes_;
  std::vector<BoundaryZone> zones_;
};

/// Sorted union of two breakpoint sets, merging points closer than 1e-12·length: the common
/// refinement on which products of functions on both meshes are polynomials.
std::vector<double> common_refinement(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace hpcontact::mesh
