// The multiplier families on the slave's Γ_C: subspaces of MultiplierSpace's discontinuous P_{p_C}
// on T_{C,H}, each given by the Legendre coefficients of its basis functions.
#pragma once

#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "space/multiplier_space.hpp"

namespace hpcontact::space {

/// discontinuous  the paper's M^{p_C}(T_{C,H}) itself (nodal basis at Chebyshev–Lobatto points);
/// standard       continuous piecewise P_{p_C}: the Lagrange basis at the p_C + 1 Gauss–Lobatto
///                points of each segment, the end points shared with the neighbours (standard
///                mortar with T_{C,H} the slave's trace mesh and p_C = p or p − 1);
/// dual           the biorthogonal basis of Wohlmuth (p_C = 1) and Lamichhane & Wohlmuth (any p_C
///                in one dimension): per segment ψ_i = Σ_j (D M⁻¹)_ij φ_j, with φ the standard
///                basis, M_ij = ∫ φ_i φ_j and D_ii = ∫ φ_i > 0 (Gauss–Lobatto weights), so that
///                ∫ ψ_i φ_j = δ_ij ∫ φ_j; ψ of a shared node is the sum of its pieces.
enum class MultiplierFamilyKind { discontinuous, standard, dual };

/// The end modification ("-modified"): at both ends of each open zone of Γ_C the end node's
/// function is dropped and the end segment's space lowered to P_{r−1} on its r remaining nodes
/// (Lagrange there, or the dual basis of that space against the remaining φ_j): for p_C = 1 the
/// multiplier is constant on the end segments, the usual crosspoint modification. Every family
/// reproduces constants.
struct MultiplierFamily {
  MultiplierFamilyKind kind = MultiplierFamilyKind::discontinuous;
  bool end_modification = false;  ///< standard and dual only
  bool operator==(const MultiplierFamily&) const = default;
};

/// "discontinuous", "standard", "standard-modified", "dual", "dual-modified".
std::string to_string(const MultiplierFamily& family);
/// Every family, in that order.
const std::vector<MultiplierFamily>& all_multiplier_families();
/// The family named `text` (to_string's names). @throws InputError naming `origin`, the key
/// `key` and the allowed names otherwise.
MultiplierFamily parse_multiplier_family(const std::string& text, const std::string& origin,
                                         const std::string& key = "family");

/// The basis of a continuous (standard) or dual family in the Legendre coefficients of
/// MultiplierSpace.
struct FamilyBasis {
  /// T, shape (multipliers.n_dofs(), n_functions): column i holds the Legendre coefficients of
  /// basis function i, so that a multiplier with family coefficients c has coefficients T c.
  Eigen::SparseMatrix<double> legendre;
  std::vector<double> node_s;  ///< arc length of each function's node (where its sign is imposed)
  /// The segments each function lives on (one or two; the node's segments).
  std::vector<std::vector<int>> segments;
  int n_functions() const { return static_cast<int>(node_s.size()); }
};

/// The number of multiplier functions of `family` on `multipliers`' T_{C,H}: its dofs for the
/// discontinuous family, the family basis's functions otherwise.
long long multiplier_function_count(const MultiplierSpace& multipliers, const MultiplierFamily& family);

/// @throws InputError if `family` is discontinuous (its basis is MultiplierSpace's own), if a
/// segment has p_C = 0 (the families are continuous or dual to a continuous space: p_C ≥ 1), or if
/// the end modification leaves a segment without a function (one segment of p_C = 1 in a zone).
FamilyBasis family_basis(const MultiplierSpace& multipliers, const MultiplierFamily& family);

}  // namespace hpcontact::space
