// The constraints of the discrete multiplier in a nodal basis (Remark 3): per segment of T_{C,H},
// the Lagrange basis at p_C + 1 Chebyshev–Lobatto points, the constraint rows at |𝒞| points and
// the bounds of M_- (9), M_1 (13) or M_s (15) there. For a standard or dual family
// (space/multiplier_family.hpp) the family's basis, with the bounds on its coefficients.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "contact/contact_problem.hpp"
#include "mesh/contact_boundary.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::contact {

struct MultiplierConstraints {
  /// Block diagonal V⁻ᵀ, V_ik = P_k(τ_i): c_nodal = V c_legendre, B_nodal = V⁻ᵀ B_legendre. For a
  /// standard or dual family Tᵀ (FamilyBasis::legendre), shape (functions, Legendre dofs):
  /// c_legendre = to_nodalᵀ c always.
  Eigen::MatrixXd to_nodal;
  Eigen::MatrixXd matrix;               ///< C (rows: constraint points, columns: nodal coefficients)
  Eigen::VectorXd lower, upper;         ///< lo ≤ C λ ≤ hi
  std::vector<double> s;                ///< arc length of each constraint point
  std::vector<int> points_per_segment;  ///< discontinuous family only
  /// C = I: every segment uses its nodal points, so the bounds act on the coefficients.
  bool bounds_only = true;
};

/// @throws InputError if s < 0 (or not finite) at a constraint point, or the constraint points
/// are fewer than p_C + 1, or are given for a standard or dual family; as space::family_basis.
MultiplierConstraints build_multiplier_constraints(const ContactSetup& setup, const space::MultiplierSpace& multipliers,
                                                   const mesh::ContactBoundary& contact);

}  // namespace hpcontact::contact
