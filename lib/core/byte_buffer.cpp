// broadcast_bytes: the length first, then the bytes in pieces of at most 1 GiB;
// bytes_made_by_first_rank.
#include "core/byte_buffer.hpp"

#include <algorithm>

#include "core/petsc_session.hpp"
#include "core/rank_agreement.hpp"

namespace hpcontact {

std::vector<char> broadcast_bytes(std::vector<char> bytes, int root, MPI_Comm ranks) {
  std::uint64_t size = bytes.size();
  HPC_VERIFY(MPI_Bcast(&size, 1, MPI_UINT64_T, root, ranks) == MPI_SUCCESS, "broadcast of a length");
  bytes.resize(size);
  constexpr std::uint64_t kPiece = std::uint64_t{1} << 30;
  for (std::uint64_t at = 0; at < size; at += kPiece) {
    const int count = static_cast<int>(std::min(kPiece, size - at));
    HPC_VERIFY(MPI_Bcast(bytes.data() + at, count, MPI_CHAR, root, ranks) == MPI_SUCCESS, "broadcast of bytes");
  }
  return bytes;
}

std::vector<char> bytes_made_by_first_rank(const std::function<std::vector<char>()>& make, MPI_Comm ranks) {
  if (rank_and_size(ranks).second == 1) return make();
  const bool first = rank_and_size(ranks).first == 0;
  std::vector<char> bytes;
  run_on_all_ranks_agreeing(
      [&] {
        if (first) bytes = make();
      },
      ranks);
  return broadcast_bytes(std::move(bytes), 0, ranks);
}

}  // namespace hpcontact
