// run_on_all_ranks_agreeing: a MAX reduction of the exit codes, then the lowest failing rank's
// message broadcast to all; and the failure channel, a communicator of its own on which failing
// ranks meet in a non-blocking barrier, so that it cannot be confused with a collective call of the
// work in progress.
#include "core/rank_agreement.hpp"

#include <mpi.h>

#include <chrono>
#include <exception>
#include <stdexcept>
#include <string>
#include <thread>

#include "core/error.hpp"
#include "core/petsc_session.hpp"

namespace hpcontact {
namespace {
bool agreed = false;
bool alone = false;
MPI_Comm failure_channel = MPI_COMM_NULL;

// Whether every rank of `channel` enters a non-blocking barrier on it within `seconds`.
bool barrier_within(MPI_Comm channel, double seconds) {
  MPI_Request request = MPI_REQUEST_NULL;
  MPI_Ibarrier(channel, &request);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int done = 0;
  for (;;) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return true;
    if (std::chrono::steady_clock::now() > deadline) return false;  // the job is aborted next
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

}  // namespace

bool failed_alone() { return alone; }

bool group_fails_within(MPI_Comm channel, double seconds) {
  if (channel == MPI_COMM_NULL || barrier_within(channel, seconds)) return true;
  alone = true;
  return false;
}

void open_failure_channel() {
  if (failure_channel != MPI_COMM_NULL || mpi_rank_and_size().second == 1) return;
  MPI_Comm_dup(MPI_COMM_WORLD, &failure_channel);
}

bool every_rank_fails_within(double seconds) {
  if (failure_channel == MPI_COMM_NULL || alone || !barrier_within(failure_channel, seconds)) return false;
  agreed = true;
  return true;
}

bool failure_shared_by_every_rank() {
  if (mpi_rank_and_size().second == 1) return true;
  if (!agreed) every_rank_fails_within(kFailurePatience);
  // A rank that failed alone inside a group's collective work aborts, whatever was agreed before.
  return agreed && !alone;
}

void run_on_all_ranks_agreeing(const std::function<void()>& work, MPI_Comm ranks) {
  const int rank = rank_and_size(ranks).first, size = rank_and_size(ranks).second;
  if (size == 1) {
    work();
    return;
  }
  int code = 0;
  std::string message;
  try {
    work();
  } catch (const std::exception& error) {
    if (alone) throw;  // the others wait elsewhere: no reduction, the job is aborted
    code = exit_code_of(error);
    message = message_of(error);
  } catch (...) {  // leaving one rank alone would hang the others in the reduction below
    if (alone) throw;
    code = 1;
    message = "an exception that is not a std::exception";
  }
  int worst = 0;
  MPI_Allreduce(&code, &worst, 1, MPI_INT, MPI_MAX, ranks);
  if (worst == 0) return;
  const int candidate = code != 0 ? rank : size;
  int first = size;
  MPI_Allreduce(&candidate, &first, 1, MPI_INT, MPI_MIN, ranks);
  int shared[3] = {code, static_cast<int>(message.size()), mpi_rank_and_size().first};
  MPI_Bcast(shared, 3, MPI_INT, first, ranks);
  const int shared_code = shared[0], length = shared[1], world_rank = shared[2];
  message.resize(static_cast<std::size_t>(length));
  MPI_Bcast(message.data(), length, MPI_CHAR, first, ranks);
  // A message agreed on before, within a group of ranks (a sweep's unit), names its rank already.
  if (world_rank != 0 && !message.starts_with("on rank "))
    message = "on rank " + std::to_string(world_rank) + ": " + message;
  agreed = true;
  switch (shared_code) {
    case 2:
      throw InputError(message);
    case 3:
      throw NumericalError(message);
    case 4:
      throw IoError(message);
    default:
      throw std::runtime_error(message);
  }
}

}  // namespace hpcontact
