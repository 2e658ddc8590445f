// The residual a posteriori error estimator of elastic contact against a rigid obstacle
// (frictionless, Tresca, Coulomb, tied): for a discrete saddle point (u_h, p_H, τ_H) of
//   −div σ(u) = f in Ω,  σn = t on Γ_N,  σn = −p n + τ t on Γ_C
// (p the contact pressure, τ = σ_nt the tangential traction along increasing arc length) plus
// the contact conditions, the indicator of a cell T of T_h is, with 2μ_T its shear stiffness,
//   η_T² = (h_T/p_T)² ‖f + div σ(u_h)‖²_T / 2μ_T                           volume residual
//        + ½ Σ_{E interior} (h_E/p_E) ‖[σ(u_h)n]‖²_E / 2μ_T                traction jumps
//        + Σ_{E ⊂ Γ_N ∪ Γ_C} (h_E/p_T) ‖σ(u_h)n − t‖²_E / 2μ_T              traction mismatch
//              (t = −p_H n + τ_H t on Γ_C; a component a roller fixes is left out)
//        + Σ_{E ⊂ Γ_C} contact terms:
//            2μ_T (p_T/h_E) ‖(u_h·n − g)⁺‖²_E + (h_E/p_T) ‖p_H⁻‖²_E / 2μ_T + ∫_E p_H⁺ (g − u_h·n)⁺
//            with friction (s given, or F p_H⁺ for Coulomb), in addition
//            (h_E/p_T) ‖(|τ_H| − s)⁺‖²_E / 2μ_T + ∫_E (s|u_h·t| + τ_H u_h·t)⁺
//            tied: 2μ_T (p_T/h_E) (‖u_h·n − g‖²_E + ‖u_h·t‖²_E) instead
// the scalar estimator's terms (adapt/residual_estimator.hpp) with the stress for the flux and the
// material's stiffness making every term an energy. η² estimates a(e, e); η²/2 the error in the
// energy ½ a(u_h, u_h) − F(u_h).
#pragma once

#include <array>
#include <vector>

#include "adapt/residual_estimator.hpp"
#include "contact/elastic_contact.hpp"

namespace hpcontact::adapt {

/// The indicators of `solution`, solved from `setup` (a whole, serial space). `fixed` as the
/// rollers of operators::ElasticOperators: the components they fix have no traction residual on
/// their edges (the reaction there is unknown).
ResidualIndicators elastic_residual_indicators(const contact::ElasticContactSetup& setup,
                                               const contact::ElasticContactSolution& solution,
                                               const std::array<std::vector<char>, space::kComponents>& fixed = {});

}  // namespace hpcontact::adapt
