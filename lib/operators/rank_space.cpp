// build_rank_space: a numbering-only space weighs the cells, the split follows, then the space
// with the rank's cells' shapes.
#include "operators/rank_space.hpp"

#include <mpi.h>

#include "mesh/cell_partition.hpp"

namespace hpcontact::operators {

RankSpace build_rank_space(const mesh::Mesh& mesh, std::vector<int> cell_degrees, const mesh::ContactBoundary& contact,
                           int components, linalg::Distribution distribution) {
  RankSpace out;
  if (!distribution.distributed()) {
    out.space = std::make_unique<space::H1Space>(mesh, std::move(cell_degrees));
    return out;
  }
  const int n_cells = mesh.n_cells();
  std::vector<char> held(n_cells, 0);
  {
    // Holding no cell, the space still numbers every dof and counts every cell's shapes.
    const space::H1Space numbering(mesh, cell_degrees, space::DirichletDofs::eliminated, held);
    std::vector<int> weights(n_cells);
    for (int c = 0; c < n_cells; ++c) weights[c] = components * numbering.shape_count(c);
    out.cell_parts = mesh::split_cells_over_ranks(mesh, weights, distribution.ranks);
  }
  int rank = 0;
  MPI_Comm_rank(distribution.ranks, &rank);
  for (int c = 0; c < n_cells; ++c) held[c] = out.cell_parts[c] == rank;
  for (const auto& edge : contact.edges()) held[edge.cell] = 1;
  out.space = std::make_unique<space::H1Space>(mesh, std::move(cell_degrees), space::DirichletDofs::eliminated, held);
  return out;
}

}  // namespace hpcontact::operators
