// SharedCounter: one long in an MPI window on rank 0, in a shared lock epoch for the counter's
// lifetime, advanced by MPI_Fetch_and_op.
#include "core/shared_counter.hpp"

#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "core/rank_agreement.hpp"

namespace hpcontact {

SharedCounter::SharedCounter() {
  const auto [rank, size] = mpi_rank_and_size();
  if (size == 1) return;
  const MPI_Aint bytes = rank == 0 ? static_cast<MPI_Aint>(sizeof(long)) : 0;
  HPC_VERIFY(MPI_Win_allocate(bytes, sizeof(long), MPI_INFO_NULL, MPI_COMM_WORLD, &value_, &window_) == MPI_SUCCESS,
             "MPI_Win_allocate failed");
  MPI_Win_lock_all(MPI_MODE_NOCHECK, window_);
  // Rank 0's initial value must be in the window (synced into its public copy) before any rank's
  // first fetch-and-add.
  if (rank == 0) {
    *value_ = 0;
    MPI_Win_sync(window_);
  }
  MPI_Barrier(MPI_COMM_WORLD);
}

SharedCounter::~SharedCounter() {
  // Freeing the window waits for every rank, which a rank that failed alone would not see again.
  if (window_ == MPI_WIN_NULL || failed_alone()) return;
  MPI_Win_unlock_all(window_);
  MPI_Win_free(&window_);
}

long SharedCounter::take() { return add(1); }

long SharedCounter::exhaust(long end) { return add(end); }

long SharedCounter::value() const {
  // MPI_NO_OP: an atomic read beside the other ranks' MPI_SUM (its origin is ignored; Open MPI
  // before 4.0.2 crashed on a null one).
  return window_ == MPI_WIN_NULL ? local_ : fetch_and_op(0, MPI_NO_OP);
}

long SharedCounter::add(long amount) {
  if (window_ == MPI_WIN_NULL) {
    const long before = local_;
    local_ += amount;
    return before;
  }
  // Always an addition: concurrent accumulates on one location are atomic only with the same
  // operation (the window's default accumulate_ops = same_op_no_op).
  return fetch_and_op(amount, MPI_SUM);
}

long SharedCounter::fetch_and_op(long operand, MPI_Op op) const {
  long before = 0;
  HPC_VERIFY(MPI_Fetch_and_op(&operand, &before, MPI_LONG, 0, 0, op, window_) == MPI_SUCCESS,
             "MPI_Fetch_and_op failed");
  MPI_Win_flush(0, window_);
  return before;
}

}  // namespace hpcontact
