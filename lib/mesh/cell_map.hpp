// The bilinear map Ψ_T from the reference square [-1,1]² onto a quadrilateral cell, its Jacobian,
// and its inverse (Newton), used by assembly, evaluation and point location.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "mesh/quad_mesh.hpp"

namespace hpcontact::mesh {

class CellMap {
 public:
  CellMap(const QuadMesh& mesh, int cell);

  /// Ψ_T(ξ, η).
  Point map(double xi, double eta) const;
  /// DΨ_T(ξ, η) = [[∂x/∂ξ, ∂x/∂η], [∂y/∂ξ, ∂y/∂η]].
  Eigen::Matrix2d jacobian(double xi, double eta) const;
  /// Whether the cell is a parallelogram (Ψ_T affine, DΨ_T constant): the ξη coefficient is
  /// below 1e-13 of the cell's size. Such cells admit exact Kronecker-product element matrices.
  bool is_parallelogram() const;
  /// Reference coordinates of x if x lies in the cell (within `tolerance` in reference
  /// coordinates), otherwise nothing.
  std::optional<Eigen::Vector2d> inverse(const Point& x, double tolerance = 1e-10) const;

 private:
  // Ψ(ξ,η) = a + b ξ + c η + d ξη
  Point a_, b_, c_, d_;
};

}  // namespace hpcontact::mesh
