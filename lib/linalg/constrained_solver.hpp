// ConstrainedSolver: solves of A x = b on the affine set C_A x = c_A, where C_A is a chosen set of
// rows of one fixed C (the active constraints of a contact problem, which change from one solve to
// the next): the conjugate gradients of an iterative solver (BDDC, GAMG) projected onto the null
// space of C_A, so that contact costs a few linear solves rather than one per multiplier.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace hpcontact::linalg {

/// The minimizer of ½ xᵀ A x − bᵀ x over C_A x = c_A and its multipliers μ: A x + C_Aᵀ μ = b.
struct ConstrainedSolution {
  Eigen::VectorXd x;            ///< shape (n)
  Eigen::VectorXd multipliers;  ///< μ at the active rows, in their order
  int iterations = 0;           ///< conjugate gradients' iterations of this solve
  /// ‖M⁻¹ (b − A x − C_Aᵀ μ)‖ / ‖M⁻¹ (b − C_Aᵀ μ)‖, M⁻¹ the preconditioner: the measure the
  /// unconstrained solves stop on (PETSc's preconditioned norm), with μ's load in b
  double relative_residual = 0.0;
};

class ConstrainedSolver {
 public:
  virtual ~ConstrainedSolver() = default;
  /// The solve on the rows `active` of C (ascending, distinct) with values c_A, from `start`
  /// (shape n; projected onto C_A x = c_A first), until relative_residual ≤ `relative_tolerance`.
  /// Vectors replicated on every rank. Collective.
  /// @throws NumericalError if the active rows are linearly dependent or CG does not converge.
  virtual ConstrainedSolution solve(const Eigen::VectorXd& rhs, const std::vector<int>& active,
                                    const Eigen::VectorXd& values, const Eigen::VectorXd& start,
                                    double relative_tolerance) = 0;
  /// Applications of the preconditioner over all solves (one per CG iteration, and those that
  /// scale the tolerance).
  virtual long preconditioner_applications() const = 0;
  /// Conjugate gradients' iterations over all solves.
  virtual long iterations() const = 0;
  /// The relative tolerance of the solver's unconstrained solves (PETSc's ksp_rtol).
  virtual double relative_tolerance() const = 0;

 protected:
  ConstrainedSolver() = default;
};

}  // namespace hpcontact::linalg
