// partition_cells_by_graph: the cells' dual graph, laid out by the first rank and scattered as a
// PETSc MPIAdj matrix (one contiguous slice of rows per rank), MatPartitioning with PT-Scotch, the
// parts gathered on the first rank.
#include "mesh/graph_partition.hpp"

#include <mpi.h>
#include <petscmat.h>

#include <cstdio>  // ptscotch.h needs FILE (and MPI) declared first
#include <limits>
// (the reset below reaches the generator PT-Scotch runs on because libptscotch, linked here, and
// the copy PETSc loads are one library in the process)
#include <ptscotch.h>

#include "core/error.hpp"
#include "core/petsc_check.hpp"
#include "core/petsc_handle.hpp"
#include "core/petsc_session.hpp"
#include "core/rank_agreement.hpp"

namespace hpcontact::mesh {

std::vector<int> partition_cells_by_graph(const Mesh* mesh, const std::vector<int>& cell_weights,
                                          MPI_Comm ranks_sharing) {
  // (not a structured binding: clang 14 refuses to capture one in the lambda below)
  const int rank = rank_and_size(ranks_sharing).first, ranks = rank_and_size(ranks_sharing).second;
  const bool first = rank == 0;
  if (ranks == 1) {
    HPC_VERIFY(mesh, "partitioning without a mesh");
    return std::vector<int>(mesh->n_cells(), 0);
  }
  // The first rank alone reads the mesh: it lays out every slice's graph rows, as one run of
  // neighbour counts, one of neighbours and one of weights in cell order.
  std::vector<int> row_sizes, all_neighbours, all_weights;
  run_on_all_ranks_agreeing(
      [&] {
        if (!first) return;
        HPC_VERIFY(mesh && static_cast<int>(cell_weights.size()) == mesh->n_cells(), "one weight per cell");
        for (int c = 0; c < mesh->n_cells(); ++c) {
          const auto before = all_neighbours.size();
          for (int k = 0; k < mesh->cell_size(c); ++k) {
            const auto& cells = mesh->edge_cells(mesh->cell_edge(c, k));
            const int other = cells[0] == c ? cells[1] : cells[0];
            if (other >= 0) all_neighbours.push_back(other);
          }
          row_sizes.push_back(static_cast<int>(all_neighbours.size() - before));
        }
        all_weights = cell_weights;
        HPC_VERIFY(all_neighbours.size() <= static_cast<std::size_t>(std::numeric_limits<int>::max()),
                   "the cells' graph has more edges than MPI's int counts can scatter");
      },
      ranks_sharing);
  int n_cells = static_cast<int>(row_sizes.size());
  HPC_VERIFY(MPI_Bcast(&n_cells, 1, MPI_INT, 0, ranks_sharing) == MPI_SUCCESS, "broadcast of the cell count");
  const auto slice_begin = [&](int r) { return static_cast<int>(static_cast<long long>(n_cells) * r / ranks); };
  const int begin = slice_begin(rank), end = slice_begin(rank + 1), n_local = end - begin;
  std::vector<int> cell_counts(ranks), cell_starts(ranks), neighbour_counts(ranks), neighbour_starts(ranks);
  for (int r = 0, at = 0; r < ranks; ++r) {
    cell_starts[r] = slice_begin(r), cell_counts[r] = slice_begin(r + 1) - slice_begin(r);
    neighbour_starts[r] = at;
    if (first)
      for (int c = slice_begin(r); c < slice_begin(r + 1); ++c) at += row_sizes[c];
    neighbour_counts[r] = at - neighbour_starts[r];
  }
  std::vector<int> local_sizes(n_local);
  HPC_VERIFY(MPI_Scatterv(row_sizes.data(), cell_counts.data(), cell_starts.data(), MPI_INT, local_sizes.data(),
                          n_local, MPI_INT, 0, ranks_sharing) == MPI_SUCCESS,
             "scattering the graph's rows failed");
  row_sizes = {};
  int n_local_neighbours = 0;
  for (int size : local_sizes) n_local_neighbours += size;
  // The MPIAdj matrix takes ownership of its arrays, which must come from PetscMalloc. A rank
  // whose allocation fails must not leave the others waiting in MatCreateMPIAdj: all agree first.
  PetscInt *offsets = nullptr, *neighbours = nullptr, *weights = nullptr;
  try {
    run_on_all_ranks_agreeing(
        [&] {
          HPC_PETSC_CALL(PetscMalloc1(n_local + 1, &offsets));
          HPC_PETSC_CALL(PetscMalloc1(n_local_neighbours + 1, &neighbours));
          HPC_PETSC_CALL(PetscMalloc1(n_local + 1, &weights));
        },
        ranks_sharing);
  } catch (...) {  // every rank: those whose allocations succeeded free them too
    PetscFree(offsets);
    PetscFree(neighbours);
    PetscFree(weights);
    throw;
  }
  static_assert(sizeof(PetscInt) == sizeof(int), "the graph is scattered as MPI_INT");
  HPC_VERIFY(MPI_Scatterv(all_neighbours.data(), neighbour_counts.data(), neighbour_starts.data(), MPI_INT, neighbours,
                          n_local_neighbours, MPI_INT, 0, ranks_sharing) == MPI_SUCCESS &&
                 MPI_Scatterv(all_weights.data(), cell_counts.data(), cell_starts.data(), MPI_INT, weights, n_local,
                              MPI_INT, 0, ranks_sharing) == MPI_SUCCESS,
             "scattering the graph's rows failed");
  all_neighbours = {}, all_weights = {};
  offsets[0] = 0;
  for (int c = 0; c < n_local; ++c) offsets[c + 1] = offsets[c] + local_sizes[c];
  PetscHandle<Mat, MatDestroy> graph;
  HPC_PETSC_CALL(MatCreateMPIAdj(ranks_sharing, n_local, n_cells, offsets, neighbours, nullptr, graph.out()));
  PetscHandle<MatPartitioning, MatPartitioningDestroy> partitioning;
  HPC_PETSC_CALL(MatPartitioningCreate(ranks_sharing, partitioning.out()));
  HPC_PETSC_CALL(MatPartitioningSetAdjacency(partitioning.get(), graph.get()));
  HPC_PETSC_CALL(MatPartitioningSetType(partitioning.get(), MATPARTITIONINGPTSCOTCH));
  HPC_PETSC_CALL(MatPartitioningSetVertexWeights(partitioning.get(), weights));
  // Scotch's threads and its random generator, which runs on from call to call, make the parts
  // of one graph differ (K and A_G of one run, two runs of one scene: interface sizes 2284 to
  // 2396 on a 45 056-cell annulus over 2 ranks). One thread (SCOTCH_PTHREAD_NUMBER, set by
  // PetscSession before MPI starts) and a reset make them a function of the graph.
  SCOTCH_randomReset();
  PetscHandle<IS, ISDestroy> parts;
  HPC_PETSC_CALL(MatPartitioningApply(partitioning.get(), parts.out()));
  const PetscInt* mine = nullptr;
  HPC_PETSC_CALL(ISGetIndices(parts.get(), &mine));
  std::vector<int> local(mine, mine + n_local);
  HPC_PETSC_CALL(ISRestoreIndices(parts.get(), &mine));
  std::vector<int> part_of_cell(first ? n_cells : 0);
  HPC_VERIFY(MPI_Gatherv(local.data(), n_local, MPI_INT, part_of_cell.data(), cell_counts.data(), cell_starts.data(),
                         MPI_INT, 0, ranks_sharing) == MPI_SUCCESS,
             "gathering the cells' parts failed");
  return part_of_cell;
}

}  // namespace hpcontact::mesh
