// α of the §7 square's pairing on n × n cells, degree p, m uniform segments of degree p_C
// (interpolation norm, Signorini): shared by the tests that compare against it.
#pragma once

#include "infsup/infsup_analysis.hpp"
#include "mesh/boundary_mesh.hpp"
#include "mesh/rectangle_mesh.hpp"

namespace hpcontact::testing {

inline infsup::InfSupResult paper_alpha(int n, int p, int pc, int m,
                                        infsup::EigenBackend backend = infsup::EigenBackend::dense) {
  const auto mesh = mesh::make_paper_square_mesh(n);
  const auto boundary = mesh::BoundaryMesh::uniform(2.0, m);
  infsup::InfSupSetup setup;
  setup.mesh = &mesh;
  setup.cell_degrees.assign(mesh.n_cells(), p);
  setup.boundary_mesh = &boundary;
  setup.segment_degrees.assign(m, pc);
  return infsup::analyse_infsup(setup, backend);
}

}  // namespace hpcontact::testing
