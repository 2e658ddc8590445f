// Frictionless contact of an elastic body on a hexahedral mesh against a rigid obstacle across a
// flat Γ_C with outward normal n: the gap g is the distance to the obstacle along n, the multiplier
// the contact pressure P ≥ 0 on T_{C,H}, the traction on the body −P n:
//     [K    B_nᵀ] [u]   [F]        B_n,ij = ∫_{Γ_C} ℓ_i (φ_j · n),  G_i = ∫_{Γ_C} ℓ_i g,
//     [B_n  0   ] [P] ≤ [G]        P ≥ 0, B_n u ≤ G, Pᵀ(G − B_n u) = 0 at the nodal points.
// Condensed onto Γ_C as the scalar problems: min ½ Pᵀ S P − Pᵀ d over P ≥ 0, S = B_n K⁻¹ B_nᵀ,
// d = B_n K⁻¹ F − G, u = K⁻¹(F − B_nᵀ P).
// Tresca friction with threshold s adds the tangential multipliers t₁, t₂ along Γ_C's axes e₁, e₂
// (traction on the body −P n − t₁ e₁ − t₂ e₂): λ = (P; t₁; t₂), B = [B_n; B_1; B_2], and at every
// nodal point P ≥ 0 and |(t₁, t₂)| ≤ s, a disc (contact/disc_qp.hpp). Coulomb friction with
// coefficient F: the Tresca problems with s = F P at the nodal points, P that of the previous one.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <vector>

#include "assembly/material.hpp"
#include "assembly/solid_load.hpp"
#include "contact/box_qp.hpp"
#include "contact/inequality_qp.hpp"
#include "contact/qp_report.hpp"
#include "contact/solid_contact.hpp"
#include "linalg/coupling_matrix.hpp"
#include "linalg/distribution.hpp"
#include "space/solid_vector_space.hpp"
#include "space/surface_multiplier_space.hpp"

namespace hpcontact::contact {

struct SolidElasticSetup {
  const space::SolidVectorSpace* space = nullptr;
  const space::SurfaceMultiplierSpace* multipliers = nullptr;
  std::vector<assembly::Material> materials;          ///< one per cell
  std::array<assembly::SolidFunction, 3> body_force;  ///< f_x, f_y, f_z (empty: 0)
  assembly::SolidFunction gap;                        ///< g: u·n ≤ g on Γ_C
  assembly::SolidFunction threshold;                  ///< Tresca's s ≥ 0 (empty: frictionless or Coulomb)
  /// Coulomb's F ≥ 0 (in place of `threshold`): the discs' radii F P at the nodal points, by the
  /// fixed point s_{k+1} = F P(λ_k) from s_0 = 0 on Tresca problems
  std::optional<double> friction_coefficient;
  int max_fixed_point_iterations = 100;  ///< Coulomb
  double fixed_point_tolerance = 1e-10;  ///< Coulomb: on max |Δλ| / max |λ| between iterates
  BoxQpOptions qp;
  InequalityQpOptions interior_point;
  SchurPath trace_solve = SchurPath::automatic;  ///< S dense or by products (trace_operator.hpp)
  /// K factorized over these ranks (each eliminates its part of the box; every rank makes the same
  /// calls and receives the whole solution), or serial
  linalg::Distribution distribution;
};

struct SolidElasticSolution {
  Eigen::VectorXd u;         ///< coefficients on the vector space
  Eigen::VectorXd pressure;  ///< P at the nodal points of the multiplier space
  /// Tresca: t₁, t₂ at the nodal points (tangential tractions along e₁, e₂); zero without friction
  Eigen::VectorXd traction_1, traction_2;
  Eigen::VectorXd gap;  ///< (ℓ_i, g − u·n) = S P − d (the QP's gradient), ≥ 0
  double energy = 0.0;  ///< ½ a(u, u) − F(u)
  int n_trace = 0;
  QpReport qp;                              ///< the last QP's (Coulomb: of the last fixed-point iterate)
  std::vector<double> fixed_point_changes;  ///< Coulomb: max |Δλ| / max |λ| per iteration
  SolidSolveSeconds seconds;
};

/// F = ∫ f · φ_j of the setup's body force on its vector space (zero where f is not given).
Eigen::VectorXd solid_body_load(const SolidElasticSetup& setup);
/// B = B_n (`blocks` = 1), or [B_n; B_1; B_2] (3): the couplings of u·n, u·e₁, u·e₂ with the
/// multipliers.
linalg::Coupling stacked_coupling(const space::SolidVectorSpace& space,
                                  const space::SurfaceMultiplierSpace& multipliers, int blocks);

/// Frictionless, Tresca where `threshold` is given, Coulomb where `friction_coefficient` is.
/// @throws InputError for missing data, s < 0, F < 0 or both s and F; NumericalError if K is singular
/// (no Γ_D holds the body), the QP fails or Coulomb's fixed point does not converge.
SolidElasticSolution solve_solid_elastic_contact(const SolidElasticSetup& setup);

}  // namespace hpcontact::contact
