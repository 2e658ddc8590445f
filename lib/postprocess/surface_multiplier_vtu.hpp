// A multiplier on the surface mesh T_{C,H} of a 3-D Γ_C (a contact solution's λ or pressure, a
// spurious inf-sup mode) as a VTU of surface cells: each cell of T_{C,H} cut into linear
// quadrilaterals through its lattice of (max(p_C, 1) + 1)² equispaced points, exact at those
// points; no point is shared between cells, so the jumps of the discontinuous multiplier show.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "io/vtu_writer.hpp"
#include "space/surface_multiplier_space.hpp"

namespace hpcontact::postprocess {

/// `coefficients`: one multiplier per name, one after the other (nodal, multipliers.n_dofs() each),
/// as the point fields `names`; the cell data "p" is p_C.
io::VtuGrid surface_multiplier_vtu_grid(const space::SurfaceMultiplierSpace& multipliers,
                                        const Eigen::VectorXd& coefficients, const std::vector<std::string>& names);

}  // namespace hpcontact::postprocess
