// Contact of an elastic body with a rigid obstacle, on [S^p(T_h)]² × M^{p_C}(T_{C,H}) (normal, and
// with friction tangential, multipliers; both in one family on T_{C,H}, the paper's discontinuous
// P_{p_C} by default), condensed onto Γ_C as the scalar problems are:
//   frictionless  u·n ≤ g,  σ_nn ≤ 0,  σ_nn (u·n − g) = 0,  σ_nt = 0
//   Tresca        the same, and |σ_nt| ≤ s, σ_nt u_t ≤ 0 where slipping (s given, ≥ 0)
//   Coulomb       Tresca with s = F |σ_nn|, by a fixed point on the Tresca problem
//   tied          u·n = g, u·t = 0 (no bound on λ)
// With λ = (σ_nn, −σ_nt) in the nodal basis at the Chebyshev–Lobatto points of each segment (or
// the family's basis),
// B = (−B_n; B_t) and A u = F − Bᵀ λ, the multiplier solves
//     min ½ λᵀ S λ − dᵀ λ   over   σ_nn ≤ 0 and |σ_nt| ≤ s at the constraint points (Remark 3),
// S = B A⁻¹ Bᵀ, d = B A⁻¹ F + (ℓ_i, g; 0): the problem of contact_problem.hpp with M_- for the
// normal part and M_s for the tangential one, so the same QP methods solve it.
#pragma once

#include <Eigen/Core>
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "assembly/dirichlet_lift.hpp"
#include "assembly/elastic_load.hpp"
#include "contact/contact_problem.hpp"
#include "operators/elastic_operators.hpp"

namespace hpcontact::contact {

/// tied: the bodies bonded, (u_s − u_m∘Φ)·n = g and (u_s − u_m∘Φ)·t = 0 on Γ_C (against a rigid
/// obstacle u·n = g, u·t = 0): the linear special case, λ = (σ_nn, −σ_nt) of either sign.
enum class ElasticContactProblem { frictionless, tresca, coulomb, tied };

/// The effect names: "frictionless", "tresca", "coulomb", "tied".
std::string to_string(ElasticContactProblem problem);

struct ElasticContactSetup {
  const operators::ElasticOperators* operators = nullptr;  ///< required; its log records what is built
  const mesh::BoundaryMesh* boundary_mesh = nullptr;       ///< T_{C,H}
  std::vector<int> segment_degrees;                        ///< p_C per segment
  space::MultiplierFamily family;                          ///< as ContactSetup::family
  ElasticContactProblem problem = ElasticContactProblem::frictionless;
  assembly::VectorFunction body_force;  ///< f (may be empty)
  assembly::TractionFunction traction;  ///< t on Γ_N (may be empty)
  /// Dirichlet data u_D,x and u_D,y wherever the component is fixed (Γ_D, rollers); empty: 0.
  std::array<PointFunction, space::kComponents> dirichlet;
  /// g: the gap between Γ_C and the obstacle along n in the undeformed state; u·n ≤ g.
  PointFunction gap;
  PointFunction threshold;            ///< s ≥ 0, Tresca only
  double friction_coefficient = 0.0;  ///< F ≥ 0, Coulomb only
  /// |𝒞| per segment where Remark 3 applies: one value, or one per zone of T_{C,H}; empty: p_C + 1.
  std::vector<int> constraint_points;
  BoxQpOptions qp;
  InequalityQpOptions interior_point;
  int max_fixed_point_iterations = 100;  ///< Coulomb
  double fixed_point_tolerance = 1e-10;  ///< Coulomb: on max |Δλ| / max |λ| between iterates
};

struct ElasticContactSolution {
  /// Displacement numbered by space::VectorSpace::dof: u itself, or with Dirichlet data u_0, where
  /// u = u_0 + w. At the rows of u_rows, as ContactSolution::u.
  Eigen::VectorXd u;
  assembly::LocalRows u_rows;
  int n_dofs = 0;  ///< unknowns of u in all (of the global numbering)
  /// The lift w of the Dirichlet data (null without them); assembly::scalar_field / vector_field read u.
  std::shared_ptr<const assembly::DirichletLift> lift;
  /// Contact pressure p = −σ_nn ≥ 0 and tangential traction σ_nt on the body (along the tangent
  /// of increasing arc length), Legendre coefficients in M^{p_C}(T_{C,H}); σ_nt = 0 without friction.
  Eigen::VectorXd pressure, shear;
  /// The multiplier λ in the nodal basis (the family's basis for a standard or dual family; normal
  /// part, then tangential part with friction), the constraint rows and the gap d − S λ: the KKT
  /// data at the constraint points (the family's nodes).
  Eigen::VectorXd lambda;
  Eigen::MatrixXd constraint_matrix;
  Eigen::VectorXd lower, upper, gap;
  int n_normal = 0;  ///< rows of λ (and of gap) that belong to the normal part
  /// ‖B u_free‖_∞ + ‖offset‖_∞ + ‖S λ‖_∞: the size of the terms whose sum is the gap, against
  /// which a gap is small (as ContactSolution::gap_scale).
  double gap_scale = 0.0;
  double energy = 0.0;  ///< ½ a(u, u) − F(u) of the whole u
  QpReport qp;          ///< the last QP solved
  /// Coulomb: fixed-point iterations and max |Δλ| / max |λ| after each; empty otherwise.
  std::vector<double> fixed_point_changes;
  int n_trace = 0;
  struct Seconds {
    double assembly = 0.0, factorization = 0.0, condensation = 0.0, qp = 0.0, recovery = 0.0;
  } seconds;
};

/// @throws InputError for missing or invalid data; NumericalError if a QP or the Coulomb fixed
/// point does not converge (naming its iterations and last change).
ElasticContactSolution solve_elastic_contact(const ElasticContactSetup& setup);

}  // namespace hpcontact::contact
