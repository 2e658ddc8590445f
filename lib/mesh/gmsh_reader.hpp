// Reading 2-D meshes of triangles and quadrilaterals from Gmsh files through the Gmsh API (MSH 2
// and 4, ASCII and binary, any order); physical curves become boundary edge labels, curved
// geometry curved edges.
#pragma once

#include <limits>
#include <optional>
#include <string>

#include "mesh/mesh.hpp"

namespace hpcontact::mesh {

/// How a .geo geometry is meshed: Gmsh's maximal element size (its own sizes when empty), cells;
/// and the most cells the run can hold: a mesh_size that would give more (cells estimated from the
/// geometry's bounding box over mesh_size²) is refused before Gmsh meshes, naming `size_key` of
/// `size_where`.
struct GeoMeshing {
  std::optional<double> mesh_size;
  GeneratedCells cells = GeneratedCells::quadrilaterals;
  double max_cells = std::numeric_limits<double>::infinity();
  std::string size_where, size_key = "mesh_size", max_cells_reason;
};

/// Reads the 2-D mesh of triangles and/or quadrilaterals of a Gmsh file (any format Gmsh reads:
/// MSH 2.2, 4.0, 4.1, ASCII or binary). Line elements of a physical curve label the mesh boundary edges with the
/// group's name (or its tag as text if unnamed). Every boundary edge keeps part Neumann; callers
/// map labels to parts.
///
/// Vertices are the corner nodes of cells, in Gmsh's node order; z is ignored. Clockwise cells are
/// reversed to counterclockwise. High-order quadrilaterals (8, 9, 16, ... nodes) give curved edges
/// through their edge nodes; cells are blended from their sides (mesh/blended_geometry.hpp), so
/// nodes inside cells are not used. High-order triangles are read by their corners; a curved
/// edge on a triangle is refused (Mesh::set_edge_curve).
/// @throws InputError naming `path` for missing or unreadable files (with Gmsh's message), files
///         without 2-D cells, other 2-D element types (naming the type), curves in several
///         physical groups, labelled line elements that are not boundary edges of the mesh, and
///         cells folded by their curves.
/// A Gmsh geometry file (.geo) is meshed first, into first-order cells (gmsh_api::Session::
/// generate with `geo`; the geometry's physical groups label the edges as in a mesh file); edges
/// on its curves other than straight lines follow the exact curve (mesh/gmsh_curves.hpp).
Mesh read_gmsh_mesh(const std::string& path, const GeoMeshing& geo = {});

}  // namespace hpcontact::mesh
