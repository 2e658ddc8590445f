// The paper's discrete contact problems on S^p(T_h) × M^{p_C}(T_{C,H}), condensed onto Γ_C:
//   (9)  simplified Signorini   λ ∈ M_-:  μ ≤ 0,             pairing (μ, γ_C v),   obstacle g
//   (13) idealized friction     λ ∈ M_1:  |μ| ≤ 1 on supp s,  pairing (μ, s γ_C v)
//   (15) alternative friction   λ ∈ M_s:  |μ| ≤ s,            pairing (μ, γ_C v)
// With u = K⁻¹(F − Bᵀλ) the multiplier solves  min ½ λᵀ S λ − λᵀ d  over the constraint set,
// S = B K⁻¹ Bᵀ, d = B K⁻¹ F − g (g = 0 for friction). The multiplier uses a Lagrange basis at the
// p_C + 1 Chebyshev–Lobatto points of each segment (end points for p_C = 1, midpoint for p_C = 0).
// Constraint points (Remark 3): for M_- and M_1 with p_C ≤ 1 the nodal points themselves, which
// makes the sign and box conditions exact; otherwise q ≥ p_C + 1 Chebyshev–Lobatto points per
// segment (default q = p_C + 1). When every segment uses its nodal points the constraints are
// bounds on the coefficients (active-set method, box_qp.hpp); more points give general linear
// inequalities lo ≤ C λ ≤ hi (interior-point method, inequality_qp.hpp).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "assembly/dirichlet_lift.hpp"
#include "assembly/local_rows.hpp"
#include "contact/box_qp.hpp"
#include "contact/inequality_qp.hpp"
#include "contact/qp_report.hpp"
#include "mesh/boundary_mesh.hpp"
#include "mesh/mesh.hpp"
#include "operators/primal_operators.hpp"
#include "space/multiplier_family.hpp"

namespace hpcontact::contact {

enum class ContactProblem { signorini, friction, friction_s };

/// Constraint points of Remark 3 on [-1,1]: q Chebyshev–Lobatto points −cos(πk/(q−1)),
/// or the midpoint for q = 1.
std::vector<double> constraint_points(int q);

/// |𝒞| on a segment of degree p_C: p_C + 1 where the nodal points make the constraint exact (M_-,
/// M_1 with p_C ≤ 1), else `requested` or p_C + 1. @throws InputError if requested < p_C + 1.
int segment_constraint_points(ContactProblem problem, int pc, std::optional<int> requested);

/// The |𝒞| requested for segment `segment` of T_{C,H} from a list holding one value for every
/// segment or one per zone of T_{C,H}; empty: nothing requested (p_C + 1).
/// @throws InputError if the list has another length.
std::optional<int> requested_constraint_points(const std::vector<int>& per_zone,
                                               const mesh::BoundaryMesh& boundary_mesh, int segment);

using PointFunction = std::function<double(const mesh::Point&)>;

struct ContactSetup {
  /// T_h whole: where `primal` is built when absent. May be null when `primal` is given (a
  /// distributed run frees it once its operators hold the rank's part).
  const mesh::Mesh* mesh = nullptr;
  std::vector<int> cell_degrees;
  const mesh::BoundaryMesh* boundary_mesh = nullptr;
  std::vector<int> segment_degrees;
  /// The multiplier family on T_{C,H}: the paper's discontinuous one, or a standard or dual basis
  /// (space/multiplier_family.hpp), whose constraints act on its coefficients.
  space::MultiplierFamily family;
  ContactProblem problem = ContactProblem::signorini;
  PointFunction f;  ///< volume load
  /// Names f and the traction: problems solved on the same `primal` with the same non-empty key
  /// share the assembled F. Empty: F is assembled for this solve alone.
  std::string load_key;
  PointFunction obstacle;          ///< g, Signorini only
  assembly::CouplingWeight bound;  ///< s, friction problems only (s ≥ 0)
  /// Optional boundary traction t(x, n) on Γ_N and Γ_C, added to the load as ∫ t v ds (Neumann
  /// data; on Γ_C a prescribed traction besides the contact force, used by manufactured tests).
  std::function<double(const mesh::Point& x, const mesh::Point& normal)> traction;
  /// Dirichlet data u_D on Γ_D; empty: u = 0 there.
  PointFunction dirichlet;
  /// |𝒞|, the constraint points per segment where Remark 3 applies (p_C ≥ 2, or every p_C for
  /// (15)); must be ≥ p_C + 1 on each such segment. One value for every segment, or one per zone
  /// of T_{C,H}; empty: p_C + 1.
  std::vector<int> constraint_points;
  BoxQpOptions qp;
  InequalityQpOptions interior_point;
  /// Optional: the operators of S^p(T_h) shared with other computations (α of the same pairing),
  /// built here when absent. Must belong to (mesh, cell_degrees) (checked when `mesh` is given).
  /// Its log, if any, records what this solve builds.
  const operators::PrimalOperators* primal = nullptr;
};

struct ContactSolution {
  /// Coefficients on S^p(T_h): u itself, or with Dirichlet data u_0, where u = u_0 + w; at the
  /// rows of u_rows (serial: every dof in the global numbering; distributed: this rank's own cells'
  /// dofs, so assembly::scalar_field reads it on those cells).
  Eigen::VectorXd u;
  assembly::LocalRows u_rows;
  int n_dofs = 0;  ///< unknowns of u in all (of the global numbering)
  /// The lift w of the Dirichlet data (null without them); assembly::scalar_field / vector_field read u.
  std::shared_ptr<const assembly::DirichletLift> lift;
  /// λ in the Lagrange basis: its values at the constraint points, segment by segment.
  Eigen::VectorXd lambda;
  /// The same λ in the Legendre basis of MultiplierSpace (for evaluation anywhere on Γ_C).
  Eigen::VectorXd lambda_legendre;
  /// The constraints lower ≤ C λ ≤ upper, one row per constraint point: C_ji = ℓ_i(τ_j), block
  /// diagonal by segment (the identity where the nodal points are the constraint points).
  Eigen::MatrixXd constraint_matrix;
  Eigen::VectorXd lower, upper;
  std::vector<double> constraint_s;    ///< arc length of each constraint point
  std::vector<int> constraint_points;  ///< constraint points used on each segment
  /// Multiplier y_j of each constraint row, Cᵀ y = gap: y_j > 0 where λ(τ_j) is held at its
  /// upper bound, < 0 at its lower one, 0 where it is free.
  Eigen::VectorXd constraint_multiplier;
  /// (ℓ_i, γ_C u − g) for Signorini, (ℓ_i, s γ_C u) or (ℓ_i, γ_C u) for friction: the dual
  /// gradient −(Sλ − d).
  Eigen::VectorXd gap;
  /// ‖B u_free‖_∞ + ‖(ℓ_i, g)‖_∞ + ‖S λ‖_∞ (u_free = K⁻¹F): the size of the terms whose sum is the
  /// gap d − S λ, the scale against which a gap or a multiplier y is small (the gap itself may
  /// vanish, e.g. on a contact set covering Γ_C or an obstacle touching tangentially).
  double gap_scale = 0.0;
  double energy = 0.0;  ///< E(u) = ½ a(u, u) − F(u) of the whole u
  QpReport qp;
  int n_trace = 0;  ///< trace dofs the condensation works on (ordered last in the factor)
  struct Seconds {
    double assembly = 0.0;       ///< spaces, K, F, B, constraints
    double factorization = 0.0;  ///< sparse Cholesky of K with the trace ordered last
    double condensation = 0.0;   ///< S = B K⁻¹ Bᵀ from the trailing block, d
    double qp = 0.0;             ///< the multiplier problem
    double recovery = 0.0;       ///< u = K⁻¹(F − Bᵀλ), gap, energy
  } seconds;
};

/// @throws InputError for missing data or s < 0; NumericalError if the QP does not converge.
ContactSolution solve_contact(const ContactSetup& setup);

}  // namespace hpcontact::contact
