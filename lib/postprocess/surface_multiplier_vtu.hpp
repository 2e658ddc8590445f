// A multiplier on the surface mesh T_{C,H} of a 3-D Γ_C (a contact solution's λ or pressure, a
// spurious inf-sup mode) as a VTU of surface cells: each cell of T_{C,H} cut into linear
// quadrilaterals through its lattice of (max(p_C, 1) + 1)² equispaced points, exact at those
// points; no point is shared between cells, so the jumps of the discontinuous multiplier show.
#pragma once

#include <Eigen/Core>
#include <string>

#include "io/vtu_writer.hpp"
#include "space/surface_multiplier_space.hpp"

namespace hpcontact::postprocess {

/// `coefficients` (nodal, shape (multipliers.n_dofs())) as the point field `name`, the cell data
/// "p" being p_C; k · n_dofs coefficients (several multipliers, one after the other) as the
/// fields name_1 … name_k.
io::VtuGrid surface_multiplier_vtu_grid(const space::SurfaceMultiplierSpace& multipliers,
                                        const Eigen::VectorXd& coefficients, const std::string& name);

}  // namespace hpcontact::postprocess
