// The paper's scalar model as a run's Model: S^p(T_h) with the contact problems (9), (13), (15)
// and the pairings (11), (22).
#pragma once

#include <memory>

#include "driver/model.hpp"

namespace hpcontact::driver {

/// The scalar model of `scene` with its operators on `d` (see build_model).
std::unique_ptr<Model> make_scalar_model(const scene::Scene& scene, const SceneDiscretization& d, OperatorLog* log,
                                         const linalg::Distribution& distribution);

}  // namespace hpcontact::driver
