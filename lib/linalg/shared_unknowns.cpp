// shared_unknowns: an all-to-all of the touched unknowns to the ranks that keep their blocks,
// counted there, and the shared ones gathered.
#include "linalg/shared_unknowns.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/petsc_session.hpp"

namespace hpcontact::linalg {

namespace {

// Exclusive prefix sums of `counts`.
std::vector<int> displacements(const std::vector<int>& counts) {
  std::vector<int> out(counts.size(), 0);
  for (std::size_t r = 1; r < counts.size(); ++r) out[r] = out[r - 1] + counts[r - 1];
  return out;
}

[[noreturn]] void throw_untouched(int unknown, int n) {
  throw NumericalError(fmt::format("substructured Cholesky: unknown {} of {} has no entries", unknown, n));
}

}  // namespace

std::vector<int> shared_unknowns(MPI_Comm ranks, int n, const std::vector<int>& touched) {
  const int rank = rank_and_size(ranks).first, size = rank_and_size(ranks).second;
  if (size == 1) {
    for (int i = 0; i < static_cast<int>(touched.size()); ++i)
      if (touched[i] != i) throw_untouched(i, n);
    if (static_cast<int>(touched.size()) != n) throw_untouched(static_cast<int>(touched.size()), n);
    return {};
  }
  const auto block_begin = [&](int r) { return static_cast<int>((static_cast<long long>(n) * r + size - 1) / size); };
  // 1. Each touched unknown to the rank that keeps its block (`touched` is ascending, so the
  //    blocks follow one another).
  std::vector<int> send_counts(size, 0), receive_counts(size, 0);
  for (int r = 0, k = 0; k < static_cast<int>(touched.size()); ++k) {
    HPC_VERIFY(touched[k] >= 0 && touched[k] < n && (k == 0 || touched[k] > touched[k - 1]),
               "shared_unknowns: touched unknowns must be ascending, distinct and in range");
    while (touched[k] >= block_begin(r + 1)) ++r;
    ++send_counts[r];
  }
  HPC_VERIFY(MPI_Alltoall(send_counts.data(), 1, MPI_INT, receive_counts.data(), 1, MPI_INT, ranks) == MPI_SUCCESS,
             "MPI_Alltoall failed");
  const std::vector<int> send_displacements = displacements(send_counts),
                         receive_displacements = displacements(receive_counts);
  std::vector<int> received(static_cast<std::size_t>(receive_displacements.back() + receive_counts.back()));
  HPC_VERIFY(MPI_Alltoallv(touched.data(), send_counts.data(), send_displacements.data(), MPI_INT, received.data(),
                           receive_counts.data(), receive_displacements.data(), MPI_INT, ranks) == MPI_SUCCESS,
             "MPI_Alltoallv failed");
  // 2. Count the reports of this rank's block; an unknown nobody touches fails on every rank.
  const int begin = block_begin(rank), end = block_begin(rank + 1);
  std::vector<int> reports(static_cast<std::size_t>(end - begin), 0);
  for (int i : received) ++reports[static_cast<std::size_t>(i - begin)];
  std::vector<int> mine;
  int untouched = n;
  for (int i = begin; i < end; ++i) {
    const int count = reports[static_cast<std::size_t>(i - begin)];
    if (count == 0 && untouched == n) untouched = i;
    if (count >= 2) mine.push_back(i);
  }
  int first_untouched = n;
  HPC_VERIFY(MPI_Allreduce(&untouched, &first_untouched, 1, MPI_INT, MPI_MIN, ranks) == MPI_SUCCESS,
             "MPI_Allreduce failed");
  if (first_untouched < n) throw_untouched(first_untouched, n);
  // 3. The blocks' shared unknowns, in block (hence index) order, on every rank.
  const int n_mine = static_cast<int>(mine.size());
  std::vector<int> counts(size);
  HPC_VERIFY(MPI_Allgather(&n_mine, 1, MPI_INT, counts.data(), 1, MPI_INT, ranks) == MPI_SUCCESS,
             "MPI_Allgather failed");
  const std::vector<int> offsets = displacements(counts);
  std::vector<int> shared(static_cast<std::size_t>(offsets.back() + counts.back()));
  HPC_VERIFY(MPI_Allgatherv(mine.data(), n_mine, MPI_INT, shared.data(), counts.data(), offsets.data(), MPI_INT,
                            ranks) == MPI_SUCCESS,
             "MPI_Allgatherv failed");
  return shared;
}

}  // namespace hpcontact::linalg
