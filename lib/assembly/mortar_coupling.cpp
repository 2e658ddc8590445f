// B^m segment by segment: Gauss points on the slave, their images under Φ on the master's trace.
#include "assembly/mortar_coupling.hpp"

#include <Eigen/SparseCore>
#include <algorithm>
#include <array>
#include <functional>
#include <vector>

#include "assembly/cell_values.hpp"
#include "assembly/coupling.hpp"
#include "basis/quadrature.hpp"

namespace hpcontact::assembly {

namespace {

// The coupling of one covered mortar segment: rows the multipliers of its segment of T_{C,H}
// (from first_multiplier on), columns the shapes of the master cell beneath its image.
struct MortarBlock {
  std::vector<Eigen::MatrixXd> local;  ///< one per weight
  int master_cell = -1;
  int first_multiplier = 0;
};

// ∫ w(s) μ_i φ^m_j∘Φ ds on every covered mortar segment for each weight w of the slave's arc
// length (none: 1, the scalar coupling; the components of n_s or t_s for the directional one), so
// that one call evaluates Φ once for all of them.
std::vector<MortarBlock> mortar_blocks(const space::H1Space& master_space, const mesh::MasterProjection& projection,
                                       const mesh::ContactBoundary& slave, const space::MultiplierSpace& multipliers,
                                       const std::vector<std::function<double(double)>>& weights) {
  const auto& boundary_mesh = multipliers.boundary_mesh();
  check_multiplier_mesh(slave, boundary_mesh);
  const mesh::ContactBoundary& master = projection.master();
  std::vector<MortarBlock> blocks;
  for (const auto& segment : projection.mortar_segments(slave, boundary_mesh.nodes())) {
    if (!segment.covered) continue;
    const int multiplier_segment = boundary_mesh.segment_at(0.5 * (segment.s_begin + segment.s_end));
    const auto& image = master.edges()[segment.master_edge];
    const int p = master_space.cell_degree(image.cell), pc = multipliers.segment_degree(multiplier_segment);
    // Exact for p + p_C where both edges are straight (Φ affine, n_s constant); a curved edge on
    // either side makes φ∘Φ and n_s non-polynomial in s: 8 more points, as for the one-body coupling.
    const bool curved = image.arc || slave.edges()[segment.slave_edge].arc;
    const int n_points = basis::gauss_points_for_degree(p + pc) + (curved ? 8 : 0);
    const auto& rule = basis::gauss_legendre(n_points);
    const double half = 0.5 * (segment.s_end - segment.s_begin);
    std::vector<double> t(n_points);
    const auto n_weights = std::max<std::size_t>(weights.size(), 1);
    std::vector<Eigen::MatrixXd> mu(n_weights, Eigen::MatrixXd(n_points, pc + 1));
    for (int q = 0; q < n_points; ++q) {
      const double s = segment.s_begin + half * (rule.points[q] + 1.0);
      const auto phi = projection.project(slave.point_on_edge(segment.slave_edge, s));
      // At round-off from a master vertex Φ may land on the neighbouring edge: then its arc
      // length, clamped to this edge, gives the parameter.
      t[q] = phi.edge == segment.master_edge ? phi.t
                                             : image.local_parameter(std::clamp(phi.s, image.s_begin, image.s_end));
      const Eigen::RowVectorXd basis =
          rule.weights[q] * half *
          multipliers.basis_values(multiplier_segment, multipliers.local_coordinate(multiplier_segment, s)).transpose();
      for (std::size_t w = 0; w < n_weights; ++w) mu[w].row(q) = (weights.empty() ? 1.0 : weights[w](s)) * basis;
    }
    const CellValues cell =
        tabulate_cell(master_space, image.cell,
                      edge_reference_points(master_space.mesh().cell_type(image.cell), image.local_edge, t));
    MortarBlock block{{}, image.cell, multipliers.first_dof(multiplier_segment)};
    for (const auto& weighted : mu) block.local.push_back(weighted.transpose() * cell.values);
    blocks.push_back(std::move(block));
  }
  return blocks;
}

}  // namespace

linalg::Coupling assemble_mortar_coupling(const space::H1Space& master_space, const mesh::MasterProjection& projection,
                                          const mesh::ContactBoundary& slave,
                                          const space::MultiplierSpace& multipliers) {
  std::vector<Eigen::Triplet<double>> triplets;
  for (const auto& block : mortar_blocks(master_space, projection, slave, multipliers, {}))
    add_cell_coupling(triplets, block.local.front(), master_space.cell_shapes(block.master_cell),
                      block.first_multiplier);
  linalg::Coupling coupling(multipliers.n_dofs(), master_space.n_dofs());
  coupling.setFromTriplets(triplets.begin(), triplets.end());
  return coupling;
}

linalg::Coupling assemble_directional_mortar_coupling(const space::VectorSpace& master_space,
                                                      const mesh::MasterProjection& projection,
                                                      const mesh::ContactBoundary& slave,
                                                      const space::MultiplierSpace& multipliers,
                                                      TraceDirection direction) {
  std::vector<std::function<double(double)>> components;
  for (int c = 0; c < space::kComponents; ++c)
    components.emplace_back([&, c](double s) { return trace_direction(slave, s, direction)(c); });
  std::vector<Eigen::Triplet<double>> triplets;
  for (const auto& block : mortar_blocks(master_space.scalar(), projection, slave, multipliers, components)) {
    const auto& shapes = master_space.scalar().cell_shapes(block.master_cell);
    for (int c = 0; c < space::kComponents; ++c) {
      const Eigen::MatrixXd& local = block.local[static_cast<std::size_t>(c)];
      for (std::size_t j = 0; j < shapes.size(); ++j) {
        const int column = master_space.dof(shapes[j].dof, c);
        for (Eigen::Index i = 0; column >= 0 && i < local.rows(); ++i)
          if (local(i, static_cast<Eigen::Index>(j)) != 0.0)
            triplets.emplace_back(block.first_multiplier + static_cast<int>(i), column,
                                  local(i, static_cast<Eigen::Index>(j)));
      }
    }
  }
  linalg::Coupling coupling(multipliers.n_dofs(), master_space.n_dofs());
  coupling.setFromTriplets(triplets.begin(), triplets.end());
  return coupling;
}

}  // namespace hpcontact::assembly
