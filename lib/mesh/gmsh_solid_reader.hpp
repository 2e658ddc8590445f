// Reading 3-D meshes of hexahedra or tetrahedra from Gmsh files (mesh files, or .geo geometries meshed on the
// fly) through the Gmsh API; physical surfaces become the labels of boundary faces.
#pragma once

#include <string>

#include "mesh/gmsh_reader.hpp"
#include "mesh/solid_mesh.hpp"

namespace hpcontact::mesh {

/// The dimension of the model of a Gmsh file: a mesh file's highest element dimension, a .geo's
/// highest entity dimension (3 when it defines a volume), without meshing it.
/// @throws InputError naming `path` if Gmsh cannot read it.
int gmsh_file_dimension(const std::string& path);

/// Reads the hexahedral or tetrahedral mesh of a Gmsh file (MSH 2.2, 4.0, 4.1, ASCII or binary).
/// A .geo geometry is meshed first in 3-D with its own settings (tetrahedra by default;
/// Transfinite Volume with Recombine, or Mesh.SubdivisionAlgorithm = 2, give hexahedra) and
/// Mesh.MeshSizeMax = geo.mesh_size when given (geo.cells does not apply). Quadrilaterals or
/// triangles of a physical surface label the boundary faces they cover with the group's name (its
/// tag as text if unnamed).
///
/// Hexahedra are trilinear maps of their eight corners (Gmsh's corner order turned into the tensor
/// order of SolidMesh; a cell Gmsh lists with negative orientation is mirrored), tetrahedra affine
/// maps of their four; vertices are the corners in Gmsh's node order.
/// @throws InputError naming `path` for missing or unreadable files (with Gmsh's message), files
///         without 3-D elements, 3-D elements other than hexahedra and tetrahedra (naming the
///         type), both kinds in one mesh (a conforming mesh of both needs pyramids), high-order
///         cells (their curved faces would be flattened), physical surfaces holding elements other
///         than the cells' faces or faces that are not boundary faces of the mesh, a face in two
///         physical surfaces, and a mesh_size that gives more than geo.max_cells (estimated before
///         Gmsh meshes as hexahedra, four times the tetrahedra of the same size, naming geo.size_key).
SolidMesh read_gmsh_solid_mesh(const std::string& path, const GeoMeshing& geo = {});

}  // namespace hpcontact::mesh
