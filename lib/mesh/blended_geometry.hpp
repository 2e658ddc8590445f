// The transfinite (Gordon–Hall) map of a quadrilateral cell with curved sides: the bilinear map of
// its corners plus, for each curved side, that side's deviation from its chord blended linearly
// into the cell. On every side the map is exactly that side's curve (or its chord), so two cells
// sharing a side agree on it; no nodes inside the cell are needed.
// A refined cell keeps its parent's map restricted to a sub-square, so refinement nests spaces and
// leaves the domain unchanged.
#pragma once

#include <Eigen/Core>
#include <array>
#include <memory>

#include "mesh/edge_curve.hpp"
#include "mesh/mesh.hpp"

namespace hpcontact::mesh {

class BlendedGeometry {
 public:
  /// A cell with straight sides between `corners` (local vertex order of Mesh).
  explicit BlendedGeometry(const std::array<Point, 4>& corners);

  /// Side `local_edge` follows `curve`; `reversed`: the curve runs against the local edge
  /// direction (its t = -1 at the local edge's end vertex).
  void set_side(int local_edge, std::shared_ptr<const EdgeCurve> curve, bool reversed);
  bool has_curved_side() const;
  /// Whether the map covers the whole original cell (not a refined part of it).
  bool is_whole() const { return xi0_ == -1.0 && xi1_ == 1.0 && eta0_ == -1.0 && eta1_ == 1.0; }

  /// The same map restricted to the sub-square [ξ0, ξ1] × [η0, η1] of this cell's reference square,
  /// reparametrized onto [-1, 1]².
  BlendedGeometry restricted(double xi0, double xi1, double eta0, double eta1) const;

  Point map(double xi, double eta) const;
  /// [[∂x/∂ξ, ∂x/∂η], [∂y/∂ξ, ∂y/∂η]].
  Eigen::Matrix2d jacobian(double xi, double eta) const;

 private:
  struct Side {
    std::shared_ptr<const EdgeCurve> curve;
    bool reversed = false;
  };
  /// The side's deviation δ(s) from its chord and δ'(s), s the local edge parameter.
  std::pair<Point, Point> deviation(int local_edge, double s) const;

  std::array<Point, 4> corners_;
  std::array<Side, 4> sides_;
  // The sub-square of the original cell's reference square this map covers.
  double xi0_ = -1.0, xi1_ = 1.0, eta0_ = -1.0, eta1_ = 1.0;
};

}  // namespace hpcontact::mesh
