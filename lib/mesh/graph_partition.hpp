// Partition of a mesh's cells over the MPI ranks by PT-Scotch (PETSc's MatPartitioning) on the
// cells' dual graph: parts of equal work with the fewest cut edges, i.e. the smallest interface
// between the ranks' parts (what substructuring's dense interface problem, MUMPS's separators
// and BDDC's coarse space all grow with).
#pragma once

#include <vector>

#include "mesh/mesh.hpp"

namespace hpcontact::mesh {

/// The part (0 .. ranks-1, one per rank of MPI_COMM_WORLD) of every cell. The dual graph joins
/// two cells through each shared edge; a cell weighs its number of vertices (a triangle's
/// unknowns are about 3/4 of a quadrilateral's at the same degree). Each rank hands PT-Scotch the
/// graph rows of one contiguous slice of the cells, so the partition is computed once over the
/// ranks, then gathered on every rank. Collective; on one rank every cell is in part 0.
/// @throws NumericalError if PETSc's partitioner fails.
std::vector<int> partition_cells_by_graph(const Mesh& mesh);

/// Skeleton-independent measure of a partition: the mesh edges and vertices that cells of two or
/// more parts share (each cut edge carries p - 1 interface unknowns at degree p, each vertex one).
struct PartitionInterface {
  int edges = 0;
  int vertices = 0;
};
PartitionInterface partition_interface(const Mesh& mesh, const std::vector<int>& part_of_cell);

}  // namespace hpcontact::mesh
