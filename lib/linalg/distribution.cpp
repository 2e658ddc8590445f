// Distribution: parsing and naming.
#include "linalg/distribution.hpp"

#include "core/error.hpp"
#include "core/petsc_session.hpp"

namespace hpcontact::linalg {

DistributedSolver parse_distributed_solver(const std::string& text, const std::string& origin, const std::string& key) {
  if (text == "substructuring") return DistributedSolver::substructuring;
  if (text == "mumps") return DistributedSolver::mumps;
  if (text == "bddc") return DistributedSolver::bddc;
  if (text == "gamg") return DistributedSolver::gamg;
  throw_bad_input(origin, key, text, "must be one of: substructuring, mumps, bddc, gamg");
}

std::string to_string(DistributedSolver solver) {
  switch (solver) {
    case DistributedSolver::serial:
      return "serial";
    case DistributedSolver::substructuring:
      return "substructuring";
    case DistributedSolver::mumps:
      return "mumps";
    case DistributedSolver::bddc:
      return "bddc";
    case DistributedSolver::gamg:
      return "gamg";
  }
  return "?";
}

Distribution distribution_over(MPI_Comm ranks, DistributedSolver choice) {
  return {rank_and_size(ranks).second > 1 ? choice : DistributedSolver::serial, ranks};
}

Distribution distribution_named(MPI_Comm ranks, const std::string& text, const std::string& origin,
                                const std::string& key) {
  if (text.empty()) return distribution_over(ranks, DistributedSolver::substructuring);
  const DistributedSolver solver = parse_distributed_solver(text, origin, key);
  // (MPI and PETSc start lazily, when a serial run first needs them; a distributed one needs them now)
  HPC_VERIFY(ensure_petsc_initialized(), "--distributed-solver: PETSc could not be started");
  return {solver, ranks};
}

}  // namespace hpcontact::linalg
