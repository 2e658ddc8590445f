// Sparse symmetric positive definite direct solver over the MPI ranks by substructuring: every
// rank factorizes (CHOLMOD) the unknowns only its own entries touch, and the unknowns shared
// between ranks plus a trailing set (the Γ_C trace) form a dense interface problem held and
// factorized over the ranks by ScaLAPACK (InterfaceCholesky). Right-hand sides and results either replicated on every
// rank or held on the unknowns each rank touches (solve_local).
#pragma once

#include <mpi.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "linalg/coupling_matrix.hpp"
#include "linalg/skeleton_solver.hpp"

namespace hpcontact::linalg {

/// A = Σ_r A_r, where A_r holds rank r's entries (e.g. the element matrices of its cells). An
/// unknown touched by one rank only is that rank's interior (I_r); the others, and the trailing
/// set C, are the interface G (ordered G \ C, then C). (C joins G only when it is at most twice
/// the shared unknowns, or on one rank; otherwise its unknowns stay interior and B A⁻¹ Bᵀ comes
/// from solves.) With A_r split accordingly,
///
///     A_r = [A_II   A_IG ]     S_r = A_GG,r − A_GI A_II⁻¹ A_IG   (rank r alone, CHOLMOD with
///           [A_GI   A_GG,r]                                        G ∩ r ordered last),
///
/// the interface problem S_G = Σ_r S_r (dense, |G| × |G|) is assembled from the ranks' S_r into
/// ScaLAPACK's distributed layout and factorized there (InterfaceCholesky: no rank holds more
/// than |G|²/P of it plus trace-sized blocks). A solve condenses each rank's interior right-hand
/// side onto G, solves with S_G, and back-substitutes on each rank; B A⁻¹ Bᵀ for B supported on C
/// is Wᵀ W with W = L_CC⁻¹ B_Cᵀ, L_CC the trailing block of chol(S_G). Rank r's A_GG,r alone is only semi-
/// definite where its part of the domain floats, so it factorizes A_r + D_r (D_r its own diagonal
/// on G ∩ r) and subtracts D_r from the trailing block again. On one rank G = C: the serial
/// trailing-block factorization.
class SubstructuredCholesky : public SkeletonSolver {
 public:
  /// `lower_entries`: this rank's contributions (row ≥ col) to the lower triangle of the n × n
  /// matrix; contributions to one entry are summed. `trailing`: the same on every rank.
  /// Collective on `ranks` (or serial when MPI is not initialized), which must outlive the solver.
  /// @throws NumericalError if A (or an interior block) is not positive definite, or an unknown
  /// has no entries.
  SubstructuredCholesky(MPI_Comm ranks, int n, const std::vector<Eigen::Triplet<double>>& lower_entries,
                        const std::vector<int>& trailing);
  ~SubstructuredCholesky() override;
  SubstructuredCholesky(SubstructuredCholesky&&) noexcept;
  SubstructuredCholesky& operator=(SubstructuredCholesky&&) noexcept;

  int size() const override { return size_; }
  /// |G|: the size of the dense interface problem (unknowns shared by ranks, and the trailing set
  /// when it joined them).
  int interface_size() const;
  /// Entries of the interface problem this rank stores (about |G|²/P plus trace-sized blocks).
  double interface_entries() const;
  /// Nonzeros of the ranks' sparse (CHOLMOD) factors, averaged over the ranks.
  double mean_factor_nonzeros() const { return mean_factor_nonzeros_; }
  /// A⁻¹ rhs, shape (n, k), the same on every rank. Collective.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& rhs) const override;
  /// The unknowns this rank's entries touch (ascending): the rows of solve_local.
  const std::vector<int>& local_unknowns() const override;
  /// A⁻¹ b for b = Σ_r b_r: each rank passes its share b_r at its local unknowns (shape
  /// (local_unknowns().size(), k), k the same on every rank) and receives A⁻¹ b there. Only the
  /// interface rows (|G| × k) are summed over the ranks. Collective.
  Eigen::MatrixXd solve_local(const Eigen::MatrixXd& partial_rhs) const override;
  /// B A⁻¹ Bᵀ, dense symmetric (m, m), the same on every rank, for B (m, n) replicated: from L_CC,
  /// the trailing block of chol(S_G), when B's nonzero columns lie in the trailing set, otherwise by solves
  /// in blocks of 64 columns. Collective.
  Eigen::MatrixXd schur_complement(const Coupling& b) const override;

 private:
  /// B A⁻¹ Bᵀ by solves in blocks of 64 rows of B, each rank multiplying B's columns at its own
  /// interior unknowns (rank 0 those at the interface): the sums that cross the ranks are
  /// |G| × 64 per block and the m × m result, none of the global length.
  Eigen::MatrixXd schur_complement_by_solves(const Coupling& b) const;

  struct Impl;
  std::unique_ptr<Impl> impl_;
  MPI_Comm ranks_ = MPI_COMM_NULL;  ///< the ranks sharing the matrix
  int size_ = 0;
  double mean_factor_nonzeros_ = 0.0;
};

/// Whether a rank's share of the dense interface problem (`interface_entries`) holds more than the
/// ranks' sparse factors on average (`mean_factor_nonzeros`, or before factorizing a proxy of it)
/// and more than 64 MB: the factors shrink like 1/P, |G|²/P
/// does not (|G| grows with P), so another distributed solver scales further.
bool interface_outweighs_factors(double interface_entries, double mean_factor_nonzeros);

}  // namespace hpcontact::linalg
