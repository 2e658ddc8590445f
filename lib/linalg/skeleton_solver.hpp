// SkeletonSolver: the one interface of the sparse symmetric positive definite solvers that
// CondensedFactor solves its skeleton Schur complement with (CHOLMOD, substructuring, MUMPS, BDDC).
#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <vector>

#include "linalg/constrained_solver.hpp"
#include "linalg/coupling_matrix.hpp"

namespace hpcontact::linalg {

/// Iterations of the conjugate gradients over all solves of an iterative solver (BDDC).
/// `round_off_stops`: solves where CG stopped on an indefinite preconditioner or a breakdown at
/// round-off and the true residual ‖b − A x‖ met 100 × the relative tolerance, so the answer was kept.
struct IterationCounts {
  long solves = 0, total = 0, round_off_stops = 0;
  int largest = 0;
};

/// Solves with one sparse symmetric positive definite A of n unknowns, A = Σ_r A_r summed from the
/// entries of each rank r (serially one rank holds them all), with a trailing set T (the Γ_C
/// trace) ordered after the other unknowns I:
///
///          I      T
///     [  A_II   A_IT ] [x_I]   [b_I]      S_T = A_TT − A_TI A_II⁻¹ A_IT   (the Schur complement on the trace)
///     [  A_TI   A_TT ] [x_T] = [b_T]      B A⁻¹ Bᵀ = B_T S_T⁻¹ B_Tᵀ       (B supported on T)
///
/// b and x are either replicated (solve: n × k, the same on every rank) or held at each rank's
/// local unknowns, those its entries touch (solve_local: b = Σ_r b_r, each rank passing its share
/// b_r and receiving x at the same unknowns). The direct solvers keep S_T or its Cholesky factor
/// (trace-sized; substructuring where that is the cheaper way), so that B A⁻¹ Bᵀ costs dense work
/// of the trace's size; BDDC solves once per row of B. Distributed, every call is collective on the
/// solver's ranks.
class SkeletonSolver {
 public:
  virtual ~SkeletonSolver() = default;

  /// n.
  virtual int size() const = 0;
  /// A⁻¹ rhs, shape (n, k), the same on every rank.
  virtual Eigen::MatrixXd solve(const Eigen::MatrixXd& rhs) const = 0;
  /// The unknowns this rank's entries touch (ascending): the rows of solve_local. Serial: all n.
  virtual const std::vector<int>& local_unknowns() const = 0;
  /// A⁻¹ b for b = Σ_r b_r: each rank passes its share b_r at its local unknowns (shape
  /// (local_unknowns().size(), k), k the same on every rank) and receives A⁻¹ b there.
  virtual Eigen::MatrixXd solve_local(const Eigen::MatrixXd& partial_rhs) const = 0;
  /// B A⁻¹ Bᵀ, dense symmetric (m, m), the same on every rank, for B (m, n) replicated.
  virtual Eigen::MatrixXd schur_complement(const Coupling& b) const = 0;
  /// The iterations so far of an iterative solver; empty for a direct one.
  virtual std::optional<IterationCounts> iterations() const { return std::nullopt; }
  /// Solves on active rows of C (m, n), replicated (ConstrainedSolver), by this solver's iteration
  /// and preconditioner; null for a direct solver (whose way to contact is S). The object refers
  /// to this solver, which must outlive it.
  virtual std::unique_ptr<ConstrainedSolver> constrained(const Coupling& /*c*/) const { return nullptr; }

 protected:
  // (a solver is moved as its own type, never sliced through this interface)
  SkeletonSolver() = default;
  SkeletonSolver(SkeletonSolver&&) = default;
  SkeletonSolver& operator=(SkeletonSolver&&) = default;
};

}  // namespace hpcontact::linalg
