// Partition of a mesh's cells over the MPI ranks by PT-Scotch (PETSc's MatPartitioning) on the
// cells' dual graph: parts of equal work with few cut edges wherever the mesh is unstructured or
// graded (mesh/cell_partition.hpp compares it with coordinate bisection).
#pragma once

#include <mpi.h>

#include <vector>

#include "mesh/mesh.hpp"

namespace hpcontact::mesh {

/// The part (0 .. ranks-1, one per rank of `ranks`) of every cell, on the first rank of `ranks`
/// (empty on the others). The dual graph joins two cells through each shared edge; cell c weighs
/// `cell_weights[c]` (> 0; the factorizations weigh a cell by its unknowns, so a mesh of mixed
/// degrees is balanced by work, not by cells). `mesh` and `cell_weights` are read on the first rank
/// only (the others may pass null and nothing): it hands each rank the graph rows of one contiguous
/// slice of the cells, so that the partition is computed over the ranks while no other rank holds
/// the mesh. Collective on `ranks`; on one rank every cell is in part 0.
/// @throws NumericalError if PETSc's partitioner fails.
std::vector<int> partition_cells_by_graph(const Mesh* mesh, const std::vector<int>& cell_weights, MPI_Comm ranks);

}  // namespace hpcontact::mesh
