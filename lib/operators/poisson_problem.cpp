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
  if (data.dirichlet) out.lift = std::make_shared<assembly::DirichletLift>(space, data.dirichlet);
  // With Dirichlet data the load is assembled with Γ_D kept, then moved to u_0's unknowns.
  const space::H1Space& load_space = out.lift ? out.lift->extended_scalar() : space;
  Eigen::VectorXd load = assembly::assemble_volume_load(load_space, data.f);
  if (data.neumann)
    load += assembly::assemble_boundary_load(load_space, {mesh::BoundaryPart::neumann, mesh::BoundaryPart::contact},
                                             data.neumann);
  if (out.lift) load = out.lift->lifted_load(assembly::ScalarCellSystem(space, 1.0, 0.0), load).load;
  out.assembly_seconds = assembly_clock.seconds();
  Stopwatch solve_clock;
  const linalg::SparseCholesky cholesky(matrices.stiffness);
  out.coefficients = cholesky.solve(load);
  out.solve_seconds = solve_clock.seconds();
  return out;
}

}  // namespace hpcontact::operators
