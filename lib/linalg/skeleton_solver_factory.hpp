// make_skeleton_solver: the SkeletonSolver a Distribution names (serial → CHOLMOD, substructuring,
// MUMPS, BDDC), built from each rank's entries of the matrix.
#pragma once

#include <Eigen/SparseCore>
#include <functional>
#include <memory>
#include <vector>

#include "linalg/bddc_solver.hpp"
#include "linalg/distribution.hpp"
#include "linalg/skeleton_solver.hpp"
#include "linalg/sparse_cholesky.hpp"

namespace hpcontact::linalg {

/// The solver of the n × n matrix A = Σ_r A_r that `distribution` names: serial, SparseCholesky
/// (CHOLMOD, this process's entries are all of A); substructuring, SubstructuredCholesky (noting on
/// stderr when its interface problem outweighs the ranks' factors); mumps, DistributedCholesky;
/// bddc, BddcSolver to a relative tolerance of 1e-12. `lower_entries`: this rank's contributions
/// (row ≥ col) to A's lower triangle, summed where they meet (serially freed once the matrix is
/// assembled, before the factorization). `trailing`: the trailing set, the same on every rank.
/// `bddc_hints`: what the rank knows of its subdomain beyond its matrix, asked for by BDDC alone.
/// `ordering`: the serial factor's fill-reducing ordering.
/// Distributed: collective on distribution.ranks.
/// @throws NumericalError if A is not positive definite (or BDDC's set-up fails).
std::unique_ptr<SkeletonSolver> make_skeleton_solver(int n, std::vector<Eigen::Triplet<double>> lower_entries,
                                                     const std::vector<int>& trailing, const Distribution& distribution,
                                                     const std::function<BddcHints()>& bddc_hints = {},
                                                     FillOrdering ordering = FillOrdering::minimum_degree);

}  // namespace hpcontact::linalg
