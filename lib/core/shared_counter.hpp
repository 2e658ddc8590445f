// A counter shared by all MPI ranks, from which idle ranks take the next unit of work (a dynamic
// work queue without a dispatching rank).
#pragma once

#include <mpi.h>

namespace hpcontact {

/// Held in an MPI window on rank 0 and advanced by atomic fetch-and-add (MPI_Fetch_and_op in a
/// passive-target epoch), so a rank takes work without rank 0 answering: on one node the window
/// is shared memory; across nodes Open MPI needs an RMA-capable transport (UCX) for a rank to take
/// work while rank 0 computes, and otherwise serves the request when rank 0 next enters MPI.
/// Construction and destruction are collective over MPI_COMM_WORLD; on one rank (or without MPI)
/// it is a plain counter.
class SharedCounter {
 public:
  SharedCounter();
  ~SharedCounter();
  SharedCounter(const SharedCounter&) = delete;
  SharedCounter& operator=(const SharedCounter&) = delete;

  /// The counter's value before this call adds one: 0, 1, 2, ... over all ranks, each value
  /// handed to exactly one caller.
  long take();
  /// The same, adding `amount` (a share of work done, counted in units).
  long take(long amount) { return add(amount); }
  /// Adds `end` (the number of units) to the counter, so that no rank takes new work: a failing
  /// rank calls it so the run ends after the units in progress. Returns the counter before, i.e.
  /// how many values below `end` were handed out.
  long exhaust(long end);
  /// The counter now (another rank may advance it at any time).
  long value() const;

 private:
  /// Adds `amount`; returns the counter before.
  long add(long amount);
  /// The counter on rank 0 before `op` with `operand`, atomically (window only).
  long fetch_and_op(long operand, MPI_Op op) const;

  MPI_Win window_ = MPI_WIN_NULL;
  long* value_ = nullptr;  // rank 0's cell of the window
  long local_ = 0;         // the counter on one rank
};

}  // namespace hpcontact
