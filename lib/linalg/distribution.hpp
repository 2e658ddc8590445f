// How one problem's factorizations are spread over the MPI ranks under mpirun (the option
// --distributed-solver of `solve` and `infsup`).
#pragma once

#include <string>

namespace hpcontact::linalg {

enum class Distribution {
  serial,          ///< one process (CHOLMOD)
  substructuring,  ///< SubstructuredCholesky: CHOLMOD per rank, dense interface problem on every
                   ///< rank
  mumps,           ///< DistributedCholesky: PETSc MPIAIJ + MUMPS, S_T by its Schur interface
  bddc,            ///< BddcSolver: PETSc MATIS + conjugate gradients with PCBDDC
};

/// "substructuring" | "mumps" | "bddc". @throws InputError naming `origin` and `key` otherwise.
Distribution parse_distributed_solver(const std::string& text, const std::string& origin, const std::string& key);
std::string to_string(Distribution distribution);
/// `choice` when more than one rank runs, serial otherwise.
Distribution distribution_over(int ranks, Distribution choice);

}  // namespace hpcontact::linalg
