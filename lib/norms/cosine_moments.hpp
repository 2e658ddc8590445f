// The one-dimensional pieces of the interpolation norm on a flat rectangular Γ_C, shared by the
// dense Gram matrix (surface_interpolation_gram.hpp) and its products (surface_gram_products.hpp):
// the cosine moments of the tensor multipliers along one axis, the surface operator's
// frequencies, and the weights (1 + f1 + f2)^{-1/2} as a sum of exponentials.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "space/surface_multiplier_space.hpp"

namespace hpcontact::norms {

/// Along axis k: (c_j, ℓ_i) for the modes j < n_modes (c_0 = 1/√L, c_j = √(2/L) cos(jπa/L)) and
/// the 1-D multiplier functions i = cell · (p_C + 1) + a (cell along the axis, a its local
/// Lagrange index), shape (n_modes, cells · (p_C + 1)). Needs a grid T_{C,H}.
Eigen::MatrixXd cosine_moments(const space::SurfaceMultiplierSpace& multipliers, int axis, int n_modes);

/// (jπ/L)² for j < n_modes along `axis` of Γ_C: the surface operator's eigenvalues are 1 + f1_j + f2_k.
Eigen::VectorXd cosine_frequencies(const space::SurfaceMultiplierSpace& multipliers, int axis, int n_modes);

/// The multiplier dof of the 1-D functions (i1, i2) along the two axes (tensor Lagrange on the grid).
Eigen::Index tensor_dof(const space::SurfaceMultiplierSpace& multipliers, Eigen::Index i1, Eigen::Index i2);

/// The weights (1 + a_j + b_k)^{-1/2} as Σ_r c_r e^{-s_r} e^{-s_r a_j} e^{-s_r b_k}: the trapezoidal
/// rule, step 1/4, for x^{-1/2} = π^{-1/2} ∫ e^{v/2 − x e^v} dv (x = 1 + a + b ∈ [1, largest]).
/// The integrand is analytic in the strip |Im v| < π/2, so the rule's relative error is about
/// 3.3 e^{-2π·1.2·4} ≈ 2.6e-13 at most (measured: 1e-14); the left end is cut where the neglected
/// tail 2 e^{v/2}/√π is 1e-14 of largest^{-1/2}; the terms with largest · e^v < 1e-17 have
/// e^{-x e^v} = 1 to round-off and are summed into one constant term (s = 0).
struct ExponentialSum {
  std::vector<double> coefficient, rate;  ///< c_r, s_r
};
ExponentialSum exponential_sum(double largest);

}  // namespace hpcontact::norms
