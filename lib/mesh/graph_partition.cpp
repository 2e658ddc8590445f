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

namespace {

// The cells' dual graph as the first rank lays it out for scattering: each cell's neighbour count,
// then all neighbours and all weights, in cell order.
struct DualGraph {
  std::vector<int> row_sizes, neighbours, weights;
};

// The dual graph of `mesh` on the first rank of `ranks` (empty on the others, which may pass no
// mesh). Collective: a failure there ends every rank alike.
DualGraph dual_graph_on_first_rank(const Mesh* mesh, const std::vector<int>& cell_weights, MPI_Comm ranks) {
  DualGraph graph;
  const bool first = rank_and_size(ranks).first == 0;
  run_on_all_ranks_agreeing(
      [&] {
        if (!first) return;
        HPC_VERIFY(mesh && static_cast<int>(cell_weights.size()) == mesh->n_cells(), "one weight per cell");
        for (int c = 0; c < mesh->n_cells(); ++c) {
          const auto before = graph.neighbours.size();
          for (int k = 0; k < mesh->cell_size(c); ++k) {
            const auto& cells = mesh->edge_cells(mesh->cell_edge(c, k));
            const int other = cells[0] == c ? cells[1] : cells[0];
            if (other >= 0) graph.neighbours.push_back(other);
          }
          graph.row_sizes.push_back(static_cast<int>(graph.neighbours.size() - before));
        }
        graph.weights = cell_weights;
        HPC_VERIFY(graph.neighbours.size() <= static_cast<std::size_t>(std::numeric_limits<int>::max()),
                   "the cells' graph has more edges than MPI's int counts can scatter");
      },
      ranks);
  return graph;
}

// The rows of the graph each rank receives: one contiguous slice of cells per rank, and where
// each slice's cells and neighbours start in the first rank's arrays (MPI_Scatterv's counts).
struct Slices {
  std::vector<int> cell_counts, cell_starts, neighbour_counts, neighbour_starts;
};

// `row_sizes`: the first rank's (empty elsewhere, where the neighbour counts stay 0: unused).
Slices slice_rows(int n_cells, int ranks, const std::vector<int>& row_sizes) {
  const auto slice_begin = [&](int r) { return static_cast<int>(static_cast<long long>(n_cells) * r / ranks); };
  Slices out{std::vector<int>(ranks), std::vector<int>(ranks), std::vector<int>(ranks), std::vector<int>(ranks)};
  for (int r = 0, at = 0; r < ranks; ++r) {
    out.cell_starts[r] = slice_begin(r), out.cell_counts[r] = slice_begin(r + 1) - slice_begin(r);
    out.neighbour_starts[r] = at;
    if (!row_sizes.empty())
      for (int c = slice_begin(r); c < slice_begin(r + 1); ++c) at += row_sizes[c];
    out.neighbour_counts[r] = at - out.neighbour_starts[r];
  }
  return out;
}

// This rank's rows of the graph in PetscMalloc'd arrays, which the MPIAdj matrix and the
// partitioning take over: CSR offsets and neighbours, one weight per cell.
struct GraphRows {
  int n_rows = 0;
  PetscInt *offsets = nullptr, *neighbours = nullptr, *weights = nullptr;
};

// Scatters `graph` (the first rank's; emptied here) into each rank's rows. Collective.
GraphRows scatter_rows(DualGraph& graph, const Slices& slices, int rank, MPI_Comm ranks) {
  GraphRows rows;
  rows.n_rows = slices.cell_counts[rank];
  std::vector<int> local_sizes(rows.n_rows);
  HPC_VERIFY(MPI_Scatterv(graph.row_sizes.data(), slices.cell_counts.data(), slices.cell_starts.data(), MPI_INT,
                          local_sizes.data(), rows.n_rows, MPI_INT, 0, ranks) == MPI_SUCCESS,
             "scattering the graph's rows failed");
  graph.row_sizes = {};
  int n_local_neighbours = 0;
  for (int size : local_sizes) n_local_neighbours += size;
  // A rank whose allocation fails must not leave the others waiting in MatCreateMPIAdj: all agree
  // first.
  try {
    run_on_all_ranks_agreeing(
        [&] {
          HPC_PETSC_CALL(PetscMalloc1(rows.n_rows + 1, &rows.offsets));
          HPC_PETSC_CALL(PetscMalloc1(n_local_neighbours + 1, &rows.neighbours));
          HPC_PETSC_CALL(PetscMalloc1(rows.n_rows + 1, &rows.weights));
        },
        ranks);
  } catch (...) {  // every rank: those whose allocations succeeded free them too
    PetscFree(rows.offsets);
    PetscFree(rows.neighbours);
    PetscFree(rows.weights);
    throw;
  }
  static_assert(sizeof(PetscInt) == sizeof(int), "the graph is scattered as MPI_INT");
  HPC_VERIFY(MPI_Scatterv(graph.neighbours.data(), slices.neighbour_counts.data(), slices.neighbour_starts.data(),
                          MPI_INT, rows.neighbours, n_local_neighbours, MPI_INT, 0, ranks) == MPI_SUCCESS &&
                 MPI_Scatterv(graph.weights.data(), slices.cell_counts.data(), slices.cell_starts.data(), MPI_INT,
                              rows.weights, rows.n_rows, MPI_INT, 0, ranks) == MPI_SUCCESS,
             "scattering the graph's rows failed");
  graph = {};
  rows.offsets[0] = 0;
  for (int c = 0; c < rows.n_rows; ++c) rows.offsets[c + 1] = rows.offsets[c] + local_sizes[c];
  return rows;
}

// The part of each of this rank's rows, by PT-Scotch over the ranks (which take over `rows`'s
// arrays). Collective.
std::vector<int> partition_rows(const GraphRows& rows, int n_cells, MPI_Comm ranks) {
  PetscHandle<Mat, MatDestroy> graph;
  HPC_PETSC_CALL(MatCreateMPIAdj(ranks, rows.n_rows, n_cells, rows.offsets, rows.neighbours, nullptr, graph.out()));
  PetscHandle<MatPartitioning, MatPartitioningDestroy> partitioning;
  HPC_PETSC_CALL(MatPartitioningCreate(ranks, partitioning.out()));
  HPC_PETSC_CALL(MatPartitioningSetAdjacency(partitioning.get(), graph.get()));
  HPC_PETSC_CALL(MatPartitioningSetType(partitioning.get(), MATPARTITIONINGPTSCOTCH));
  HPC_PETSC_CALL(MatPartitioningSetVertexWeights(partitioning.get(), rows.weights));
  // Scotch's threads and its random generator, which runs on from call to call, make the parts
  // of one graph differ (K and A_G of one run, two runs of one scene: interface sizes 2284 to
  // 2396 on a 45 056-cell annulus over 2 ranks). One thread (SCOTCH_PTHREAD_NUMBER, set by
  // PetscSession before MPI starts) and a reset make them a function of the graph.
  SCOTCH_randomReset();
  PetscHandle<IS, ISDestroy> parts;
  HPC_PETSC_CALL(MatPartitioningApply(partitioning.get(), parts.out()));
  const PetscInt* mine = nullptr;
  HPC_PETSC_CALL(ISGetIndices(parts.get(), &mine));
  std::vector<int> local(mine, mine + rows.n_rows);
  HPC_PETSC_CALL(ISRestoreIndices(parts.get(), &mine));
  return local;
}

}  // namespace

std::vector<int> partition_cells_by_graph(const Mesh* mesh, const std::vector<int>& cell_weights,
                                          MPI_Comm ranks_sharing) {
  const auto [rank, ranks] = rank_and_size(ranks_sharing);
  if (ranks == 1) {
    HPC_VERIFY(mesh, "partitioning without a mesh");
    return std::vector<int>(mesh->n_cells(), 0);
  }
  // The first rank alone reads the mesh; each rank receives one slice of the graph's rows.
  DualGraph graph = dual_graph_on_first_rank(mesh, cell_weights, ranks_sharing);
  int n_cells = static_cast<int>(graph.row_sizes.size());
  HPC_VERIFY(MPI_Bcast(&n_cells, 1, MPI_INT, 0, ranks_sharing) == MPI_SUCCESS, "broadcast of the cell count");
  const Slices slices = slice_rows(n_cells, ranks, graph.row_sizes);
  const GraphRows rows = scatter_rows(graph, slices, rank, ranks_sharing);
  const std::vector<int> local = partition_rows(rows, n_cells, ranks_sharing);
  std::vector<int> part_of_cell(rank == 0 ? n_cells : 0);
  HPC_VERIFY(MPI_Gatherv(local.data(), rows.n_rows, MPI_INT, part_of_cell.data(), slices.cell_counts.data(),
                         slices.cell_starts.data(), MPI_INT, 0, ranks_sharing) == MPI_SUCCESS,
             "gathering the cells' parts failed");
  return part_of_cell;
}

}  // namespace hpcontact::mesh
