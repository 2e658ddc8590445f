// Reading 2-D quadrilateral meshes from Gmsh files through the Gmsh API (MSH 2 and 4, ASCII and
// binary, any order); physical curves become boundary edge labels, curved geometry curved edges.
#pragma once

#include <optional>
#include <string>

#include "mesh/quad_mesh.hpp"

namespace hpcontact::mesh {

/// Reads the 2-D quadrilateral mesh of a Gmsh file (any format Gmsh reads: MSH 2.2, 4.0, 4.1,
/// ASCII or binary). Line elements of a physical curve label the mesh boundary edges with the
/// group's name (or its tag as text if unnamed). Every boundary edge keeps part Neumann; callers
/// map labels to parts.
///
/// Vertices are the corner nodes of quadrilaterals, in Gmsh's node order; z is ignored. Clockwise
/// quadrilaterals are reversed to counterclockwise. High-order quadrilaterals (8, 9, 16, ...
/// nodes) give curved edges through their edge nodes; cells are blended from their sides
/// (mesh/blended_geometry.hpp), so nodes inside cells are not used.
/// @throws InputError naming `path` for missing or unreadable files (with Gmsh's message), files
///         without quadrilaterals, 2-D elements other than quadrilaterals (naming the type and the
///         Gmsh option that avoids it), curves in several physical groups, labelled line elements
///         that are not boundary edges of the quadrilateral mesh, and cells folded by their curves.
/// A Gmsh geometry file (.geo) is meshed first, into first-order quadrilaterals (gmsh_api::Session::
/// generate_quadrilaterals, elements at most `geo_mesh_size` before the split into quadrilaterals
/// when given; the geometry's physical groups label the edges as in a mesh file); edges on its
/// curves other than straight lines follow the exact curve (mesh/gmsh_curves.hpp).
QuadMesh read_gmsh_mesh(const std::string& path, std::optional<double> geo_mesh_size = {});

}  // namespace hpcontact::mesh
