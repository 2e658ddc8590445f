// partition_cells_by_graph: the cells' dual graph as a PETSc MPIAdj matrix (one contiguous slice
// of rows per rank), MatPartitioning with PT-Scotch, the parts gathered on every rank.
#include "mesh/graph_partition.hpp"

#include <mpi.h>
#include <petscmat.h>

#include <cstdio>  // ptscotch.h needs FILE (and MPI) declared first
// (the reset below reaches the generator PT-Scotch runs on because libptscotch, linked here, and
// the copy PETSc loads are one library in the process)
#include <ptscotch.h>

#include "core/error.hpp"
#include "core/petsc_check.hpp"
#include "core/petsc_handle.hpp"
#include "core/petsc_session.hpp"
#include "core/rank_agreement.hpp"

namespace hpcontact::mesh {

std::vector<int> partition_cells_by_graph(const Mesh& mesh, const std::vector<int>& cell_weights,
                                          MPI_Comm ranks_sharing) {
  // (not a structured binding: clang 14 refuses to capture one in the lambda below)
  const int rank = rank_and_size(ranks_sharing).first, ranks = rank_and_size(ranks_sharing).second;
  const int n_cells = mesh.n_cells();
  HPC_VERIFY(static_cast<int>(cell_weights.size()) == n_cells, "one weight per cell");
  if (ranks == 1) return std::vector<int>(n_cells, 0);
  const auto slice_begin = [&](int r) { return static_cast<int>(static_cast<long long>(n_cells) * r / ranks); };
  const int begin = slice_begin(rank), end = slice_begin(rank + 1), n_local = end - begin;
  // The MPIAdj matrix takes ownership of its arrays, which must come from PetscMalloc. A rank
  // whose allocation fails must not leave the others waiting in MatCreateMPIAdj: all agree first.
  PetscInt *offsets = nullptr, *neighbours = nullptr, *weights = nullptr;
  try {
    run_on_all_ranks_agreeing(
        [&] {
          HPC_PETSC_CALL(PetscMalloc1(n_local + 1, &offsets));
          HPC_PETSC_CALL(PetscMalloc1(4 * static_cast<std::size_t>(n_local) + 1, &neighbours));
          HPC_PETSC_CALL(PetscMalloc1(n_local + 1, &weights));
        },
        ranks_sharing);
  } catch (...) {  // every rank: those whose allocations succeeded free them too
    PetscFree(offsets);
    PetscFree(neighbours);
    PetscFree(weights);
    throw;
  }
  offsets[0] = 0;
  for (int c = begin; c < end; ++c) {
    PetscInt count = offsets[c - begin];
    for (int k = 0; k < mesh.cell_size(c); ++k) {
      const auto& cells = mesh.edge_cells(mesh.cell_edge(c, k));
      const int other = cells[0] == c ? cells[1] : cells[0];
      if (other >= 0) neighbours[count++] = other;
    }
    offsets[c - begin + 1] = count;
    weights[c - begin] = cell_weights[c];
  }
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
  // Every rank still holds the whole mesh, so every rank needs every cell's part.
  const PetscInt* mine = nullptr;
  HPC_PETSC_CALL(ISGetIndices(parts.get(), &mine));
  std::vector<int> local(mine, mine + n_local);
  HPC_PETSC_CALL(ISRestoreIndices(parts.get(), &mine));
  std::vector<int> counts(ranks), displacements(ranks);
  for (int r = 0; r < ranks; ++r) displacements[r] = slice_begin(r), counts[r] = slice_begin(r + 1) - slice_begin(r);
  std::vector<int> part_of_cell(n_cells);
  HPC_VERIFY(MPI_Allgatherv(local.data(), n_local, MPI_INT, part_of_cell.data(), counts.data(), displacements.data(),
                            MPI_INT, ranks_sharing) == MPI_SUCCESS,
             "gathering the cells' parts failed");
  return part_of_cell;
}

}  // namespace hpcontact::mesh
