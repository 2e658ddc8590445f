// solve_poisson.
#include "operators/poisson_problem.hpp"

#include "assembly/poisson_assembly.hpp"
#include "core/timer.hpp"
#include "linalg/sparse_cholesky.hpp"

namespace hpcontact::operators {

PoissonSolution solve_poisson(const space::H1Space& space, const PoissonData& data) {
  PoissonSolution out;
  Stopwatch assembly_clock;
  const auto matrices = assembly::assemble_volume_matrices(space, {.stiffness = true, .mass = false});
  Eigen::VectorXd load = assembly::assemble_volume_load(space, data.f);
  if (data.neumann)
    load += assembly::assemble_boundary_load(space, {mesh::BoundaryPart::neumann, mesh::BoundaryPart::contact},
                                             data.neumann);
  out.assembly_seconds = assembly_clock.seconds();
  Stopwatch solve_clock;
  const linalg::SparseCholesky cholesky(matrices.stiffness);
  out.coefficients = cholesky.solve(load);
  out.solve_seconds = solve_clock.seconds();
  return out;
}

}  // namespace hpcontact::operators
