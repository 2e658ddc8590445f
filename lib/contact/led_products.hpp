// Work on a collective operator that one rank leads: each product of a distributed S (a collective
// solve) must be made by every rank together, and an iterative method run on every rank alike
// makes them together only while all ranks take the same steps — one step more on one rank (a
// different BLAS kernel or thread count changing a convergence test) would hang them all. Here the
// first rank alone runs the method and announces each product it needs; the others serve them.
#pragma once

#include <mpi.h>

#include <functional>
#include <vector>

#include "contact/trace_operator.hpp"

namespace hpcontact::contact {

/// Runs `lead` on the first rank of `ranks` with `s` (collective: each product made by every rank
/// with the same x) as an operator that rank applies alone: each product it asks for is broadcast
/// (an order, then x) to the others, which serve products until it is done. Every rank returns the
/// bytes `lead` returned. A failure of `lead` is raised on every rank alike (run_on_all_ranks_agreeing).
/// Collective on `ranks`; on one rank it only runs `lead(s)`.
std::vector<char> run_with_products_led_by_first_rank(
    const TraceOperator& s, MPI_Comm ranks, const std::function<std::vector<char>(const TraceOperator&)>& lead);

}  // namespace hpcontact::contact
