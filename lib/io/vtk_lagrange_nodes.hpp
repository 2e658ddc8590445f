// The node order of VTK's Lagrange cells (VTK_LAGRANGE_QUADRILATERAL = 70, VTK_LAGRANGE_TRIANGLE =
// 69) of one order k, as integer lattice coordinates, and where each node sits on our reference
// cells (mesh/reference_cell.hpp), so that writers share nodes between cells by entity.
#pragma once

#include <array>
#include <vector>

#include "assembly/cell_values.hpp"
#include "mesh/reference_cell.hpp"

namespace hpcontact::io {

/// VTK's cell type number of the Lagrange cell on a reference cell.
int vtk_lagrange_cell_type(mesh::CellType type);

/// The nodes of the order-k Lagrange cell in VTK's order, as lattice points (i, j) of the reference
/// cell cut into k steps per direction (i, j ∈ [0, k], and i + j ≤ k on the triangle):
///   quadrilateral  vertices (0,0) (k,0) (k,k) (0,k); edge nodes of edges (0,0)→(k,0), (k,0)→(k,k),
///                  (0,k)→(k,k), (0,0)→(0,k), each in that direction; interior nodes row by row;
///   triangle       vertices (0,0) (k,0) (0,k); edge nodes of (0,0)→(k,0), (k,0)→(0,k), (0,k)→(0,0);
///                  interior nodes as the order k − 3 triangle one step inside, recursively.
/// @pre k >= 1.
std::vector<std::array<int, 2>> vtk_lagrange_lattice(mesh::CellType type, int k);

/// The lattice points as reference points: ξ = -1 + 2i/k, η = -1 + 2j/k.
assembly::ReferencePoints lattice_reference_points(const std::vector<std::array<int, 2>>& lattice, int k);

/// Where a lattice node of a cell lies: on a local vertex, inside a local edge (at `step` steps
/// from the edge's start vertex, in the edge's direction of mesh/reference_cell.hpp), or inside.
struct LatticeEntity {
  enum class Kind { vertex, edge, interior } kind;
  int local = -1;  ///< local vertex or edge
  int step = 0;    ///< edge nodes: 1 … k − 1
};
LatticeEntity lattice_entity(mesh::CellType type, std::array<int, 2> node, int k);

}  // namespace hpcontact::io
