// build_rank_space: a numbering-only space weighs the cells, the split follows, then the space
// with the rank's cells' shapes, restricted to the rank's part.
#include "operators/rank_space.hpp"

#include <mpi.h>

#include <algorithm>

#include "mesh/cell_partition.hpp"

namespace hpcontact::operators {

RankSpace build_rank_space(const mesh::Mesh& mesh, std::vector<int> cell_degrees, const mesh::ContactBoundary& contact,
                           linalg::Distribution distribution, const RollerMasks* rollers) {
  RankSpace out;
  if (!distribution.distributed()) {
    out.space = std::make_unique<space::H1Space>(mesh, std::move(cell_degrees));
    if (rollers) out.vector_space = std::make_unique<space::VectorSpace>(*out.space, *rollers);
    return out;
  }
  const int components = rollers ? space::kComponents : 1;
  const int n_cells = mesh.n_cells();
  std::vector<char> held(n_cells, 0);
  // Holding no cell, the space still numbers every dof and counts every cell's shapes.
  const space::H1Space numbering(mesh, cell_degrees, space::DirichletDofs::eliminated, held);
  std::vector<int> weights(n_cells);
  for (int c = 0; c < n_cells; ++c) weights[c] = components * numbering.shape_count(c);
  std::vector<int> parts = mesh::split_cells_over_ranks(mesh, weights, distribution.ranks);
  weights = {};
  int rank = 0;
  MPI_Comm_rank(distribution.ranks, &rank);
  for (int c = 0; c < n_cells; ++c) held[c] = parts[c] == rank;
  for (const auto& edge : contact.edges()) held[edge.cell] = 1;
  std::vector<int> cells;
  for (int c = 0; c < n_cells; ++c)
    if (held[c]) cells.push_back(c);
  out.part = std::make_unique<mesh::Mesh>(mesh.extract(cells));
  out.space = std::make_unique<space::H1Space>(numbering.restricted_to(*out.part));
  for (int c : cells) out.cell_parts.push_back(parts[c]);
  // The rollers' unknowns are numbered from the whole mesh's roller edges (boundary-sized).
  if (rollers)
    out.vector_space = std::make_unique<space::VectorSpace>(*out.space, space::VectorSpace(numbering, *rollers));
  if (mesh.has_part(mesh::BoundaryPart::dirichlet)) {
    const space::H1Space kept(mesh, std::move(cell_degrees), space::DirichletDofs::kept, std::vector<char>(n_cells, 0));
    out.kept = std::make_unique<space::H1Space>(kept.restricted_to(*out.part, false));
  }
  return out;
}

WholeMeshFacts::WholeMeshFacts(const mesh::Mesh& mesh, const std::vector<int>& cell_degrees)
    : address_(reinterpret_cast<std::uintptr_t>(&mesh)),
      cells_(mesh.n_cells()),
      vertices_(mesh.n_vertices()),
      edges_(mesh.n_edges()),
      smallest_degree_(cell_degrees.empty() ? 0 : *std::min_element(cell_degrees.begin(), cell_degrees.end())),
      longest_edge_(mesh.longest_edge()),
      has_dirichlet_(mesh.has_part(mesh::BoundaryPart::dirichlet)) {}

bool WholeMeshFacts::is(const mesh::Mesh& mesh) const {
  return reinterpret_cast<std::uintptr_t>(&mesh) == address_ && mesh.n_cells() == cells_ &&
         mesh.n_vertices() == vertices_ && mesh.n_edges() == edges_;
}

bool space_built_on(const space::H1Space& space, const WholeMeshFacts& built_from, const mesh::Mesh& mesh,
                    const std::vector<int>& cell_degrees) {
  if (!built_from.is(mesh) || static_cast<int>(cell_degrees.size()) != mesh.n_cells()) return false;
  const auto& space_mesh = space.mesh();
  for (int c = 0; c < space_mesh.n_cells(); ++c)
    if (space.cell_degree(c) != cell_degrees[space_mesh.global_cell(c)]) return false;
  return true;
}

}  // namespace hpcontact::operators
