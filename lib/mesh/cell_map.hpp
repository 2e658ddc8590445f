// The map Ψ_T from the reference cell onto a cell: bilinear on the square, affine on the triangle,
// or blended from curved sides (mesh/blended_geometry.hpp); its Jacobian and its inverse (Newton),
// used by assembly, evaluation and point location.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "mesh/blended_geometry.hpp"
#include "mesh/mesh.hpp"

namespace hpcontact::mesh {

class CellMap {
 public:
  CellMap(const Mesh& mesh, int cell);

  /// Ψ_T(ξ, η).
  Point map(double xi, double eta) const;
  /// DΨ_T(ξ, η) = [[∂x/∂ξ, ∂x/∂η], [∂y/∂ξ, ∂y/∂η]].
  Eigen::Matrix2d jacobian(double xi, double eta) const;
  /// dΨ_T/dt along local edge `local_edge` at its parameter t (its length is the speed ds/dt).
  Point edge_tangent(int local_edge, double t) const;
  /// Whether the cell has a curved side (or is part of a cell that has one).
  bool is_curved() const { return curved_ != nullptr; }
  CellType type() const { return type_; }
  /// Whether Ψ_T is affine (DΨ_T constant): a straight triangle, or a parallelogram (the ξη
  /// coefficient below 1e-13 of the cell's size). Parallelograms admit exact Kronecker-product
  /// element matrices; affine cells of equal Jacobian and degrees have equal element matrices.
  bool is_affine() const;
  /// Reference coordinates of x if x lies in the cell (within `tolerance` in reference
  /// coordinates; the result is moved into the reference cell), otherwise nothing.
  std::optional<Eigen::Vector2d> inverse(const Point& x, double tolerance = 1e-10) const;

 private:
  // Straight cells: Ψ(ξ,η) = a + b ξ + c η + d ξη, d = 0 on triangles (a, b, c, d also
  // approximate a curved cell's).
  Point a_, b_, c_, d_;
  CellType type_ = CellType::quadrilateral;
  const BlendedGeometry* curved_ = nullptr;
};

}  // namespace hpcontact::mesh
