// The interpolation-norm Gram matrix of the multipliers on a flat rectangular Γ_C (3-D), by the
// fractional power of the surface Laplacian in its own eigenbasis.
//
// H^{1/2}(Γ_C) = [L², H¹]_{1/2} on the rectangle R = [0, L₁] × [0, L₂] (no boundary conditions on
// its sides) is the Hilbert scale of T = I − Δ with natural (Neumann) conditions, whose
// eigenfunctions are the cosine products φ_{jk}(a) = c_j(a₁) c_k(a₂), c_0 = 1/√L, c_j =
// √(2/L) cos(jπa/L), with eigenvalues 1 + (jπ/L₁)² + (kπ/L₂)². So the dual norm is
//     ‖μ‖²_{-1/2} = (μ, T^{-1/2} μ) = Σ_{j,k} (μ, φ_{jk})² (1 + (jπ/L₁)² + (kπ/L₂)²)^{-1/2}.
// T_{C,H} is a tensor grid and its multipliers tensor Lagrange polynomials, so (ℓ_i, φ_{jk})
// factors into one-dimensional moments, and G is two matrix products of the moments.
// Truncating the sum at j < N₁, k < N₂ drops positive terms only: the truncations increase
// towards G (the ladder's levels double N and are ordered, as norms/gram_ladder.hpp asks), and a
// piecewise polynomial with jumps has moments O(1/j), so the dropped part decays like 1/N²
// (a factor 4 per level).
#pragma once

#include <Eigen/Core>
#include <array>

#include "norms/gram_ladder.hpp"
#include "space/surface_multiplier_space.hpp"

namespace hpcontact::norms {

/// How the double sum over the modes is evaluated: directly (two matrix products, a cost of the
/// modes' product), or with the weights (1 + (jπ/L₁)² + (kπ/L₂)²)^{-1/2} as a sum of about 250
/// exponentials e^{-s(1 + ...)}, each a product of one factor per axis, so that G is a sum of
/// Kronecker products of one-dimensional matrices (a cost linear in the modes; relative error
/// 1e-13 in every weight, hence in G); `cheaper` takes the one with fewer operations.
enum class GramSummation { cheaper, direct, exponential_sum };

/// G with the cosine modes j < modes[0], k < modes[1]: dense, symmetric positive semi-definite
/// (definite once the modes outnumber the multipliers along each axis), shape (n_dofs, n_dofs)
/// in the multipliers' own numbering.
Eigen::MatrixXd surface_interpolation_gram(const space::SurfaceMultiplierSpace& multipliers, std::array<int, 2> modes,
                                           GramSummation summation = GramSummation::cheaper);

/// The ladder's levels: ℓ = 0 … kSurfaceGramTopLevel, level ℓ keeping 8 · 2^ℓ cosine modes per
/// multiplier function along each axis ((p_C + 1) m_k functions along axis k).
inline constexpr int kSurfaceGramTopLevel = 5;
std::array<int, 2> surface_gram_modes(const space::SurfaceMultiplierSpace& multipliers, int level);

/// G on the levels of surface_gram_modes. `multipliers` must outlive the ladder.
GramLadder surface_interpolation_gram_ladder(const space::SurfaceMultiplierSpace& multipliers);

}  // namespace hpcontact::norms
