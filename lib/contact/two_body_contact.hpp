// Contact between two elastic bodies meshed independently (small deformation): the multiplier
// λ = (σ_nn, −σ_nt) lives on T_{C,H} of the slave's Γ_C and pairs with the jump of the traces,
//   b(μ, v) = ∫_{Γ_C^s} μ (v_s − v_m∘Φ)·n_s   (and ·t_s for friction),
// Φ the closest point on the master's Γ_C and the gap g = (Φ(x) − x)·n_s in the reference
// configuration (mesh::MasterProjection). Frictionless, Tresca and Coulomb as for one body
// (elastic_contact.hpp), on the same condensed trace solver with C = [C_s, −C_m]: the slave's
// traces by its own coupling, the master's by the mortar coupling (assembly/mortar_coupling.hpp).
#pragma once

#include "contact/elastic_contact.hpp"
#include "contact/elastic_trace_solver.hpp"

namespace hpcontact::contact {

struct TwoBodyContactSetup {
  /// The slave body (its operators, loads and Dirichlet data), T_{C,H} on its Γ_C, the problem and
  /// the multiplier's data and solver options. Its gap must be empty: the gap is the geometric one.
  ElasticContactSetup slave;
  ElasticBody master;  ///< its operators' Γ_C is the master boundary
};

struct TwoBodyContactSolution {
  /// The multiplier (the traction on the slave) and its KKT data, the slave's displacement, the
  /// energy of both bodies.
  ElasticContactSolution contact;
  BodyDisplacement master;
};

/// @throws InputError for missing data, a master Γ_C that does not cover the slave's everywhere
/// (not supported yet), distributed operators (two bodies run serially), and as
/// solve_elastic_contact; NumericalError as solve_elastic_contact.
TwoBodyContactSolution solve_two_body_contact(const TwoBodyContactSetup& setup);

}  // namespace hpcontact::contact
