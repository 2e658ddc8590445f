// Which unknowns the entries of more than one MPI rank touch (the interface of a substructuring),
// found through a directory that spreads the unknowns over the ranks in blocks: no rank holds an
// array of the global length.
#pragma once

#include <mpi.h>

#include <vector>

namespace hpcontact::linalg {

/// Every unknown of [0, n) that the `touched` lists of two or more ranks of `ranks` hold,
/// ascending, the same on every rank. `touched`: the unknowns this rank's entries touch,
/// ascending, distinct and in [0, n) (a precondition: a violation is the caller's bug and ends
/// that rank alone, before the collective calls). Rank r counts the reports of the block [⌈r n / P⌉, ⌈(r + 1) n / P⌉)
/// (one all-to-all), then the blocks' shared unknowns are gathered on every rank. Collective on
/// `ranks`; on one rank nothing is shared.
/// @throws NumericalError (on every rank) naming the first unknown that no rank touches.
std::vector<int> shared_unknowns(MPI_Comm ranks, int n, const std::vector<int>& touched);

}  // namespace hpcontact::linalg
