// The matrices of the discrete inf-sup problem on S^p(T_h) × M^{p_C}(T_{C,H}):
//   α² = λ_min of  S_G x = λ G x,   S_G = B A_G⁻¹ Bᵀ,   A_G = K + M,
// with B the coupling (Signorini, (11)) or B^s (friction, (22); multipliers restricted to supp s)
// and G the H^{-1/2}(Γ_C) Gram matrix in one of two realizations (norms/gram_ladder.hpp).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "assembly/coupling.hpp"
#include "mesh/boundary_mesh.hpp"
#include "mesh/contact_pair_geometry.hpp"
#include "mesh/mesh.hpp"
#include "norms/gram_ladder.hpp"
#include "operators/elastic_operators.hpp"
#include "operators/primal_operators.hpp"
#include "space/multiplier_family.hpp"

namespace hpcontact::infsup {

enum class GramNorm { interpolation, extension };
enum class PairingProblem { signorini, friction };

GramNorm parse_gram_norm(const std::string& text, const std::string& origin);
PairingProblem parse_pairing_problem(const std::string& text, const std::string& origin);
std::string to_string(GramNorm norm);
std::string to_string(PairingProblem problem);

struct InfSupSetup {
  /// T_h whole: where own operators are built and, for the extension norm, what its references
  /// refine. May be null when `primal` or `elastic` is given and the norm is the interpolation norm
  /// (a distributed run frees it once its operators hold the rank's part), and on the ranks but the
  /// first of a distributed run in either norm (rank 0 alone holds it and refines the references).
  const mesh::Mesh* mesh = nullptr;
  std::vector<int> cell_degrees;  ///< p_T
  const mesh::BoundaryMesh* boundary_mesh = nullptr;
  std::vector<int> segment_degrees;  ///< p_C per segment
  /// The multiplier family on T_{C,H} (space/multiplier_family.hpp): the pencil is restricted to
  /// its functions.
  space::MultiplierFamily family;
  GramNorm norm = GramNorm::interpolation;
  PairingProblem problem = PairingProblem::signorini;
  assembly::CouplingWeight friction_bound;  ///< s, required for the friction problem
  /// α is refined on the reference ladder until its estimated error is below this fraction of α.
  double alpha_tolerance = 1e-4;
  // Optional parts shared with other computations (built here when absent): a contact solve on the
  // same T_h, or the points of a sweep. They must belong to this setup: `primal` to (mesh,
  // cell_degrees), `grams` to (boundary_mesh, segment_degrees, norm).
  const operators::PrimalOperators* primal = nullptr;
  const norms::GramLadder* grams = nullptr;
  /// Elasticity (when given; `primal` is then unused and s is not needed): the pairing of the
  /// normal multiplier with u·n (problem signorini), or of the normal and the tangential
  /// multipliers with (u·n, u·t) (problem friction: λ = (λ_n; λ_t), G = diag(G, G)), on
  /// [S^p(T_h)]² in `primal_norm`. Must belong to (mesh, cell_degrees).
  const operators::ElasticOperators* elastic = nullptr;
  operators::PrimalNorm primal_norm = operators::PrimalNorm::h1;
  /// A contact pair of two elastic bodies (when given, with `elastic` the slave's operators, whose
  /// Γ_C carries T_{C,H}): the master's operators and Φ onto its Γ_C. The pairing is then
  /// b(μ, v) = ∫ μ (v_s − v_m∘Φ)·n_s (and ·t_s) on V_s × V_m in the primal norm of both bodies, so
  /// that S_G = B_s A_{G,s}⁻¹ B_sᵀ + B_m A_{G,m}⁻¹ B_mᵀ.
  const operators::ElasticOperators* master = nullptr;
  const mesh::MasterProjection* projection = nullptr;
};

struct InfSupOperators {
  Eigen::MatrixXd s_g;  ///< Rᵀ B A_G⁻¹ Bᵀ R on the active multiplier functions R, (n_active, n_active)
  /// R: the active multiplier functions as Legendre coefficients of the whole multiplier
  /// (gram_copies × dofs of M^{p_C}(T_{C,H}) rows), one column each: the family's basis functions
  /// (the Legendre modes themselves for the discontinuous family), all of them for Signorini, those
  /// whose segments meet supp s for friction.
  Eigen::SparseMatrix<double> basis;
  int n_primal_dofs = 0;
  int n_multiplier_dofs = 0;      ///< of the whole multiplier: gram_copies × functions of the family
  int gram_copies = 1;            ///< G of the pairing = diag(G, …) with this many copies
  double h = 0.0;                 ///< longest edge of T_h
  int smallest_p = 0;             ///< smallest p_T of T_h
  double H = 0.0;                 ///< longest segment of T_{C,H}
  double seconds_assembly = 0.0;  ///< what this call assembled of S^p(T_h), K, M, B
  double seconds_primal = 0.0;    ///< what this call factorized of A_G (trace last), and S_G
  OperatorLog* log = nullptr;     ///< the primal operators' log, if any
};

/// S_G and the active multipliers (G comes from the ladder: infsup_analysis.hpp).
/// @throws InputError on inconsistent setups (no friction bound, s ≡ 0 on Γ_C, ...).
InfSupOperators assemble_infsup_operators(const InfSupSetup& setup);

/// Rᵀ `matrix` R for R = `basis` (a square `matrix` in the Legendre coefficients of the whole
/// multiplier); `matrix` itself when R is the identity.
Eigen::MatrixXd restrict(const Eigen::MatrixXd& matrix, const Eigen::SparseMatrix<double>& basis);

/// diag(g, …, g) with `copies` blocks.
Eigen::MatrixXd block_copies(const Eigen::MatrixXd& g, int copies);

/// Π(h, H, p, p_C) = h H⁻¹ max(1, p_C)² p⁻¹ of (20) with θ = 1; for degree distributions the
/// worst case (largest p_C, smallest p).
double stability_indicator(double h, double H, int min_p, int max_pc);

}  // namespace hpcontact::infsup
