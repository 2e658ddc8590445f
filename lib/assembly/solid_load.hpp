// Load vectors F(v) = ∫_Ω f v on the hexahedral space S^p(T_h).
#pragma once

#include <Eigen/Core>
#include <functional>

#include "space/solid_space.hpp"

namespace hpcontact::assembly {

using SolidFunction = std::function<double(const mesh::SolidPoint&)>;

/// ∫_Ω f φ_i for every free dof i, shape (n_dofs). Integrated with the rule of the element
/// matrices (solid_points_per_axis).
Eigen::VectorXd solid_load(const space::SolidH1Space& space, const SolidFunction& f);

}  // namespace hpcontact::assembly
