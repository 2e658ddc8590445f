// Uniform refinement of a quadrilateral mesh (each cell into four), used for reference spaces.
#pragma once

#include "mesh/quad_mesh.hpp"

namespace hpcontact::mesh {

/// Splits every cell at its edge midpoints and its centre Ψ_T(0,0). Because the restriction of
/// a bilinear map to a sub-square is bilinear, and a curved cell's children keep its blended map
/// restricted, the refined cells cover exactly the same set and the old space is a subspace of the
/// new one. Boundary labels and parts are inherited.
QuadMesh refine_uniformly(const QuadMesh& mesh);

}  // namespace hpcontact::mesh
