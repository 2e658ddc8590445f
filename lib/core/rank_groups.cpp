// RankGroups: MPI_Comm_split of MPI_COMM_WORLD by rank / group size.
#include "core/rank_groups.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "core/rank_agreement.hpp"

namespace hpcontact {

RankGroups::RankGroups(int group_size) {
  const auto [rank, size] = mpi_rank_and_size();
  HPC_VERIFY(group_size >= 1 && size % group_size == 0,
             fmt::format("groups of {} ranks do not divide {} ranks", group_size, size));
  n_groups_ = size / group_size;
  group_size_ = group_size;
  if (group_size == 1) return;
  // Keyed by world rank, so a group's rank 0 is its lowest world rank.
  HPC_VERIFY(MPI_Comm_split(MPI_COMM_WORLD, rank / group_size, rank, &group_) == MPI_SUCCESS, "MPI_Comm_split failed");
  MPI_Comm_rank(group_, &rank_in_group_);
  MPI_Comm_dup(group_, &failure_channel_);
}

RankGroups::~RankGroups() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  // Freeing is collective (in the standard); a rank that failed alone leaves them to the abort.
  if (group_ == MPI_COMM_SELF || finalized || failed_alone()) return;
  MPI_Comm_free(&failure_channel_);
  MPI_Comm_free(&group_);
}

}  // namespace hpcontact
