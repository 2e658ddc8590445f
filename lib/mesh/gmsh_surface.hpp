// Reading a surface mesh of triangles in space from a Gmsh file (or a .geo geometry meshed on the
// fly): the multiplier mesh T_{C,H} of a 3-D contact surface.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "mesh/solid_mesh.hpp"

namespace hpcontact::mesh {

struct SurfaceTriangles {
  std::vector<SolidPoint> vertices;           ///< x, y, z of the corner nodes, in Gmsh's order
  std::vector<std::array<int, 3>> triangles;  ///< indices into vertices
};

/// The triangles of the 2-D cells of `path` (any format Gmsh reads; high-order triangles by their
/// corners: T_{C,H} lies on a flat Γ_C). A .geo file is meshed first into triangles, at most
/// `mesh_size` wide when given (Mesh.MeshSizeMax).
/// @throws InputError naming `path` for unreadable files (with Gmsh's message), files without 2-D
///         cells, quadrilaterals or other 2-D types (naming the type), and a mesh size given with
///         a mesh file.
SurfaceTriangles read_gmsh_surface_triangles(const std::string& path, std::optional<double> mesh_size);

}  // namespace hpcontact::mesh
