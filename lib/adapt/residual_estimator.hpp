// The residual a posteriori error estimator of the scalar contact problems (9), (13), (15): for a
// discrete saddle point (u_h, λ_H) of
//   −Δu = f in Ω,  ∂_n u = t on Γ_N,  ∂_n u = t − wλ on Γ_C  (w = s for (13), else 1),
// plus the constraint on λ and its complementarity, the indicator of a cell T of T_h is
//   η_T² = (h_T/p_T)² ‖f + Δu_h‖²_T                       volume residual
//        + ½ Σ_{E interior} (h_E/p_E) ‖[∂_n u_h]‖²_E         normal-derivative jumps (half to each side)
//        + Σ_{E ⊂ Γ_N ∪ Γ_C} (h_E/p_T) ‖∂_n u_h − t + wλ_H‖²_E      flux mismatch (λ_H = 0 off Γ_C)
//        + Σ_{E ⊂ Γ_C} contact terms:
//            (9)  (p_T/h_E)‖(g − u_h)⁺‖²_E + (h_E/p_T)‖λ_H⁺‖²_E + ∫_E (−λ_H)⁺ (u_h − g)⁺
//            (15) (h_E/p_T)‖(|λ_H| − s)⁺‖²_E + ∫_E (s|u_h| − λ_H u_h)⁺
//            (13) (h_E/p_T)‖s(|λ_H| − 1)⁺‖²_E + ∫_E s(|u_h| − λ_H u_h)⁺
// the gap and the bound violated between the constraint points (weighted as the H^{1/2} and
// H^{-1/2} norms scale on an edge of degree p) and the complementarity left over. η² = Σ_T η_T²
// estimates the squared energy norm of the error; η²/2 the error in the energy E(u_h).
#pragma once

#include <vector>

#include "contact/contact_problem.hpp"
#include "space/h1_space.hpp"

namespace hpcontact::adapt {

struct ResidualIndicators {
  std::vector<double> cell;  ///< η_T² per cell of T_h
  /// The four kinds of terms summed over T_h (their sum is η²).
  double volume = 0.0, jumps = 0.0, flux = 0.0, contact = 0.0;
  double squared() const { return volume + jumps + flux + contact; }
};

/// The indicators of `solution`, solved from `setup` on `space` (a whole, serial space with
/// straight or curved cells). The Laplacian of u_h is taken by central differences of its
/// gradient in reference coordinates (step 1e-5: truncation below 1e-9 of |∇²u_h| for the degrees
/// of T_h, round-off 1e-11), which works on every cell map without its second derivatives.
ResidualIndicators residual_indicators(const contact::ContactSetup& setup, const contact::ContactSolution& solution,
                                       const space::H1Space& space);

}  // namespace hpcontact::adapt
