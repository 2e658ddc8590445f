// TraceFactor: the trace dofs are the columns a full-degree multiplier space on the edges of
// T_h|Γ_C touches (Legendre polynomials up to p span every trace function's restriction).
#include "norms/trace_factor.hpp"

#include <algorithm>

#include "assembly/coupling.hpp"
#include "assembly/poisson_assembly.hpp"
#include "core/timer.hpp"
#include "mesh/boundary_mesh.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::norms {

TraceFactor::TraceFactor(const mesh::QuadMesh& mesh, std::vector<int> cell_degrees) {
  Stopwatch assembly_clock;
  const int p_max = *std::max_element(cell_degrees.begin(), cell_degrees.end());
  space_ = std::make_unique<space::H1Space>(mesh, std::move(cell_degrees));
  contact_ = std::make_unique<mesh::ContactBoundary>(mesh);
  const mesh::BoundaryMesh edges(contact_->breakpoints(), "trace of T_h");
  const space::MultiplierSpace full_trace(edges, p_max);
  const auto trace = linalg::nonzero_columns(assembly::assemble_coupling(*space_, *contact_, full_trace));
  const auto matrices = assembly::assemble_volume_matrices(*space_, {.stiffness = true, .mass = true});
  seconds_assembly_ = assembly_clock.seconds();
  Stopwatch factorization_clock;
  factor_ = std::make_unique<linalg::SparseCholesky>(matrices.stiffness + matrices.mass, trace);
  seconds_factorization_ = factorization_clock.seconds();
}

}  // namespace hpcontact::norms
