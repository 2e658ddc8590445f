// The interpolation-norm Gram matrix of the multiplier space from the kernel of the norm itself,
// with no reference space W to resolve.
//
// H^{1/2}(Γ_C) = [L², H¹]_{1/2} on the arc [0, L] of Γ_C (no boundary conditions at its ends) is
// the Hilbert scale of T = I − d²/ds² with natural (Neumann) end conditions, so the dual norm is
//     ‖μ‖²_{-1/2} = (μ, T^{-1/2} μ),     G_ij = ∫∫ μ_i(s) k_N(s, t) μ_j(t) ds dt.
// On the line, (1 − d²/dx²)^{-1/2} has the kernel K₀(|x|)/π (K₀ the modified Bessel function:
// its Fourier transform is π (1 + ξ²)^{-1/2}); the Neumann kernel of [0, L] is its even,
// 2L-periodic image sum
//     π k_N(s, t) = Σ_{j∈ℤ} K₀(|s − t + 2jL|) + K₀(|s + t + 2jL|)
//                 = k₋(s − t) + k₊(s + t),
//     k₋(x) = K₀(|x|) + R₋(x),          R₋ = Σ_{j≠0} K₀(|x + 2jL|)          on [−L, L],
//     k₊(y) = K₀(y) + K₀(2L − y) + R₊(y), R₊ = Σ_{j∉{0,−1}} K₀(|y + 2jL|)  on [0, 2L].
// R₋ and R₊ are analytic on their intervals (Chebyshev fits to round-off); the log singularities
// of K₀ sit at x = 0 and y ∈ {0, 2L}. A block of two segments I, J becomes a one-dimensional
// integral of k₋ (k₊) against the cross-correlation (convolution) of the two Legendre bases,
// which is a piecewise polynomial in x (y); each piece is integrated by Gauss–Legendre on
// subintervals graded geometrically towards a singularity, so the result is exact up to the
// quadrature tolerance. The reference-space realization (h_minus_half_gram.hpp) converges to the
// same matrix from below (test InfSup.KernelGramIsTheLimitOfReferenceSpaces).
#pragma once

#include <Eigen/Core>

#include "space/multiplier_space.hpp"

namespace hpcontact::norms {

/// Quadrature resolution of the kernel realization: `level` 0 integrates to about 1e-8 relative,
/// each level adds Gauss points and grading layers (level 1: about 1e-14). The difference of two
/// levels is the error estimate of the coarser one.
struct KernelQuadrature {
  int level = 1;
};

/// Dense, symmetric positive definite, shape (n_multiplier_dofs, n_multiplier_dofs); each zone of
/// the boundary mesh is an arc [0, L_z] of its own, and G is block diagonal by zones.
/// @throws InputError for a closed zone (its kernel would be periodic; the extension norm serves).
Eigen::MatrixXd interpolation_norm_gram_kernel(const space::MultiplierSpace& multipliers,
                                               const KernelQuadrature& quadrature = {});

}  // namespace hpcontact::norms
