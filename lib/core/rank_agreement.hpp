// Failures under mpirun reach every rank: a rank that throws while the others wait in a collective
// call would hang the run. Work wrapped here ends the same way on every rank.
#pragma once

#include <mpi.h>

#include <functional>

namespace hpcontact {

/// Runs `work`; if it throws on any rank of `ranks`, every rank of `ranks` throws an exception of
/// the same type (input, numerical, I/O, or other) with the message of the lowest failing rank
/// ("on rank r: ..." with r its rank in MPI_COMM_WORLD, when that is not 0). Collective on
/// `ranks`: every one must call it with its share of the work. On one rank it only runs `work`.
void run_on_all_ranks_agreeing(const std::function<void()>& work, MPI_Comm ranks = MPI_COMM_WORLD);

/// Opens the channel on which failing ranks look for each other (collective, once, after MPI is up
/// under a launcher; a no-op on one rank).
void open_failure_channel();

/// Seconds between the first and the last rank of a collective failure reaching the failure
/// channel, beyond which a rank is taken to have failed alone.
constexpr double kFailurePatience = 10.0;

/// For a failure inside collective work on a group of ranks (`channel`: the group's own failure
/// channel, RankGroups::failure_channel()): whether every rank of the group fails within `seconds`
/// of this one. If not, this rank failed alone and the others may wait in a collective call of the
/// work: from then on run_on_all_ranks_agreeing lets failures pass without a collective call and
/// failed_alone() is true, so that the failure reaches the tool's report, which aborts the job.
bool group_fails_within(MPI_Comm channel, double seconds);

/// Whether group_fails_within found this rank failing alone (collective clean-up, e.g. freeing a
/// communicator or an MPI window, must then be skipped: the other ranks never come).
bool failed_alone();

/// Whether every rank reports a failure within `seconds` of this rank's: a failure all ranks raise
/// alike (bad input read by each, a collective solve that did not converge) is then reported once
/// and ends every rank cleanly, while a failure of one rank alone (the others may wait in a
/// collective call) is not. Called by failing ranks only; false without an open channel.
bool every_rank_fails_within(double seconds);

/// For a failure that reached a program's top level: whether every rank raised it (agreed inside
/// the work, or met on the failure channel within kFailurePatience), so that rank 0 reports it
/// once and every rank ends cleanly. False when this rank failed alone: the others may wait in a
/// collective call, and the program must abort the job (MPI_Abort) rather than return. True on
/// one rank.
bool failure_shared_by_every_rank();

}  // namespace hpcontact
