// The boundary mesh T_{C,H} of Γ_C, independent of T_h: segments given by breakpoints in the
// arc length s of ContactBoundary (uniform, graded, or explicit).
#pragma once

#include <string>
#include <vector>

namespace hpcontact::mesh {

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

 private:
  std::vector<double> nodes_;
};

/// Sorted union of two breakpoint sets, merging points closer than 1e-12·length: the common
/// refinement on which products of functions on both meshes are polynomials.
std::vector<double> common_refinement(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace hpcontact::mesh
