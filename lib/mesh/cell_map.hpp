// The map Ψ_T from the reference square [-1,1]² onto a quadrilateral cell (bilinear, or blended
// from curved sides: mesh/blended_geometry.hpp), its Jacobian, and its inverse (Newton), used by
// assembly, evaluation and point location.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "mesh/blended_geometry.hpp"
#include "mesh/quad_mesh.hpp"

namespace hpcontact::mesh {

class CellMap {
 public:
  CellMap(const QuadMesh& mesh, int cell);

  /// Ψ_T(ξ, η).
  Point map(double xi, double eta) const;
  /// DΨ_T(ξ, η) = [[∂x/∂ξ, ∂x/∂η], [∂y/∂ξ, ∂y/∂η]].
  Eigen::Matrix2d jacobian(double xi, double eta) const;
  /// dΨ_T/dt along local edge `local_edge` at its parameter t (its length is the speed ds/dt).
  Point edge_tangent(int local_edge, double t) const;
  /// Whether the cell has a curved side (or is part of a cell that has one).
  bool is_curved() const { return curved_ != nullptr; }
  /// Whether the cell is a parallelogram (Ψ_T affine, DΨ_T constant): the ξη coefficient is
  /// below 1e-13 of the cell's size. Such cells admit exact Kronecker-product element matrices.
  bool is_parallelogram() const;
  /// Reference coordinates of x if x lies in the cell (within `tolerance` in reference
  /// coordinates), otherwise nothing.
  std::optional<Eigen::Vector2d> inverse(const Point& x, double tolerance = 1e-10) const;

 private:
  // Straight cells: Ψ(ξ,η) = a + b ξ + c η + d ξη (a, b, c, d also approximate a curved cell's).
  Point a_, b_, c_, d_;
  const BlendedGeometry* curved_ = nullptr;
};

/// The reference point of local edge `local_edge` at its parameter t (see QuadMesh's numbering).
Eigen::Vector2d local_edge_point(int local_edge, double t);

}  // namespace hpcontact::mesh
