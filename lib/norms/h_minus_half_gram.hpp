// The H^{-1/2}(Γ_C) Gram matrix G of the multiplier space, in two realizations (DESIGN.md).
//
// Interpolation norm. H^{1/2}(Γ_C) = [L², H¹]_{1/2} (no boundary conditions at the ends of Γ_C),
// computed on a fine continuous reference space W on Γ_C. With M_W the mass matrix, K_W the
// stiffness + mass matrix of W, and K_W Φ = M_W Φ Λ, Φᵀ M_W Φ = I, the H^{1/2} norm of w ∈ W is
// ‖w‖² = wᵀ M_W Φ Λ^{1/2} Φᵀ M_W w and its dual norm over W gives
//     G = Cᵀ Φ Λ^{-1/2} Φᵀ C,     C_kj = ∫_{Γ_C} w_k μ_j ds.
//
// Two ways to apply Φ Λ^{-1/2} Φᵀ: the dense generalized eigendecomposition (O(n_W³), for small W),
// and, for large W, the integral  Φ Λ^{-1/2} Φᵀ = (2/π) ∫_0^∞ (K_W + t² M_W)⁻¹ dt  by the
// trapezoidal rule in s = log t (the scalar integrand is sech(s − ½ log λ) / (2√λ), analytic in a
// strip of half-width π/2, so step h gives an error near e^{-π²/h}), with the tails beyond the
// nodes in closed form (K_W⁻¹ below, M_W⁻¹ above). Each node is one sparse (banded) Cholesky
// solve with the columns of C; the tests check that both ways agree.
//
// Extension norm (Lemma 1 of the paper). ‖μ‖_{-1/2} = ‖u^μ‖₁ with u^μ ∈ H¹(Ω, Γ_D) solving
// (∇u^μ, ∇v) + (u^μ, v) = (μ, v)_{Γ_C}; on a refined reference space S_ref
//     G = B_ref A_ref⁻¹ B_refᵀ,   A_ref = K_ref + M_ref.
//
// Both are computed on reference spaces finer than the discretization; tests show that α no
// longer changes when the reference is refined further.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>

#include "mesh/contact_boundary.hpp"
#include "norms/primal_operators.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::norms {

/// W: continuous piecewise polynomials of degree `degree` on the common refinement of T_h|Γ_C
/// and T_{C,H}, every interval split into `subdivisions` equal parts.
struct InterpolationReference {
  int subdivisions = 2;
  /// 0: max p_C + 6. Finer references move α little: subdividing further by < 0.1 % (test
  /// InfSup.ReferenceSpacesAreFineEnough), degree 13 instead of p_C + 6 by ≤ 0.3 % on the stability grid.
  int degree = 0;
  /// W up to this dimension uses the dense eigendecomposition, larger W the quadrature.
  int dense_limit = 200;
  /// The quadrature's nodes split over the MPI ranks and summed (collective: every rank calls,
  /// as for a distributed factorization); the result is the same as on one rank, bit for bit.
  bool split_over_ranks = false;
};

/// Dense, symmetric positive definite, shape (n_multiplier_dofs, n_multiplier_dofs).
Eigen::MatrixXd interpolation_norm_gram(const mesh::ContactBoundary& contact,
                                        const space::MultiplierSpace& multipliers,
                                        const InterpolationReference& reference = {});

/// Cᵀ Φ Λ^{-1/2} Φᵀ C for the pencil A Φ = M Φ Λ (A, M symmetric positive definite, sparse), by the
/// dense eigendecomposition, or by the quadrature above given λ_max(A, M) ≤ lambda_max (and
/// λ_min ≥ 1, i.e. A − M positive semi-definite). Shape (c.cols(), c.cols()).
Eigen::MatrixXd inverse_sqrt_gram_dense(const Eigen::SparseMatrix<double>& a, const Eigen::SparseMatrix<double>& m,
                                        const Eigen::SparseMatrix<double>& c);
Eigen::MatrixXd inverse_sqrt_gram_quadrature(const Eigen::SparseMatrix<double>& a,
                                             const Eigen::SparseMatrix<double>& m,
                                             const Eigen::SparseMatrix<double>& c, double lambda_max,
                                             bool split_over_ranks = false);

/// The Gram matrix of `sub` from that of `envelope`, a multiplier space on the same segments with
/// degrees at least those of `sub`: the principal submatrix of the modes j ≤ p_C(k) of every
/// segment k (the Legendre basis is hierarchical, and both realizations are Gram matrices of the
/// basis functions in one inner product, fixed by the reference). Shape (sub.n_dofs(), sub.n_dofs()).
Eigen::MatrixXd restrict_gram(const Eigen::MatrixXd& envelope_gram, const space::MultiplierSpace& envelope,
                              const space::MultiplierSpace& sub);

/// S_ref: T_h refined uniformly `refinements` times, degree p_T + `extra_degree`.
struct ExtensionReference {
  int refinements = 1;
  int extra_degree = 2;
};

/// The extension norm's reference space S_ref with its K + M factorized, trace last: built once
/// per (T_h, p), it serves every multiplier space on Γ_C.
class ExtensionReferenceFactor {
 public:
  ExtensionReferenceFactor(const mesh::QuadMesh& mesh, const std::vector<int>& cell_degrees,
                           const ExtensionReference& reference);
  const PrimalOperators& operators() const { return *operators_; }

 private:
  std::unique_ptr<mesh::QuadMesh> fine_;
  std::unique_ptr<PrimalOperators> operators_;
};

/// Dense, symmetric positive definite, shape (n_multiplier_dofs, n_multiplier_dofs).
Eigen::MatrixXd extension_norm_gram(const ExtensionReferenceFactor& reference,
                                    const space::MultiplierSpace& multipliers);

/// The same, building the reference first. `cell_degrees` is the degree distribution on `mesh`.
Eigen::MatrixXd extension_norm_gram(const mesh::QuadMesh& mesh, const std::vector<int>& cell_degrees,
                                    const space::MultiplierSpace& multipliers,
                                    const ExtensionReference& reference = {});

}  // namespace hpcontact::norms
