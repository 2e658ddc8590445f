// Continuous piecewise polynomials on a partition of an interval of arc length, in the Lobatto
// basis (hats and bubbles), with or without the functions at the interval's two ends: the 1-D
// trace spaces the local inf-sup predictor (infsup/local_alpha.hpp) pairs with multipliers.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace hpcontact::space {

class PiecewiseSpace1D {
 public:
  /// @param nodes strictly increasing, at least two; @param degrees one per piece, ≥ 1;
  /// @param keep_left, keep_right whether the hat at that end is in the space (else the space
  /// vanishes there). @throws std::logic_error on a malformed partition (a programming error).
  PiecewiseSpace1D(std::vector<double> nodes, std::vector<int> degrees, bool keep_left, bool keep_right);

  int n_dofs() const { return n_dofs_; }
  int n_pieces() const { return static_cast<int>(degrees_.size()); }
  const std::vector<double>& nodes() const { return nodes_; }
  int degree(int piece) const { return degrees_[piece]; }
  /// The piece containing s (the left one at a node); -1 outside [nodes.front(), nodes.back()].
  int piece_at(double s) const;

  /// The space's functions that do not vanish on `piece`, at the piece's coordinate t ∈ [-1, 1]:
  /// their dofs, values and derivatives in the arc length s (shapes (n) each; n ≤ degree + 1).
  struct PieceValues {
    std::vector<int> dofs;
    Eigen::VectorXd values, derivatives;
  };
  PieceValues values_on(int piece, double t) const;

  /// ∫ φ_i φ_j ds and ∫ φ_i' φ_j' ds: shapes (n_dofs, n_dofs).
  Eigen::MatrixXd mass() const;
  Eigen::MatrixXd stiffness() const;

 private:
  std::vector<double> nodes_;
  std::vector<int> degrees_;
  std::vector<int> vertex_dof_;    ///< per node; -1 for an end left out
  std::vector<int> first_bubble_;  ///< per piece: the dof of its bubble of degree 2
  int n_dofs_ = 0;
};

}  // namespace hpcontact::space
