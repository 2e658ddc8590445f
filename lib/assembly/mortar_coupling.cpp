// B^m segment by segment: Gauss points on the slave, their images under Φ on the master's trace.
#include "assembly/mortar_coupling.hpp"

#include <Eigen/SparseCore>
#include <algorithm>
#include <vector>

#include "assembly/cell_values.hpp"
#include "assembly/coupling.hpp"
#include "basis/quadrature.hpp"

namespace hpcontact::assembly {

linalg::Coupling assemble_mortar_coupling(const space::H1Space& master_space, const mesh::MasterProjection& projection,
                                          const mesh::ContactBoundary& slave,
                                          const space::MultiplierSpace& multipliers) {
  const auto& boundary_mesh = multipliers.boundary_mesh();
  check_multiplier_mesh(slave, boundary_mesh);
  const mesh::ContactBoundary& master = projection.master();
  std::vector<Eigen::Triplet<double>> triplets;
  for (const auto& segment : projection.mortar_segments(slave, boundary_mesh.nodes())) {
    if (!segment.covered) continue;
    const int multiplier_segment = boundary_mesh.segment_at(0.5 * (segment.s_begin + segment.s_end));
    const auto& image = master.edges()[segment.master_edge];
    const int p = master_space.cell_degree(image.cell), pc = multipliers.segment_degree(multiplier_segment);
    // Exact for p + p_C where both edges are straight (Φ affine); a curved edge on either side
    // makes φ∘Φ non-polynomial in s: 8 more points, as for the one-body coupling.
    const bool curved = image.arc || slave.edges()[segment.slave_edge].arc;
    const int n_points = basis::gauss_points_for_degree(p + pc) + (curved ? 8 : 0);
    const auto& rule = basis::gauss_legendre(n_points);
    const double half = 0.5 * (segment.s_end - segment.s_begin);
    std::vector<double> t(n_points);
    Eigen::MatrixXd mu(n_points, pc + 1);
    for (int q = 0; q < n_points; ++q) {
      const double s = segment.s_begin + half * (rule.points[q] + 1.0);
      const auto phi = projection.project(slave.point_on_edge(segment.slave_edge, s));
      t[q] = image.local_parameter(std::clamp(phi.s, image.s_begin, image.s_end));
      mu.row(q) =
          rule.weights[q] * half *
          multipliers.basis_values(multiplier_segment, multipliers.local_coordinate(multiplier_segment, s)).transpose();
    }
    const CellValues cell =
        tabulate_cell(master_space, image.cell,
                      edge_reference_points(master_space.mesh().cell_type(image.cell), image.local_edge, t));
    add_cell_coupling(triplets, mu.transpose() * cell.values, master_space.cell_shapes(image.cell),
                      multipliers.first_dof(multiplier_segment));
  }
  linalg::Coupling coupling(multipliers.n_dofs(), master_space.n_dofs());
  coupling.setFromTriplets(triplets.begin(), triplets.end());
  return coupling;
}

}  // namespace hpcontact::assembly
