// Factorization of a system assembled cell by cell (a K + b M on S^p(T_h), or elasticity on
// [S^p(T_h)]²) by static condensation: every cell's interior modes are eliminated cell by cell,
// and the Schur complement on the skeleton (vertex and edge dofs) is factorized (CHOLMOD, or a
// distributed solver), optionally with a trailing set (the Γ_C trace) last.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "assembly/cell_system.hpp"
#include "assembly/local_rows.hpp"
#include "core/operator_log.hpp"
#include "linalg/bddc_solver.hpp"
#include "linalg/coupling_matrix.hpp"
#include "linalg/distribution.hpp"
#include "linalg/skeleton_solver.hpp"
#include "space/h1_space.hpp"

namespace hpcontact::assembly {

/// With the skeleton dofs s first and the interior modes i last (H1Space numbers them so),
///
///     [A_ss A_si] [u_s]   [f_s]      S u_s = f_s − A_si A_ii⁻¹ f_i,   S = A_ss − A_si A_ii⁻¹ A_is,
///     [A_is A_ii] [u_i] = [f_i]  ⇔   u_i = A_ii⁻¹ (f_i − A_is u_s).
///
/// A_ii is block diagonal, one block of (p_T − 1)² modes per cell (2(p_T − 1)² for elasticity), so S is assembled from
/// element Schur complements S_T and never needs A itself: (4p)² entries per cell instead of (p + 1)⁴. Parallelogram
/// cells with equal Jacobian and degrees share their elimination (uniform meshes eliminate one cell). Since a trace
/// coupling B has no interior columns, B A⁻¹ Bᵀ = B_s S⁻¹ B_sᵀ: the Steklov–Poincaré condensation of SparseCholesky
/// applies to S unchanged.
///
/// Distributed (under mpirun): the cells are split into one part per rank of equal work by coordinate bisection or
/// PT-Scotch, whichever cuts fewer edges (mesh/cell_partition.hpp); each rank eliminates only its own part's cells and
/// contributes their S_T to S; condensing a right-hand side, recovering the interior modes and the quadratic form add
/// up the ranks' parts. Vectors are either replicated (solve, quadratic_form) or held at each rank's own cells' dofs
/// (solve_local and the other *_local members, with right-hand sides as the ranks' shares). S is solved by the
/// linalg::SkeletonSolver the distribution names (make_skeleton_solver): CHOLMOD serially; distributed, substructuring
/// (default, SubstructuredCholesky): each rank factorizes the skeleton dofs only its part touches, and the dofs between
/// parts and the trailing set form a small dense interface problem whose trailing block gives B A⁻¹ Bᵀ; or MUMPS on an
/// MPIAIJ matrix (DistributedCholesky), whose Schur complement on the trailing set gives B A⁻¹ Bᵀ the same way; or
/// kept unassembled as MATIS, each rank's part its subdomain, and solved by CG + BDDC (BddcSolver), B A⁻¹ Bᵀ again
/// by solves.
class CondensedFactor {
 public:
  /// `trailing`: dofs (skeleton dofs only) ordered last in the factorization of S.
  /// `part_of_cell` (distributed only): the rank of distribution.ranks that eliminates each cell,
  /// shared by factors of one mesh; empty: split_cells_over_ranks weighted by cell_work_weights.
  /// @throws NumericalError if A is not positive definite.
  CondensedFactor(const space::H1Space& space, double stiffness_weight, double mass_weight,
                  const std::vector<int>& trailing = {}, linalg::Distribution distribution = {},
                  const std::vector<int>& part_of_cell = {});
  /// Any cell system (the factor keeps it).
  CondensedFactor(std::unique_ptr<const CellSystem> system, const std::vector<int>& trailing = {},
                  linalg::Distribution distribution = {}, const std::vector<int>& part_of_cell = {});
  ~CondensedFactor();
  CondensedFactor(CondensedFactor&&) noexcept;
  CondensedFactor& operator=(CondensedFactor&&) noexcept;

  /// Number of unknowns of A: system.n_dofs().
  int size() const { return size_; }
  int n_skeleton() const { return system_->n_skeleton_dofs(); }
  /// The trace dofs the Schur complements are taken on (the trailing set).
  int n_trailing() const { return n_trailing_; }
  /// Distinct interior eliminations (of this rank's cells when distributed): 1 on a uniform mesh
  /// of one degree, n_cells on a general mesh.
  int n_eliminations() const { return static_cast<int>(blocks_.size()); }
  /// The ranks the factor is spread over (serial: one process holds it).
  const linalg::Distribution& distribution() const { return distribution_; }

  /// A⁻¹ rhs, shape (n) or (n, k). Distributed: collective, rhs and result the same on every rank.
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const;
  Eigen::MatrixXd solve(const Eigen::MatrixXd& rhs) const;
  /// A⁻¹ rhs on the skeleton for a right-hand side without interior entries (a trace coupling's
  /// Bᵀ x): the skeleton Schur complement's solve alone, shape (n_skeleton, k). Distributed:
  /// collective, replicated.
  Eigen::MatrixXd solve_skeleton(const Eigen::MatrixXd& rhs) const;
  /// The dofs of this rank's cells (ascending, so the skeleton dofs first): the rows of
  /// solve_local and quadratic_form_local. Serial: every dof.
  const std::vector<int>& local_dofs() const { return rows_.dofs(); }
  /// A⁻¹ b for b = Σ_r b_r: each rank passes its share b_r at its local dofs (e.g. its own cells'
  /// load; shape (local_dofs().size(), k), k the same on every rank) and receives A⁻¹ b there. No
  /// vector of the global length: the skeleton solver sums the shares. Collective.
  Eigen::MatrixXd solve_local(const Eigen::MatrixXd& partial_rhs) const;
  /// Where this rank assembles its share of a load for solve_local: distributed, its own cells
  /// into its local dofs; serial, the whole load. Valid while the factor lives.
  const LocalRows& local_rows() const { return rows_; }
  /// B x for B (m, n) the same on every rank and x held at the local dofs: (m, k), the same on
  /// every rank. Collective.
  Eigen::MatrixXd multiply_local(const linalg::Coupling& b, const Eigen::MatrixXd& x_local) const;
  /// This rank's share of Bᵀ y at its local dofs, for B (m, n) and y (m, k) the same on every rank.
  Eigen::MatrixXd transpose_share(const linalg::Coupling& b, const Eigen::MatrixXd& y) const;
  /// Σ_r share_r · x_r: F(u) for F given by the ranks' shares and u at the local dofs. Collective.
  double dot_local(const Eigen::VectorXd& share, const Eigen::VectorXd& x_local) const;
  /// B A⁻¹ Bᵀ, dense symmetric (m, m), for B of shape (m, n): on the skeleton factor's trailing
  /// block when B has no interior columns (any trace coupling), otherwise by solves.
  /// Distributed: collective.
  Eigen::MatrixXd schur_complement(const linalg::Coupling& b) const;
  /// uᵀ A u, cell by cell from the eliminated blocks (a sum of non-negative terms, so as accurate
  /// as u itself), without A. Distributed: collective.
  double quadratic_form(const Eigen::VectorXd& u) const;
  /// uᵀ A u for u held at local_dofs() (each rank its own). Collective.
  double quadratic_form_local(const Eigen::VectorXd& u_local) const;
  /// Solves of A u = f on active rows of the trace coupling B (no interior columns): the interiors
  /// condensed and recovered around the skeleton solver's constrained solves (vectors of all
  /// n dofs, replicated); null when the skeleton solver is direct. Refers to this factor.
  std::unique_ptr<linalg::ConstrainedSolver> constrained_solver(const linalg::Coupling& b) const;
  /// The conjugate gradients' iterations so far (BDDC); empty for a direct solver.
  std::optional<linalg::IterationCounts> iterations() const;

 private:
  struct CellBlock;
  class Constrained;  ///< constrained_solver()'s condensation around the skeleton's solves
  friend class Constrained;
  /// Fills blocks_ and block_of_cell_ for the cells c with contributes[c] (−1 for the others);
  /// returns the entries of the lower triangle of S that they add.
  std::vector<Eigen::Triplet<double>> eliminate_interiors(const std::vector<char>& contributes);
  /// rows_ and n_local_skeleton_ from the rank's cells (`own_cells` when distributed).
  void find_local_dofs(std::vector<char> own_cells);
  /// The local row of `dof` if this rank holds it and is the lowest rank holding it, else −1: so
  /// that a product with B adds each of B's entries on one rank only.
  Eigen::Index counted_local_row(int dof) const;
  /// The system's null motions, fields and boundary at the local skeleton dofs (distributed: what
  /// BDDC learns of the rank's subdomain beyond its matrix).
  linalg::BddcHints local_bddc_hints() const;
  /// −Σ_T (A_ii⁻¹ A_is)ᵀ f_i over this rank's cells, on the skeleton rows (n_skeleton_rows of them);
  /// rhs and the result held at the local dofs when `local`, else in global order.
  Eigen::MatrixXd interior_corrections(const Eigen::MatrixXd& rhs, bool local, Eigen::Index n_skeleton_rows) const;
  /// A⁻¹ rhs (replicated) with `skeleton_solve` for the condensed skeleton system: the condensation
  /// and recovery of solve() around any solve on the skeleton. Collective.
  Eigen::MatrixXd solve_around(const Eigen::MatrixXd& rhs,
                               const std::function<Eigen::MatrixXd(const Eigen::MatrixXd&)>& skeleton_solve) const;
  /// u_i = A_ii⁻¹ (f_i − A_is u_s) for this rank's cells into `solution`, whose skeleton rows
  /// hold u_s; all held at the local dofs when `local`, else in global order.
  void recover_interiors(const Eigen::MatrixXd& rhs, bool local, Eigen::MatrixXd& solution) const;
  /// Σ over this rank's cells (summed over the ranks) of uᵀ A_T u, u held at the local dofs when `local`.
  double cell_quadratic_forms(const Eigen::VectorXd& u, bool local) const;

  std::unique_ptr<const CellSystem> system_;
  int size_ = 0;
  std::vector<std::unique_ptr<CellBlock>> blocks_;
  std::vector<int> block_of_cell_;
  int n_trailing_ = 0;
  LocalRows rows_;                    ///< see local_rows(), local_dofs()
  std::vector<long> cell_row_start_;  ///< per own cell: its first entry of cell_rows_ (distributed)
  std::vector<int> cell_rows_;        ///< the local rows of the own cells' shapes (−1: Dirichlet)
  std::vector<char> counts_dof_;      ///< per local dof: this rank is the lowest holding it (distributed)
  int n_local_skeleton_ = 0;          ///< local dofs in the skeleton (the first ones)
  std::unique_ptr<linalg::SkeletonSolver> skeleton_solver_;  ///< S's solver, the one the distribution names
  /// Distributed: the cells are split over distribution_.ranks and per-cell work is summed over them.
  linalg::Distribution distribution_;
};

/// Adds the iterations of `factor`, recorded in `log` as `name`, to that record (a factor solved
/// by iterations, once it is released: then its count is final). Nothing for a direct solver.
void log_iterations(const CondensedFactor* factor, const std::string& name, OperatorLog* log);

}  // namespace hpcontact::assembly
