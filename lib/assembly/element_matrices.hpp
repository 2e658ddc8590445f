// Element stiffness K_T = (∇φ_s, ∇φ_t)_T and mass M_T = (φ_s, φ_t)_T of one cell of S^p(T_h), in
// the order of H1Space::cell_shapes with the shapes' signs applied: the one place that integrates
// them, for global assembly and for static condensation alike.
#pragma once

#include <Eigen/Core>
#include <map>

#include "space/h1_space.hpp"

namespace hpcontact::assembly {

class ElementMatrices {
 public:
  /// `kronecker_parallelograms`: parallelogram cells by Kronecker products of 1D matrices (exact,
  /// O(p⁴) per cell); false: every cell by quadrature (O(p⁶)), the independent path tests use.
  explicit ElementMatrices(const space::H1Space& space, bool kronecker_parallelograms = true);

  /// K_T into `stiffness` and M_T into `mass` (nullptr: not wanted), each of shape
  /// (n_shapes, n_shapes) with n_shapes = space.cell_shapes(cell).size().
  void compute(int cell, Eigen::MatrixXd* stiffness, Eigen::MatrixXd* mass);

  /// D_ab = (∂_a φ_s, ∂_b φ_t)_T for a, b ∈ {x, y}, each of shape (n_shapes, n_shapes) with the
  /// shapes' signs applied: the blocks of the elasticity stiffness (K_T = D_xx + D_yy).
  struct Directional {
    Eigen::MatrixXd xx, xy, yx, yy;
  };
  Directional directional(int cell);

  /// The Jacobian DΨ_T if the cell is a parallelogram (and the Kronecker path is on): equal
  /// Jacobians and degrees give equal element matrices up to the shapes' signs. False for
  /// triangles (no tensor structure), which always take the quadrature path.
  bool constant_jacobian(int cell, Eigen::Matrix2d& jacobian) const;

 private:
  struct LineMatrices {
    Eigen::MatrixXd stiffness, mass, mixed;
  };
  const LineMatrices& line(int degree);

  const space::H1Space* space_;
  bool kronecker_parallelograms_;
  std::map<int, LineMatrices> lines_;  // per degree
};

}  // namespace hpcontact::assembly
