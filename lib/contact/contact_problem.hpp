// The paper's discrete contact problems on S^p(T_h) × M^{p_C}(T_{C,H}), condensed onto Γ_C:
//   (9)  simplified Signorini   λ ∈ M_-:  μ ≤ 0,             pairing (μ, γ_C v),   obstacle g
//   (13) idealized friction     λ ∈ M_1:  |μ| ≤ 1 on supp s,  pairing (μ, s γ_C v)
//   (15) alternative friction   λ ∈ M_s:  |μ| ≤ s,            pairing (μ, γ_C v)
// With u = K⁻¹(F − Bᵀλ) the multiplier solves  min ½ λᵀ S λ − λᵀ d  over the constraint set,
// S = B K⁻¹ Bᵀ, d = B K⁻¹ F − g (g = 0 for friction). The multiplier uses a Lagrange basis at
// q = p_C + 1 points per segment (Remark 3: Chebyshev–Lobatto points; for p_C ≤ 1 the end points
// or the midpoint, which makes the sign and box conditions exact), so the constraints are bounds.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "contact/box_qp.hpp"
#include "mesh/boundary_mesh.hpp"
#include "mesh/quad_mesh.hpp"

namespace hpcontact::contact {

enum class ContactProblem { signorini, friction, friction_s };

/// Constraint points of Remark 3 on [-1,1]: q Chebyshev–Lobatto points −cos(πk/(q−1)),
/// or the midpoint for q = 1.
std::vector<double> constraint_points(int q);

using PointFunction = std::function<double(const mesh::Point&)>;

struct ContactSetup {
  const mesh::QuadMesh* mesh = nullptr;
  std::vector<int> cell_degrees;
  const mesh::BoundaryMesh* boundary_mesh = nullptr;
  std::vector<int> segment_degrees;
  ContactProblem problem = ContactProblem::signorini;
  PointFunction f;          ///< volume load
  PointFunction obstacle;   ///< g, Signorini only
  PointFunction bound;      ///< s, friction problems only (s ≥ 0)
  /// Optional boundary traction t(x, n) on Γ_N and Γ_C, added to the load as ∫ t v ds (Neumann
  /// data; on Γ_C a prescribed traction besides the contact force, used by manufactured tests).
  std::function<double(const mesh::Point& x, const mesh::Point& normal)> traction;
  BoxQpOptions qp;
};

struct ContactSolution {
  Eigen::VectorXd u;                 ///< coefficients on S^p(T_h)
  /// λ in the Lagrange basis: its values at the constraint points, segment by segment.
  Eigen::VectorXd lambda;
  /// The same λ in the Legendre basis of MultiplierSpace (for evaluation anywhere on Γ_C).
  Eigen::VectorXd lambda_legendre;
  std::vector<double> constraint_s;  ///< arc length of each constraint point
  Eigen::VectorXd lower, upper;      ///< the bounds on lambda
  /// (ℓ_i, γ_C u − g) for Signorini, (ℓ_i, s γ_C u) or (ℓ_i, γ_C u) for friction: the dual
  /// gradient −(Sλ − d), whose sign the KKT conditions fix.
  Eigen::VectorXd gap;
  double energy = 0.0;               ///< E(u) = ½ uᵀKu − Fᵀu
  BoxQpResult qp;
  double seconds_setup = 0.0, seconds_qp = 0.0;
};

/// @throws InputError for missing data or s < 0; NumericalError if the QP does not converge.
ContactSolution solve_contact(const ContactSetup& setup);

}  // namespace hpcontact::contact
