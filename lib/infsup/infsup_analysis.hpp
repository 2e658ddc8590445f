// The inf-sup constant α(h, H, p, p_C) of (11) or (22): α² = λ_min(S_G, G), with the spurious
// multiplier mode (the eigenvector), the indicator Π of (20), and an estimate of α's error from
// the H^{-1/2} reference.
//
// Error control. With G_ℓ the Gram matrix of reference level ℓ (norms/gram_ladder.hpp), α_ℓ is
// computed on level ℓ + 1 and compared with level ℓ through its own eigenvector x (xᵀG_{ℓ+1}x = 1):
//     α_ℓ² = min_y yᵀS_G y / yᵀG_ℓ y ≤ α_{ℓ+1}² / xᵀG_ℓ x,
// and G_ℓ ≤ G_{ℓ+1} gives α_ℓ ≥ α_{ℓ+1}, so  0 ≤ α_ℓ − α_{ℓ+1} ≤ α_{ℓ+1} (1/√(xᵀG_ℓx) − 1) =: e.
// e costs no second eigensolve. The levels converge geometrically (by a factor ≥ 4 per level,
// test InfSup.AlphaErrorBoundsTheChangeToTheNextReference), so e also bounds |α_{ℓ+1} − α_∞|; ℓ
// grows until e ≤ tolerance · α or the ladder ends.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "infsup/generalized_eigen.hpp"
#include "infsup/infsup_operators.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::infsup {

enum class EigenBackend { slepc, dense };
EigenBackend parse_eigen_backend(const std::string& text, const std::string& origin);

struct InfSupResult {
  double alpha = 0.0;       ///< sqrt(λ_min), ≥ 0
  double lambda_min = 0.0;  ///< α²
  double lambda_max = 0.0;  ///< largest eigenvalue of the same pencil
  /// α² ≤ kRoundOffZero · λ_max: S_G is singular to working precision, α = 0 numerically.
  bool singular = false;
  /// The eigenvector as Legendre coefficients of the whole multiplier (0 off supp s), xᵀGx = 1.
  Eigen::VectorXd mode;
  double pi = 0.0;  ///< Π(h, H, p, p_C), θ = 1
  double h = 0.0, H = 0.0;
  int n_primal_dofs = 0, n_multiplier_dofs = 0;  ///< the latter: functions of the multiplier family
  double alpha_error = 0.0;                      ///< estimate of |α − α_∞| from the reference (header)
  int reference_level = 0;                       ///< level of the ladder α was computed on
  /// alpha_error ≤ the setup's tolerance · α, on a ladder that converges geometrically (an
  /// extension-norm reference that cannot be graded makes alpha_error too low: false)
  bool alpha_converged = true;
  double seconds = 0.0;  ///< operators + eigenproblem
  double seconds_assembly = 0.0, seconds_primal = 0.0, seconds_gram = 0.0, seconds_eigen = 0.0;  ///< its parts
  std::string method;                                                                            ///< eigen solver used
  double residual = 0.0;  ///< relative eigen residual
  /// With several zones of Γ_C: α of each zone's multipliers alone (principal submatrices of S_G
  /// and G on the final reference, dense), each ≥ α; empty for one zone.
  std::vector<double> zone_alpha;
};

InfSupResult analyse_infsup(const InfSupSetup& setup, EigenBackend backend);

/// The smallest eigenpair of (S_G, Rᵀ diag(G_ℓ, …) R) (R = `basis`, `gram_copies` blocks) on the
/// ladder's levels ℓ = 1, 2, … until α's error estimate (header) is below `tolerance` · α, the
/// ladder stops converging geometrically or ends: the step every α takes, in 2-D and in 3-D.
/// Distributed, every rank takes the first rank's decision to stop.
struct LadderSolution {
  SmallestEigenpair pair;
  Eigen::MatrixXd gram;  ///< the pencil's G on the final level
  double alpha = 0.0, lambda_min = 0.0, alpha_error = 0.0;
  int reference_level = 0;
  bool alpha_converged = false;
  double seconds_eigen = 0.0;
};
LadderSolution smallest_on_ladder(const Eigen::MatrixXd& s_g, const Eigen::SparseMatrix<double>& basis, int gram_copies,
                                  const norms::GramLadder& grams, EigenBackend backend, double tolerance,
                                  linalg::Distribution distribution = {});

}  // namespace hpcontact::infsup
