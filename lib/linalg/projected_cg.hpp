// ProjectedConjugateGradients: CG on an assembled PETSc operator A with its (set-up, fixed,
// symmetric positive definite) preconditioner M⁻¹, kept on the affine set C_A x = c_A of chosen
// rows of a fixed C. Iterates stay on the set, the preconditioned residuals are projected onto C_A's
// null space by
//     Π = I − W E⁻¹ C_A,   W = D⁻¹ C_Aᵀ,   E = C_A D⁻¹ C_Aᵀ   (D = diag A; E small: one row per
//                                                          active constraint),
// and z = Π M⁻¹ Πᵀ r is the preconditioner on it (symmetric, definite on the null space, zero on
// range(C_Aᵀ)): CG converges where Πᵀ r = 0, i.e. r ∈ range(C_Aᵀ), the KKT conditions. The
// projection in M's metric (W = M⁻¹ C_Aᵀ) would keep the spectrum within that of M⁻¹ A, but costs an
// application of M⁻¹ and a vector of the global length per active row: on the elastic cube of the
// 3-D benchmark (45 000 unknowns, 140 rows ever active) 96 CG iterations + 140 applications against
// 181 iterations with D, in the same time and no n × k block.
#pragma once

#include <mpi.h>
#include <petscksp.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "core/petsc_handle.hpp"
#include "linalg/constrained_solver.hpp"

namespace hpcontact::linalg {

class ProjectedConjugateGradients {
 public:
  /// `a`, `pc`: the operator and its set-up preconditioner (both must outlive the object);
  /// `owned_constraints`: Cᵀ at this rank's rows of `a` (owned × m); `name`: the solver's, for
  /// messages. Collective on `ranks`.
  ProjectedConjugateGradients(MPI_Comm ranks, Mat a, PC pc, Eigen::SparseMatrix<double> owned_constraints,
                              int max_iterations, std::string name);

  /// ConstrainedSolver::solve on this rank's rows (rhs, start and the result's x: owned rows).
  /// Collective.
  ConstrainedSolution solve(const Eigen::VectorXd& owned_rhs, const std::vector<int>& active,
                            const Eigen::VectorXd& values, const Eigen::VectorXd& owned_start,
                            double relative_tolerance);
  /// Applications of M⁻¹ beyond CG's one per iteration (the tolerance's scale).
  long applications() const { return applications_; }
  long iterations() const { return iterations_; }

 private:
  /// M⁻¹ x, A x on owned rows.
  Eigen::VectorXd precondition(const Eigen::VectorXd& x) const;
  Eigen::VectorXd multiply(const Eigen::VectorXd& x) const;
  /// C_Aᵀ of the rows `active` (owned × k), W = D⁻¹ C_Aᵀ and the Cholesky factor of E = C_A W
  /// (summed over the ranks). @throws NumericalError if E is singular (dependent rows).
  struct ActiveRows {
    Eigen::SparseMatrix<double> c, w;
    Eigen::LLT<Eigen::MatrixXd> e;
  };
  ActiveRows active_rows(const std::vector<int>& active) const;
  /// Σ over the ranks of the rank's values.
  double sum(double local) const;
  Eigen::VectorXd sum(Eigen::VectorXd local) const;

  MPI_Comm ranks_;
  Mat a_;
  PC pc_;
  Eigen::SparseMatrix<double> constraints_;  ///< Cᵀ, owned × m
  int max_iterations_;
  std::string name_;
  PetscHandle<Vec, VecDestroy> in_, out_;  ///< work vectors of A's layout
  Eigen::VectorXd diagonal_inverse_;       ///< 1 / diag(A), owned rows
  long applications_ = 0, iterations_ = 0;
};

}  // namespace hpcontact::linalg
