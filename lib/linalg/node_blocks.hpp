// NodeBlocks: a vector problem's unknowns regrouped into whole nodes (all components of a shape
// function side by side), for PCGAMG. Dirichlet conditions remove single components (a roller
// plane fixes one of three), so the skeleton's unknowns have no constant block size; GAMG, given
// none, aggregates components apart from their nodes, and its near null space (the rigid
// motions, six per node) then makes coarse spaces of rank-deficient blocks: on 3-D Hertz at p = 1
// it coarsened 40 527 unknowns to 229 and CG took 300 iterations per solve. The removed components
// come back here as decoupled rows of the identity (right-hand side and solution zero there).
#pragma once

#include <mpi.h>
#include <petscmat.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

namespace hpcontact::linalg {

class NodeBlocks {
 public:
  /// `subdomain`: the rank's local unknowns (global indices of the n unknowns, ascending);
  /// `node`, `field`: of each, as BddcHints (node: the lowest unknown among its shape's components,
  /// the same on every rank; field in [0, components)). Rows [row_begin, row_end) of the n
  /// unknowns are the rank's. Collective on `ranks`, which must outlive the object.
  NodeBlocks(MPI_Comm ranks, int n, PetscInt row_begin, PetscInt row_end, const std::vector<PetscInt>& subdomain,
             const std::vector<int>& node, const std::vector<int>& field, int components);
  ~NodeBlocks();
  NodeBlocks(NodeBlocks&&) noexcept;
  NodeBlocks& operator=(NodeBlocks&&) noexcept;

  /// The assembled matrix (MPIAIJ, block size `components`) of the ranks' contributions
  /// `lower_entries` (row ≥ col, at global unknowns, summed where they meet), in node blocks, with
  /// the identity at the removed components. Collective.
  void assemble(const std::vector<Eigen::Triplet<double>>& lower_entries, Mat* out) const;
  /// The rows of the node blocks this rank owns (zero at removed components), from the rank's
  /// owned rows of the n unknowns (owned_rows × k). Collective.
  Eigen::MatrixXd to_blocks(const Eigen::MatrixXd& owned) const;
  /// The rank's owned rows of the n unknowns, from the rank's rows of the node blocks. Collective.
  Eigen::MatrixXd from_blocks(const Eigen::MatrixXd& owned_blocks) const;
  /// How many rows of the node blocks this rank owns.
  PetscInt owned_block_rows() const { return owned_block_rows_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  MPI_Comm ranks_ = MPI_COMM_NULL;
  int components_ = 1;
  PetscInt owned_rows_ = 0, owned_block_rows_ = 0;
};

}  // namespace hpcontact::linalg
