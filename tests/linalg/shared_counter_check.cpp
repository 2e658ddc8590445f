// Helper of distributed_factor_test, run under mpirun: every rank takes values from one
// SharedCounter until they pass N, working (sleeping) longer on higher ranks; with STOP_AT, the
// rank that takes that value exhausts the counter. Rank 0 prints how many values were taken,
// how many distinct, how many not below N, each rank's count, and how many values the counter had
// handed out when it was exhausted (-1 without STOP_AT).
//
//   shared_counter_check N [STOP_AT]
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <mpi.h>

#include <chrono>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "core/petsc_session.hpp"
#include "core/shared_counter.hpp"

using namespace hpcontact;

int main(int argc, char** argv) {
  const PetscSession session({argv[0]});
  if (argc < 2) return 2;
  const long n = std::stol(argv[1]);
  const long stop_at = argc > 2 ? std::stol(argv[2]) : -1;
  const auto [rank, size] = mpi_rank_and_size();
  std::vector<long> taken;
  long handed_out = -1;
  {
    SharedCounter counter;
    for (long value = counter.take(); value < n; value = counter.take()) {
      taken.push_back(value);
      if (value == stop_at) {
        handed_out = counter.exhaust(n);
        break;
      }
      std::this_thread::sleep_for(std::chrono::microseconds(200 * (rank + 1)));
    }
  }
  int count = static_cast<int>(taken.size());
  std::vector<int> counts(static_cast<std::size_t>(size)), offsets(static_cast<std::size_t>(size), 0);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<long> all;
  if (rank == 0) {
    for (int r = 1; r < size; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
    all.resize(static_cast<std::size_t>(offsets[size - 1] + counts[size - 1]));
  }
  MPI_Allreduce(MPI_IN_PLACE, &handed_out, 1, MPI_LONG, MPI_MAX, MPI_COMM_WORLD);
  MPI_Gatherv(taken.data(), count, MPI_LONG, all.data(), counts.data(), offsets.data(), MPI_LONG, 0, MPI_COMM_WORLD);
  if (rank == 0) {
    const std::set<long> distinct(all.begin(), all.end());
    long outside = 0;
    for (long value : all) outside += value < 0 || value >= n;
    fmt::print("taken {} distinct {} outside {} handed_out {} per_rank {}\n", all.size(), distinct.size(), outside,
               handed_out, fmt::join(counts, " "));
  }
  return 0;
}
