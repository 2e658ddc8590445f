// How a test helper run under mpirun ends on a failure: as the tool does, once for all ranks when
// every rank failed alike, and by ending the job when a rank failed alone (the others may wait in
// a collective call).
#pragma once

#include <fmt/format.h>
#include <mpi.h>

#include <cstdio>
#include <exception>

#include "core/petsc_session.hpp"
#include "core/rank_agreement.hpp"

namespace hpcontact::testing {

/// Prints `error` (rank 0 alone when every rank failed) and returns the exit code 3; aborts the
/// job with exit code 3 when this rank failed alone.
inline int end_helper_on_failure(const std::exception& error) {
  const bool shared = failure_shared_by_every_rank();
  if (!shared || mpi_rank_and_size().first == 0) fmt::print("error: {}\n", error.what());
  if (!shared) {
    std::fflush(stdout);
    MPI_Abort(MPI_COMM_WORLD, 3);
  }
  return 3;
}

}  // namespace hpcontact::testing
