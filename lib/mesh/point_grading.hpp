// Geometric refinement of a mesh (quadrilaterals, triangles) towards chosen vertices (the geometric meshes of
// hp-FEM for corner and free-boundary singularities), local and conforming: unlike grading a
// tensor mesh towards the lines x = c, y = c, it leaves the rest of the mesh alone and keeps the
// cells shape-regular, so the layers can go as deep as the singularity needs.
#pragma once

#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace hpcontact::mesh {

/// Replaces the star of each vertex P in `centres` (the cells sharing P) by `layers` geometric
/// layers: with S_k(x) = P + ratio^k (x − P), every edge QR of the star's outer boundary gives the
/// trapezoids S_{k+1}Q S_k Q S_k R S_{k+1}R (k = 0 … layers − 1), and each star cell P V1 V2 V3
/// becomes P S_L V1 S_L V2 S_L V3 at the centre (a triangle P V1 V2 becomes P S_L V1 S_L V2, its
/// layers quadrilaterals). The outer boundary is unchanged, so the result
/// is conforming; cells shrink by `ratio` per layer towards P and keep their shape. Boundary
/// edges inherit label and part from the edge they lie on. Vertex indices of the input are kept
/// (new vertices follow); cells outside the stars keep their order and come first. `parents`, if
/// given, receives the input cell that each output cell lies in.
/// @throws InputError naming `origin` if ratio ∉ (0, 1), layers < 0, a centre is not a vertex, or
/// two stars share a cell (centres too close for this mesh: refine it first).
Mesh grade_towards_vertices(const Mesh& mesh, const std::vector<int>& centres, double ratio, int layers,
                            const std::string& origin, std::vector<int>* parents = nullptr);

/// Index of the vertex at `point` (within 1e-9 of the mesh size). @throws InputError naming
/// `origin` if there is none.
int vertex_at(const Mesh& mesh, const Point& point, const std::string& origin);

}  // namespace hpcontact::mesh
