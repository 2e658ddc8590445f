// Uniform refinement of a mesh (each cell into four), used for reference spaces and convergence
// studies, and the cut of quadrilaterals into triangles.
#pragma once

#include <functional>

#include "mesh/mesh.hpp"

namespace hpcontact::mesh {

/// Splits every quadrilateral at its edge midpoints and its centre Ψ_T(0,0), every triangle at
/// its edge midpoints. Because the restriction of a bilinear (affine) map to a sub-square
/// (sub-triangle) is bilinear (affine), and a curved cell's children keep its blended map
/// restricted, the refined cells cover exactly the same set and the old space is a subspace of the
/// new one. Boundary labels and parts are inherited.
Mesh refine_uniformly(const Mesh& mesh);

/// Cuts the straight quadrilaterals for which `which` holds (all when empty) along their diagonal
/// v0–v2 into the triangles v0 v1 v2 and v0 v2 v3; other cells are kept. Boundary edges keep their
/// labels and parts. @throws InputError naming `origin` if a chosen cell is curved.
Mesh split_into_triangles(const Mesh& mesh, const std::function<bool(int cell)>& which = {},
                          const std::string& origin = "mesh");

}  // namespace hpcontact::mesh
