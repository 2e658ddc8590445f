// The split of one problem's cells over the MPI ranks: recursive coordinate bisection of the cell
// centroids, PT-Scotch on the dual graph (mesh/graph_partition.hpp), and the shorter of the two
// cuts. Bisection cuts uniform meshes straight (PT-Scotch's jagged cut of a 256 × 256 square is
// 14 % longer, and CHOLMOD's factors of the parts 19 % larger); PT-Scotch cuts unstructured and
// graded meshes shorter (up to 42 % on an annulus).
#pragma once

#include <mpi.h>

#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/solid_mesh.hpp"

namespace hpcontact::mesh {

/// The part (0 .. parts-1) of every cell, shape (n_cells). Each step sorts a set of cells by
/// centroid coordinate along the longer side of the centroids' bounding box and splits it where
/// the cells' weights (`cell_weights[c]` > 0) reach the share of the parts on the left; ties break
/// by cell index, so every process computes the same partition. Part weights differ by at most
/// one cell's weight per bisection level (equal weights: the median split, sizes within one cell).
std::vector<int> bisect_cells(const Mesh& mesh, int parts, const std::vector<int>& cell_weights);
/// The same on hexahedra (centroids in space, the longest of three sides); every process that
/// holds the mesh computes the same parts, so no communication is needed.
std::vector<int> bisect_solid_cells(const SolidMesh& mesh, int parts, const std::vector<int>& cell_weights);

/// A partition's cut: the mesh edges and vertices that cells of two or more parts share (each cut
/// edge carries p - 1 interface unknowns at degree p, each vertex one).
struct PartitionInterface {
  int edges = 0;
  int vertices = 0;
};
PartitionInterface partition_interface(const Mesh& mesh, const std::vector<int>& part_of_cell);

/// One part per rank of `ranks`, of equal weight: coordinate bisection or PT-Scotch, whichever
/// cuts fewer edges (bisection on a tie), on the first rank of `ranks` (empty on the others).
/// `mesh` and `cell_weights` are read on the first rank only (the others may pass null and nothing).
/// Collective on `ranks`.
std::vector<int> split_cells_on_first_rank(const Mesh* mesh, const std::vector<int>& cell_weights, MPI_Comm ranks);
/// The same partition on every rank, each of which holds the whole mesh. Collective on `ranks`.
std::vector<int> split_cells_over_ranks(const Mesh& mesh, const std::vector<int>& cell_weights, MPI_Comm ranks);

}  // namespace hpcontact::mesh
