// make_skeleton_solver: one switch over the distributed solvers (the only place that names them
// all), and substructuring's note when its dense interface problem dominates.
#include "linalg/skeleton_solver_factory.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <stdexcept>

#include "core/petsc_session.hpp"
#include "linalg/distributed_cholesky.hpp"
#include "linalg/sparse_cholesky.hpp"
#include "linalg/substructured_cholesky.hpp"

namespace hpcontact::linalg {

namespace {

// Tells the user (once per process, on rank 0) when substructuring's dense interface problem
// outweighs the ranks' factors: adding ranks then costs memory per rank instead of saving it.
void note_if_interface_dominates(const SubstructuredCholesky& factor) {
  static bool noted = false;
  if (noted || mpi_rank_and_size().first != 0 ||
      !interface_outweighs_factors(factor.interface_entries(), factor.mean_factor_nonzeros()))
    return;
  noted = true;
  fmt::print(stderr,
             "hpcontact: note: substructuring's dense interface problem ({} unknowns between the parts (and Γ_C), "
             "{:.0f} MB per rank) outweighs the ranks' sparse factors ({:.0f} MB on average): more ranks gain "
             "little memory per rank; --distributed-solver mumps or bddc hold no interface matrix\n",
             factor.interface_size(), factor.interface_entries() * 8e-6, factor.mean_factor_nonzeros() * 8e-6);
}

}  // namespace

std::unique_ptr<SkeletonSolver> make_skeleton_solver(int n, std::vector<Eigen::Triplet<double>> lower_entries,
                                                     const std::vector<int>& trailing, const Distribution& distribution,
                                                     const std::function<BddcHints()>& bddc_hints,
                                                     FillOrdering ordering) {
  MPI_Comm ranks = distribution.ranks;
  switch (distribution.solver) {
    case DistributedSolver::serial: {
      Eigen::SparseMatrix<double> matrix(n, n);
      matrix.setFromTriplets(lower_entries.begin(), lower_entries.end());
      lower_entries = {};
      return std::make_unique<SparseCholesky>(matrix, trailing, ordering);
    }
    case DistributedSolver::substructuring: {
      auto factor = std::make_unique<SubstructuredCholesky>(ranks, n, lower_entries, trailing);
      note_if_interface_dominates(*factor);
      return factor;
    }
    case DistributedSolver::mumps:
      return std::make_unique<DistributedCholesky>(ranks, n, lower_entries, trailing);
    case DistributedSolver::bddc:
      return std::make_unique<BddcSolver>(ranks, n, lower_entries, 1e-12, bddc_hints ? bddc_hints() : BddcHints{});
    case DistributedSolver::gamg:
      return std::make_unique<BddcSolver>(ranks, n, lower_entries, 1e-12, bddc_hints ? bddc_hints() : BddcHints{},
                                          KrylovPreconditioner::gamg);
  }
  throw std::logic_error("make_skeleton_solver: an unknown distributed solver");
}

}  // namespace hpcontact::linalg
