// Sparse symmetric positive definite solves over the MPI ranks on PETSc's own domain
// decomposition: the matrix kept unassembled as MATIS (each rank's contributions are its
// subdomain's Neumann matrix, exactly what the static condensation of its cells produces), solved
// by conjugate gradients preconditioned with BDDC (PCBDDC). No rank holds an
// interface matrix: PETSc builds BDDC's small coarse problem from vertex and edge constraints.
// Right-hand sides and results either replicated on every rank or held on the unknowns each rank
// touches, like the other distributed solvers.
#pragma once

#include <mpi.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <optional>
#include <vector>

#include "linalg/coupling_matrix.hpp"
#include "linalg/skeleton_solver.hpp"

namespace hpcontact::linalg {

/// What a rank tells BDDC of the unknowns its entries touch (ascending, as local_unknowns()),
/// beyond its matrix; each may be empty.
struct BddcHints {
  /// Motions of (almost) zero energy (elasticity's rigid motions): shape (local unknowns, k), equal
  /// where ranks share an unknown, the same k on every rank (or none). Attached to the matrix as
  /// PETSc's near null space, which BDDC adds to its coarse space (-bddc_pc_bddc_use_nnsp 0: not).
  Eigen::MatrixXd near_null_space;
  /// The field (0, 1, …) of each local unknown (elasticity: the displacement component), so that
  /// BDDC averages each field over an interface edge on its own. Empty: one field.
  std::vector<int> fields;
  /// The node of each local unknown: the lowest global unknown among the components of its shape
  /// function (the same on every rank), so that GAMG takes a node's components as one block
  /// (NodeBlocks). Empty: GAMG takes each unknown as a node.
  std::vector<int> node;
  /// The local unknowns (indices into local_unknowns(), ascending) on the boundary where the
  /// problem imposes no Dirichlet condition: an interface edge that reaches it then ends in
  /// primal vertices there.
  std::vector<int> natural_boundary;
};

/// What preconditions the conjugate gradients. bddc: PCBDDC on the MATIS (options prefix "bddc_").
/// gamg: the MATIS assembled into an MPIAIJ (then freed) and PETSc's smoothed aggregation PCGAMG
/// with the hints' near null space (options prefix "gamg_"): no factor of the whole K or of a
/// subdomain's, for systems whose factor does not fit in memory (the 3-D Hertz at p = 3).
enum class KrylovPreconditioner { bddc, gamg };

class BddcSolver : public SkeletonSolver {
 public:
  /// `lower_entries`: this rank's contributions (row ≥ col) to the lower triangle of the n × n
  /// matrix, summed where they meet. `relative_tolerance`: of the preconditioned residual (with
  /// 1e-12 the energies and α of the §7 runs equal the serial ones to about 1e-14, the solves
  /// CHOLMOD's to 1e-13; round-off stalls CG near 1e-14 on these systems, so do not ask for less).
  /// PETSc options with the prefix "bddc_" or "gamg_" (e.g. -bddc_ksp_monitor, -gamg_ksp_rtol 1e-10)
  /// adjust the solver. Collective on `ranks`, which must outlive the solver.
  /// `hints`: what the rank knows of its subdomain's unknowns beyond the matrix (BddcHints; GAMG
  /// takes the near null space, the fields and the nodes).
  BddcSolver(MPI_Comm ranks, int n, const std::vector<Eigen::Triplet<double>>& lower_entries,
             double relative_tolerance = 1e-12, const BddcHints& hints = {},
             KrylovPreconditioner preconditioner = KrylovPreconditioner::bddc);
  ~BddcSolver() override;
  BddcSolver(BddcSolver&&) noexcept;
  BddcSolver& operator=(BddcSolver&&) noexcept;

  int size() const override { return size_; }
  /// A⁻¹ rhs, shape (n, k), the same on every rank. Collective.
  /// @throws NumericalError (on every rank) if the iteration does not converge.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& rhs) const override;
  /// The unknowns this rank's entries touch (its subdomain's, ascending): the rows of solve_local.
  const std::vector<int>& local_unknowns() const override;
  /// A⁻¹ b for b = Σ_r b_r: each rank passes its share b_r at its local unknowns (shape
  /// (local_unknowns().size(), k), k the same on every rank) and receives A⁻¹ b there. Collective.
  Eigen::MatrixXd solve_local(const Eigen::MatrixXd& partial_rhs) const override;
  /// B A⁻¹ Bᵀ, dense symmetric (m, m), the same on every rank, for B (m, n) replicated: one
  /// solve per row of B, each rank multiplying its own rows of the solution. Collective.
  Eigen::MatrixXd schur_complement(const Coupling& b) const override;
  /// The conjugate gradients' iterations over all solves so far.
  std::optional<IterationCounts> iterations() const override;
  /// Projected preconditioned CG on active rows of C (linalg/constrained_solver.hpp).
  std::unique_ptr<ConstrainedSolver> constrained(const Coupling& c) const override;

 private:
  struct Impl;
  /// A⁻¹ b on this rank's rows of PETSc's layout. Collective.
  Eigen::MatrixXd solve_owned(const Eigen::MatrixXd& owned_rhs) const;
  std::unique_ptr<Impl> impl_;
  MPI_Comm ranks_ = MPI_COMM_NULL;  ///< the ranks sharing the matrix
  int size_ = 0;
};

}  // namespace hpcontact::linalg
