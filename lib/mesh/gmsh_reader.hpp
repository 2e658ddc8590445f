// Reader for 2-D quadrilateral meshes in Gmsh's MSH 4.0/4.1 ASCII format; physical curves become
// boundary edge labels.
#pragma once

#include <string>

#include "mesh/quad_mesh.hpp"

namespace hpcontact::mesh {

/// Reads a 2-D quadrilateral mesh from a Gmsh MSH 4.x ASCII file. Boundary line elements (type 1)
/// belonging to a physical group label the mesh boundary edges with the group's name (or its number
/// as text if unnamed). Quads: element type 3 (4-node). Every boundary edge keeps part Neumann;
/// callers map labels to parts.
///
/// Vertices are the nodes used by quadrilaterals, in the order of $Nodes (node tags need not be
/// contiguous); z is ignored. Clockwise quadrilaterals are reversed to counterclockwise. Point
/// elements, 3-D entities and sections other than $MeshFormat, $PhysicalNames, $Entities, $Nodes
/// and $Elements are skipped.
/// @throws InputError naming `path` and, where possible, the line, for unreadable, truncated or
///         binary files, versions other than 4.x, 2-D elements other than 4-node quadrilaterals,
///         unknown node tags, curves in several physical groups, and labelled line elements that
///         are not boundary edges of the quadrilateral mesh.
QuadMesh read_gmsh_mesh(const std::string& path);

}  // namespace hpcontact::mesh
