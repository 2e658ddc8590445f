// The transfinite map of a cell with curved sides: the bilinear (square) or affine (triangle) map
// of its corners plus, for each curved side, that side's deviation from its chord blended into
// the cell — Gordon–Hall on the square, 0.5 (1 ∓ ·) δ(s) per side; on the triangle
// 4 λ_a λ_b φ(λ_b − λ_a) with φ(s) = δ(s)/(1 − s²) for side a→b, which is δ on that side and
// vanishes on the other two. On every side the map is exactly that side's curve (or its chord), so
// two cells sharing a side agree on it; no nodes inside the cell are needed.
// A refined cell keeps its parent's map composed with the affine map of its child's reference cell
// into the parent's, so refinement nests spaces and leaves the domain unchanged.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

#include "mesh/edge_curve.hpp"
#include "mesh/mesh.hpp"

namespace hpcontact {
class ByteReader;
class ByteWriter;
}  // namespace hpcontact

namespace hpcontact::mesh {

/// The distinct curves of maps packed together, each sent once: a refined cell's children share
/// its curves, and the two cells of a side share that side's (copied per map, a twice-refined
/// curved mesh took 2.4 times its memory on the receiving ranks).
struct CurveTable {
  std::unordered_map<const EdgeCurve*, std::int32_t> index;
  std::vector<const EdgeCurve*> curves;  ///< in order of first use
  /// The curve's number in the table (added on first use); -1 for none.
  std::int32_t number_of(const EdgeCurve* curve);
};

class BlendedGeometry {
 public:
  /// A cell of `type` with straight sides between `corners` (local vertex order of Mesh; the
  /// fourth is unused for a triangle).
  BlendedGeometry(CellType type, const std::array<Point, 4>& corners);

  /// Side `local_edge` follows `curve`; `reversed`: the curve runs against the local edge
  /// direction (its t = -1 at the local edge's end vertex).
  void set_side(int local_edge, std::shared_ptr<const EdgeCurve> curve, bool reversed);
  bool has_curved_side() const;
  /// Whether the map covers the whole original cell (not a refined part of it).
  bool is_whole() const { return !part_; }

  /// The same map composed with the affine map r ↦ offset + matrix · r of a child's reference cell
  /// into this cell's (of the same type).
  BlendedGeometry restricted(const Eigen::Matrix2d& matrix, const Eigen::Vector2d& offset) const;

  Point map(double xi, double eta) const;
  /// The curve side `local_edge` follows (null: a straight side); the same object for every map
  /// that shares it.
  const EdgeCurve* side_curve(int local_edge) const { return sides_[local_edge].curve.get(); }
  /// The map as bytes, and back (mesh/mesh_bytes.cpp): the same map to the bit, its curves by
  /// their numbers in `curves` (the sender's table; the receiver's list of it).
  void pack(ByteWriter& out, CurveTable& curves) const;
  static BlendedGeometry unpack(ByteReader& in, const std::vector<std::shared_ptr<const EdgeCurve>>& curves);
  /// [[∂x/∂ξ, ∂x/∂η], [∂y/∂ξ, ∂y/∂η]].
  Eigen::Matrix2d jacobian(double xi, double eta) const;

 private:
  struct Side {
    std::shared_ptr<const EdgeCurve> curve;
    bool reversed = false;
    /// Triangle: φ(s) = δ(s)/(1 − s²) as a polynomial in the local edge parameter s.
    std::shared_ptr<const EdgeCurve> quotient;
  };
  /// The side's deviation δ(s) from its chord and δ'(s), s the local edge parameter.
  std::pair<Point, Point> deviation(int local_edge, double s) const;
  /// The map and its Jacobian at a point of the original cell's reference cell.
  std::pair<Point, Eigen::Matrix2d> square_map(double x, double y) const;
  std::pair<Point, Eigen::Matrix2d> triangle_map(double x, double y) const;
  std::pair<Point, Eigen::Matrix2d> original(double xi, double eta) const;

  CellType type_;
  std::array<Point, 4> corners_;
  std::array<Side, 4> sides_;
  /// The affine map of this part's reference cell into the original cell's (empty: the whole cell).
  struct Part {
    Eigen::Matrix2d matrix;
    Eigen::Vector2d offset;
  };
  std::optional<Part> part_;
};

}  // namespace hpcontact::mesh
