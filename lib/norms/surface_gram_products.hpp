// Products by the interpolation-norm Gram matrix G of a grid T_{C,H} on a flat rectangular Γ_C
// (surface_interpolation_gram.hpp) and by an approximate inverse of it, without forming G: the
// multiplier coefficients are a matrix X (1-D functions along axis 1 × along axis 2), the moments
// of the multiplier they give are P1 X P2ᵀ, and
//     G x = P1ᵀ (W ⊙ (P1 X P2ᵀ)) P2,   W_jk = (1 + f1_j + f2_k)^{-1/2}          (direct), or
//     G x = Σ_r c_r e^{-s_r} A1_r X A2_rᵀ,   A_r = Pᵀ diag(e^{-s_r f}) P      (exponential sum),
// whichever costs fewer operations per product (the sum's cost does not grow with the modes, the
// direct one's does, with W's memory: above 2.5e7 weights, 200 MB, the sum is taken). The memory is that of the
// moments, W or the A_r: never the n² of G itself (n multipliers).
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "norms/surface_interpolation_gram.hpp"
#include "space/surface_multiplier_space.hpp"

namespace hpcontact::norms {

/// x ↦ G x with the cosine modes j < modes[0], k < modes[1]: equal to surface_interpolation_gram's
/// G times x to round-off. `multipliers` must outlive the operator.
class SurfaceGramProducts {
 public:
  /// @throws InternalError (verify) if T_{C,H} is not a grid or a mode count is below 1.
  SurfaceGramProducts(const space::SurfaceMultiplierSpace& multipliers, std::array<int, 2> modes,
                      GramSummation summation = GramSummation::cheaper);
  Eigen::Index size() const { return size_; }
  Eigen::VectorXd operator()(const Eigen::VectorXd& x) const;
  /// Whether the products go by the exponential sum.
  bool by_exponential_sum() const { return !along_1_.empty(); }

 private:
  const space::SurfaceMultiplierSpace* multipliers_;
  Eigen::Index size_;
  Eigen::MatrixXd p1_, p2_, weights_;               ///< direct
  std::vector<Eigen::MatrixXd> along_1_, along_2_;  ///< exponential sum: c_r e^{-s_r} A1_r, A2_r
};

/// x ↦ T x with T = M⁻¹ Cᵀ W⁻¹ C M⁻¹ ≈ G⁻¹ (M the multipliers' mass matrix, C the moments with 8
/// cosine modes per 1-D function and axis, W⁻¹ = (1 + f1 + f2)^{1/2}): G's inverse if the modes
/// spanned the multipliers exactly, and spectrally close to it otherwise (both scale like the
/// H^{-1/2} norm and its dual on each mode), so that it preconditions eigensolvers of pencils with
/// G (measured in tests/norms). Symmetric positive definite.
class SurfaceGramPreconditioner {
 public:
  explicit SurfaceGramPreconditioner(const space::SurfaceMultiplierSpace& multipliers);
  Eigen::VectorXd operator()(const Eigen::VectorXd& x) const;

 private:
  const space::SurfaceMultiplierSpace* multipliers_;
  Eigen::MatrixXd q1_, q2_;  ///< P M⁻¹ along each axis (modes × 1-D functions)
  Eigen::MatrixXd root_weights_;
};

}  // namespace hpcontact::norms
