// The H^{-1/2}(Γ_C) Gram matrix G of the multiplier space, in two realizations (docs/mathematics.md).
//
// Interpolation norm. H^{1/2}(Γ_C) = [L², H¹]_{1/2} (no boundary conditions at the ends of Γ_C).
// The toolkit computes it from its kernel (interpolation_norm_kernel.hpp); here, as the
// independent check, on a continuous reference space W on Γ_C: with M_W the mass matrix, K_W the
// stiffness + mass matrix of W, and K_W Φ = M_W Φ Λ, Φᵀ M_W Φ = I, the H^{1/2} norm of w ∈ W is
// ‖w‖² = wᵀ M_W Φ Λ^{1/2} Φᵀ M_W w and its dual norm over W gives
//     G_W = Cᵀ Φ Λ^{-1/2} Φᵀ C,     C_kj = ∫_{Γ_C} w_k μ_j ds,
// by a dense generalized eigendecomposition. G_W ≤ G, and G − G_W falls like the square of W's
// interval length only (the Riesz representative of a discontinuous μ has x log|x| kinks), which
// is why W is not the production path: 16 subdivisions of degree p_C + 12 still leave 3e-6.
//
// Extension norm (Lemma 1 of the paper). ‖μ‖_{-1/2} = ‖u^μ‖₁ with u^μ ∈ H¹(Ω, Γ_D) solving
// (∇u^μ, ∇v) + (u^μ, v) = (μ, v)_{Γ_C}; on a reference space S_ref finer than the discretization
//     G = B_ref A_ref⁻¹ B_refᵀ,   A_ref = K_ref + M_ref.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>

#include "mesh/contact_boundary.hpp"
#include "operators/primal_operators.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::norms {

/// W: continuous piecewise polynomials of degree `degree` on the common refinement of T_h|Γ_C
/// and T_{C,H}, every interval split into `subdivisions` equal parts.
struct InterpolationReference {
  int subdivisions = 2;
  int degree = 0;  ///< 0: max p_C + 6
};

/// G_W, dense, symmetric positive definite, shape (n_multiplier_dofs, n_multiplier_dofs).
Eigen::MatrixXd interpolation_norm_gram_on_reference(const mesh::ContactBoundary& contact,
                                                     const space::MultiplierSpace& multipliers,
                                                     const InterpolationReference& reference = {});

/// The Gram matrix of `sub` from that of `envelope`, a multiplier space on the same segments with
/// degrees at least those of `sub`: the principal submatrix of the modes j ≤ p_C(k) of every
/// segment k (the Legendre basis is hierarchical, and both realizations are Gram matrices of the
/// basis functions in one inner product, fixed by the reference). Shape (sub.n_dofs(), sub.n_dofs()).
Eigen::MatrixXd restrict_gram(const Eigen::MatrixXd& envelope_gram, const space::MultiplierSpace& envelope,
                              const space::MultiplierSpace& sub);

/// S_ref: T_h refined uniformly `refinements` times (its cells on Γ_C cut, or the whole mesh
/// refined, where the grading points need it), then graded geometrically (`layers` layers of ratio
/// `grading`) towards the grading points on Γ_C and towards the singular points of ∂Ω (vertices where
/// the boundary condition changes or the boundary turns by more than 30°). u^μ of a piecewise polynomial μ has an
/// r log r singularity at every jump of μ, so the grading points are the breakpoints of T_{C,H}; it
/// has an r^{1/2} singularity where Γ_D meets Γ_N on a straight side (the §7 square's (1, 0)), which
/// ungraded held α up to 5e-5 high for smooth weakest modes and converged only algebraically. On
/// a uniform refinement α converged like h_ref², on the graded one geometrically.
/// Degrees: p_T + `extra_degree` in the cells at Γ_C (a vertex on it) and in the stars of the
/// singular points; max(1, p_T − 3) + `far_extra_degree` elsewhere, where u^μ is smooth: the far
/// cells' degree moves α by 1e-9 at n = 128, p = 4 (p_T − 3 against p_T + 2) and costs most of the
/// reference's unknowns.
struct ExtensionReference {
  int refinements = 1;
  int layers = 0;
  double grading = 0.2;
  int extra_degree = 2;
  int far_extra_degree = 0;
};

/// The reference of resolution `level` (0, 1, …) of the sequence that error-controlled α walks.
ExtensionReference extension_reference_at(int level);

/// The extension norm's reference space S_ref with its K + M factorized, trace last: built once
/// per (T_h, p, grading points), it serves every multiplier space on Γ_C with those breakpoints.
class ExtensionReferenceFactor {
 public:
  /// `grading_points`: arc lengths on Γ_C of `mesh`. `distribution`: K + M factorized over its
  /// ranks (the first builds S_ref's mesh whole and sends each rank its part, and all make the same
  /// calls; `mesh` and `cell_degrees` are read on the first rank only, the others may pass null
  /// and nothing), or serial.
  /// `n_multipliers`: the rows of the couplings its Schur complements will take (it decides,
  /// serially, whether the trace is ordered last: trace_ordering_for; 0, unknown: by solves).
  ExtensionReferenceFactor(const mesh::Mesh* mesh, const std::vector<int>& cell_degrees,
                           const ExtensionReference& reference, const std::vector<double>& grading_points = {},
                           linalg::Distribution distribution = {}, int n_multipliers = 0);
  const operators::PrimalOperators& operators() const { return *operators_; }
  /// Whether S_ref is graded towards every grading point (they are vertices of T_h refined at most
  /// twice more, with disjoint stars). Without it α converges algebraically, slowly, and the
  /// difference of two levels no longer bounds the error.
  bool graded() const { return graded_; }

 private:
  /// Refines fine_ (T_h at first) into S_ref's mesh, `degrees` with it, and finds graded_.
  void refine_reference(const ExtensionReference& reference, const std::vector<double>& grading_points,
                        std::vector<int>& degrees);
  /// Adds to `centres` the singular points of ∂Ω (not yet among them) and marks their stars `near`;
  /// clears graded_ where a star would share a cell with another.
  void add_singular_points(std::vector<int>& centres, std::vector<char>& near);

  bool graded_ = false;
  /// S_ref's mesh, whole; distributed, on the first rank only, and freed once the operators hold their part.
  std::unique_ptr<mesh::Mesh> fine_;
  std::unique_ptr<operators::PrimalOperators> operators_;
};

/// How a reference with `n_unknowns` unknowns and `n_trace` of them on Γ_C is best factorized for
/// Schur complements with `n_multipliers` rows: the trace last costs about n_trace³/3 of dense
/// factorization beyond the sparse one, solves about one sweep pair through the factor per multiplier.
/// Measured on the 55 references of the stability grid (one thread, 0.1 … 28 s each) the trace
/// last wins while n_trace³ ≤ 400 · n_multipliers · n_unknowns, and loses by 4× at the graded
/// references of n = 60, p = 8 (10 081 trace unknowns: 28 s against 7.4 s).
operators::PrimalOperators::TraceOrdering trace_ordering_for(long long n_unknowns, long long n_trace,
                                                             long long n_multipliers);

/// Dense, symmetric positive definite, shape (n_multiplier_dofs, n_multiplier_dofs).
Eigen::MatrixXd extension_norm_gram(const ExtensionReferenceFactor& reference,
                                    const space::MultiplierSpace& multipliers);

/// The same, building the reference first, graded towards the breakpoints of `multipliers`.
/// `cell_degrees` is the degree distribution on `mesh`. `graded`, if given, receives
/// ExtensionReferenceFactor::graded(). `mesh` as there.
Eigen::MatrixXd extension_norm_gram(const mesh::Mesh* mesh, const std::vector<int>& cell_degrees,
                                    const space::MultiplierSpace& multipliers, const ExtensionReference& reference,
                                    bool* graded = nullptr, linalg::Distribution distribution = {});

}  // namespace hpcontact::norms
