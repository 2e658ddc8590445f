// Reading 2-D quadrilateral meshes from Gmsh files through the Gmsh API (MSH 2 and 4, ASCII and
// binary); physical curves become boundary edge labels.
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
/// Vertices are the nodes used by quadrilaterals, in Gmsh's node order; z is ignored. Clockwise
/// quadrilaterals are reversed to counterclockwise.
/// @throws InputError naming `path` for missing or unreadable files (with Gmsh's message), files
///         without quadrilaterals, 2-D elements other than 4-node quadrilaterals (naming the type
///         and the Gmsh option that avoids it), curved lines, curves in several physical groups,
///         and labelled line elements that are not boundary edges of the quadrilateral mesh.
/// A Gmsh geometry file (.geo) is meshed first, into quadrilaterals (gmsh_api::Session::
/// generate_quadrilaterals, elements at most `geo_mesh_size` before the split into quadrilaterals
/// when given; the geometry's physical groups label the edges as in a mesh file).
QuadMesh read_gmsh_mesh(const std::string& path, std::optional<double> geo_mesh_size = {});

}  // namespace hpcontact::mesh
