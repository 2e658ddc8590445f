// broadcast_bytes: the length first, then the bytes in pieces of at most 1 GiB;
// bytes_made_by_first_rank; bytes_made_by_first_rank_for_each, sent rank by rank likewise.
#include "core/byte_buffer.hpp"

#include <algorithm>

#include "core/petsc_session.hpp"
#include "core/rank_agreement.hpp"

namespace hpcontact {

namespace {
constexpr std::uint64_t kPiece = std::uint64_t{1} << 30;  // below MPI's int count limit
}  // namespace

std::vector<char> broadcast_bytes(std::vector<char> bytes, int root, MPI_Comm ranks) {
  std::uint64_t size = bytes.size();
  HPC_VERIFY(MPI_Bcast(&size, 1, MPI_UINT64_T, root, ranks) == MPI_SUCCESS, "broadcast of a length");
  bytes.resize(size);
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

namespace {

void send_bytes(const std::vector<char>& bytes, int to, MPI_Comm ranks) {
  const std::uint64_t size = bytes.size();
  HPC_VERIFY(MPI_Send(&size, 1, MPI_UINT64_T, to, 0, ranks) == MPI_SUCCESS, "sending a length");
  for (std::uint64_t at = 0; at < size; at += kPiece)
    HPC_VERIFY(MPI_Send(bytes.data() + at, static_cast<int>(std::min(kPiece, size - at)), MPI_CHAR, to, 0, ranks) ==
                   MPI_SUCCESS,
               "sending bytes");
}

std::vector<char> received_bytes(int from, MPI_Comm ranks) {
  std::uint64_t size = 0;
  HPC_VERIFY(MPI_Recv(&size, 1, MPI_UINT64_T, from, 0, ranks, MPI_STATUS_IGNORE) == MPI_SUCCESS, "receiving a length");
  std::vector<char> bytes(size);
  for (std::uint64_t at = 0; at < size; at += kPiece)
    HPC_VERIFY(MPI_Recv(bytes.data() + at, static_cast<int>(std::min(kPiece, size - at)), MPI_CHAR, from, 0, ranks,
                        MPI_STATUS_IGNORE) == MPI_SUCCESS,
               "receiving bytes");
  return bytes;
}

}  // namespace

std::vector<char> bytes_made_by_first_rank_for_each(const std::function<std::vector<char>(int rank)>& make,
                                                    MPI_Comm ranks) {
  // (not a structured binding: clang 14 refuses to capture one in the lambda below)
  const int rank = rank_and_size(ranks).first, size = rank_and_size(ranks).second;
  if (size == 1) return make(0);
  std::vector<char> mine;
  // The others' bytes first, each sent as soon as it is made; the first rank's own last.
  for (int r = 1; r <= size; ++r) {
    const int to = r % size;
    std::vector<char> bytes;
    run_on_all_ranks_agreeing(
        [&] {
          if (rank == 0) bytes = make(to);
        },
        ranks);
    if (to == 0) {
      if (rank == 0) mine = std::move(bytes);
    } else if (rank == 0) {
      send_bytes(bytes, to, ranks);
    } else if (rank == to) {
      mine = received_bytes(0, ranks);
    }
  }
  return mine;
}

}  // namespace hpcontact
