// The ranks of MPI_COMM_WORLD in groups of consecutive ranks, each with a communicator of its
// own, so that a group shares one distributed problem while other groups solve others (a sweep's
// units on several ranks each).
#pragma once

#include <mpi.h>

namespace hpcontact {

class RankGroups {
 public:
  /// Groups of `group_size` ranks: ranks 0 .. k-1 the first, k .. 2k-1 the next, and so on.
  /// Collective over MPI_COMM_WORLD, whose size `group_size` must divide (checked by the caller:
  /// an InternalError here). With groups of one, or without MPI, each rank is its own group
  /// (MPI_COMM_SELF) and nothing is collective.
  explicit RankGroups(int group_size);
  ~RankGroups();
  RankGroups(const RankGroups&) = delete;
  RankGroups& operator=(const RankGroups&) = delete;

  /// This rank's group; valid while the object lives.
  MPI_Comm group() const { return group_; }
  /// A copy of the group's communicator on which its failing ranks meet (group_fails_within),
  /// apart from the collective calls of the work; MPI_COMM_NULL for groups of one.
  MPI_Comm failure_channel() const { return failure_channel_; }
  /// This rank's rank in its group (0: the group's leader).
  int rank_in_group() const { return rank_in_group_; }
  int group_size() const { return group_size_; }
  /// How many groups there are (the world's size / group_size).
  int n_groups() const { return n_groups_; }

 private:
  MPI_Comm group_ = MPI_COMM_SELF;
  MPI_Comm failure_channel_ = MPI_COMM_NULL;
  int rank_in_group_ = 0, group_size_ = 1, n_groups_ = 1;
};

}  // namespace hpcontact
