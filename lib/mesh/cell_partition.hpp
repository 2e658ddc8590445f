// Partition of a mesh's cells into parts of nearly equal size with short interfaces: recursive
// coordinate bisection of the cell centroids (the split of one problem over MPI ranks).
#pragma once

#include <vector>

#include "mesh/mesh.hpp"

namespace hpcontact::mesh {

/// The part (0 .. parts-1) of every cell, shape (n_cells). Each step splits a set of cells at the
/// median centroid coordinate along the longer side of the centroids' bounding box, in sizes
/// proportional to the parts on either side; ties break by cell index, so every process computes
/// the same partition. Part sizes differ by at most one cell per bisection level.
std::vector<int> bisect_cells(const Mesh& mesh, int parts);

}  // namespace hpcontact::mesh
