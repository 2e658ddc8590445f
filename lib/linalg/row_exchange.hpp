// RowExchange: moves columns of values between the unknowns a rank's entries touch (its local
// unknowns, where right-hand sides are assembled and results are read) and the contiguous rows
// PETSc gives the rank (where its distributed solvers work), with PETSc's VecScatter: no array of
// the global length on any rank.
#pragma once

#include <mpi.h>
#include <petscvec.h>

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <vector>

namespace hpcontact::linalg {

class RowExchange {
 public:
  /// `local`: the rank's local unknowns (global indices, ascending, no repeats); rows
  /// [row_begin, row_end) of the n unknowns are the rank's in PETSc's layout. Collective on `ranks`.
  RowExchange(MPI_Comm ranks, int n, int row_begin, int row_end, std::vector<int> local);
  ~RowExchange();
  RowExchange(RowExchange&&) noexcept;
  RowExchange& operator=(RowExchange&&) noexcept;

  const std::vector<int>& local() const { return local_; }
  int owned_rows() const { return row_end_ - row_begin_; }
  /// b = Σ_r b_r: each rank's share on its local unknowns (local().size() × k) in, the rank's
  /// owned rows of the sum out. Collective.
  Eigen::MatrixXd sum_to_owned(const Eigen::MatrixXd& partial) const;
  /// The owned rows of x, given x at every rank's local unknowns (equal where ranks share one).
  /// Collective.
  Eigen::MatrixXd consistent_to_owned(const Eigen::MatrixXd& local) const;
  /// The rows at the rank's local unknowns of x, given each rank's owned rows of x. Collective.
  Eigen::MatrixXd owned_to_local(const Eigen::MatrixXd& owned) const;
  /// For each local unknown, whether this rank is the lowest of the ranks holding it: the one rank
  /// that counts it in sums over the ranks (shares of a replicated vector, gathers, dot products).
  /// Collective.
  std::vector<char> lowest_rank_holds() const;

 private:
  /// One column between the owned rows and the local unknowns (both arrays of the caller's),
  /// forward (owned → local) or reverse (local → owned, combined by `mode`). Collective.
  void scatter(double* owned, double* local, InsertMode mode, ScatterMode direction) const;

  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::vector<int> local_;
  int row_begin_ = 0, row_end_ = 0;
  int rank_ = 0;
};

/// A solver that works on PETSc's owned rows [row_begin, row_end) applied to a right-hand side
/// replicated on every rank (n × k): each rank solves its owned rows, and the result, non-zero
/// on each row's owner only, is summed over the ranks. Collective.
Eigen::MatrixXd solve_replicated(MPI_Comm ranks, int row_begin, int row_end, const Eigen::MatrixXd& rhs,
                                 const std::function<Eigen::MatrixXd(const Eigen::MatrixXd&)>& solve_owned);

}  // namespace hpcontact::linalg
