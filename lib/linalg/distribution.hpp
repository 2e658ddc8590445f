// How one problem's factorizations are spread over MPI ranks: the solver (the option
// --distributed-solver of `solve`, `infsup` and `sweep`) and the ranks that share the problem
// (all of mpirun's, or one group of a sweep's ranks).
#pragma once

#include <mpi.h>

#include <string>

namespace hpcontact::linalg {

enum class DistributedSolver {
  serial,          ///< one process (CHOLMOD)
  substructuring,  ///< SubstructuredCholesky: CHOLMOD per rank, the dense interface problem over the
                   ///< ranks by ScaLAPACK
  mumps,           ///< DistributedCholesky: PETSc MPIAIJ + MUMPS, S_T by its Schur interface
  bddc,            ///< BddcSolver: PETSc MATIS + conjugate gradients with PCBDDC
  gamg,            ///< BddcSolver's conjugate gradients on the assembled MPIAIJ with PCGAMG (smoothed
                   ///< aggregation, the rigid motions as its near null space): no factor of K at all
};

struct Distribution {
  DistributedSolver solver = DistributedSolver::serial;
  /// The ranks that share the problem: every collective call of its factorizations and solves
  /// runs on this communicator only (unused when serial). The caller keeps it alive.
  MPI_Comm ranks = MPI_COMM_WORLD;
  bool distributed() const { return solver != DistributedSolver::serial; }
};

/// "substructuring" | "mumps" | "bddc" | "gamg". @throws InputError naming `origin` and `key` otherwise.
DistributedSolver parse_distributed_solver(const std::string& text, const std::string& origin, const std::string& key);
std::string to_string(DistributedSolver solver);
/// `choice` on the ranks of `ranks` when it has more than one, serial otherwise.
Distribution distribution_over(MPI_Comm ranks, DistributedSolver choice);
/// The option --distributed-solver of `solve` and `infsup` on the ranks of `ranks`: `text` empty
/// (not given) is substructuring under mpirun and serial on one rank; a named solver runs on any
/// number of ranks, one included (MUMPS's own options, out of core among them, on one machine).
/// @throws InputError naming `origin` and `key` for another name.
Distribution distribution_named(MPI_Comm ranks, const std::string& text, const std::string& origin,
                                const std::string& key);

}  // namespace hpcontact::linalg
