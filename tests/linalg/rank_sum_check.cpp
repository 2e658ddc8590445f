// Helper of distributed_factor_test, run under mpirun: every rank contributes values of very
// different sizes (so that the order of the additions changes the rounded sum) to one
// sum_over_ranks of COUNT doubles, in more than one 8 MB piece; rank 0 prints how many entries
// differ, bit for bit, between any rank's sum and rank 0's, and the largest deviation from the
// sum added in rank order in long double.
//
//   rank_sum_check COUNT
#include <fmt/format.h>
#include <mpi.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "core/petsc_session.hpp"

using namespace hpcontact;

namespace {

// Rank r's k-th value: alternating magnitudes 1e16 and 1 with signs that cancel across ranks.
double contribution(int rank, std::size_t k) {
  const double big = (rank + k) % 2 == 0 ? 1e16 : 1.0;
  return (rank % 3 == 1 ? -1.0 : 1.0) * big * (1.0 + 1e-3 * static_cast<double>((k * 7 + rank * 13) % 101));
}

}  // namespace

int main(int argc, char** argv) {
  const PetscSession session({argv[0]});
  if (argc != 2) return 2;
  const std::size_t count = std::stoul(argv[1]);
  const auto [rank, size] = mpi_rank_and_size();
  std::vector<double> data(count);
  for (std::size_t k = 0; k < count; ++k) data[k] = contribution(rank, k);
  sum_over_ranks(MPI_COMM_WORLD, data.data(), count);
  // Rank 0's sum against every rank's, bit for bit.
  std::vector<double> first(data);
  MPI_Bcast(first.data(), static_cast<int>(count), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  long differ = 0;
  double deviation = 0.0;
  for (std::size_t k = 0; k < count; ++k) {
    if (std::memcmp(&first[k], &data[k], sizeof(double)) != 0) ++differ;
    long double exact = 0.0L;
    for (int r = 0; r < size; ++r) exact += contribution(r, k);
    const double scale = 1e16 * size;
    deviation = std::max(deviation, static_cast<double>(std::fabs(static_cast<long double>(data[k]) - exact)) / scale);
  }
  long all_differ = 0;
  MPI_Reduce(&differ, &all_differ, 1, MPI_LONG, MPI_SUM, 0, MPI_COMM_WORLD);
  if (rank == 0) fmt::print("differing_entries {} relative_deviation {:.3e}\n", all_differ, deviation);
  return 0;
}
