// solve_two_body_contact: the pair's geometry (Φ, the gap), the slave's and the master's coupling
// rows, and the condensed trace solver.
#include "contact/two_body_contact.hpp"

#include <fmt/format.h>

#include "assembly/mortar_coupling.hpp"
#include "core/error.hpp"
#include "mesh/contact_pair_geometry.hpp"

namespace hpcontact::contact {

namespace {

void check_pair(const TwoBodyContactSetup& setup, const mesh::MasterProjection& projection) {
  const auto& slave = setup.slave.operators->contact();
  if (setup.slave.gap)
    throw InputError(
        "two-body contact: a gap function was given, but the gap of two bodies is their distance "
        "(Φ(x) − x)·n along the slave's normal; move a body instead");
  if (setup.slave.operators->distribution().distributed() || setup.master.operators->distribution().distributed())
    throw InputError("two-body contact runs serially for now; run it without mpirun");
  for (const auto& segment : projection.mortar_segments(slave)) {
    if (segment.covered) continue;
    const auto x = slave.point_at(0.5 * (segment.s_begin + segment.s_end));
    throw InputError(fmt::format(
        "two-body contact: the master's Γ_C does not cover the slave's at ({:.6g}, {:.6g}) (arc length {:.6g} to "
        "{:.6g} of {:.6g}); a slave Γ_C that reaches beyond the master's is not supported yet: shorten it",
        x.x(), x.y(), segment.s_begin, segment.s_end, slave.length()));
  }
}

}  // namespace

TwoBodyContactSolution solve_two_body_contact(const TwoBodyContactSetup& setup) {
  HPC_VERIFY(setup.slave.operators && setup.slave.boundary_mesh && setup.master.operators,
             "two-body contact setup without operators or T_{C,H}");
  const auto& slave = setup.slave.operators->contact();
  const mesh::MasterProjection projection(setup.master.operators->contact());
  check_pair(setup, projection);

  TraceBody master_body{setup.master, -1.0, {}};
  master_body.coupling = [&](const space::VectorSpace& space, const space::MultiplierSpace& multipliers,
                             assembly::TraceDirection direction) {
    return assembly::assemble_directional_mortar_coupling(space, projection, slave, multipliers, direction);
  };
  auto solved = solve_on_trace(setup.slave, [&](double s) { return projection.gap(slave, s); },
                               {body_on_own_traces(setup.slave), master_body});
  return {std::move(solved.contact), std::move(solved.bodies.back())};
}

}  // namespace hpcontact::contact
