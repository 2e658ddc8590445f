// An elastic body as a run's Model: [S^p(T_h)]² with frictionless, Tresca and Coulomb contact and
// the elastic pairings.
#pragma once

#include <memory>

#include "driver/model.hpp"

namespace hpcontact::driver {

/// The elastic model of `scene` with its operators on `d` (see build_model).
std::unique_ptr<Model> make_elastic_model(const scene::Scene& scene, const SceneDiscretization& d, OperatorLog* log,
                                          const linalg::Distribution& distribution);

}  // namespace hpcontact::driver
