// make_projected_solves: the ConstrainedSolver of CG + GAMG or BDDC (BddcSolver::constrained):
// replicated vectors moved to the rank's owned rows (and node blocks) around
// ProjectedConjugateGradients, which runs on PETSc's set-up operator and preconditioner.
#pragma once

#include <mpi.h>
#include <petscksp.h>

#include <memory>
#include <string>

#include "linalg/constrained_solver.hpp"
#include "linalg/coupling_matrix.hpp"
#include "linalg/node_blocks.hpp"

namespace hpcontact::linalg {

/// Solves on active rows of C (m × n, replicated) with `ksp`'s preconditioner on `a` (its CG's
/// tolerance and iteration limit), the rank owning rows [row_begin, row_end) of the n unknowns;
/// `blocks`: a's node blocks, or null when a's rows are the unknowns'. All must outlive the result.
/// Collective on `ranks`.
std::unique_ptr<ConstrainedSolver> make_projected_solves(MPI_Comm ranks, int n, PetscInt row_begin, PetscInt row_end,
                                                         const NodeBlocks* blocks, Mat a, KSP ksp, const Coupling& c,
                                                         const std::string& name);

}  // namespace hpcontact::linalg
