// Two elastic bodies in contact as a run's Model: the slave's scene and discretization are the
// run's (T_{C,H} on its Γ_C), the master's are built beside them from the pair's scene; the
// contact problems frictionless, Tresca and Coulomb (contact/two_body_contact.hpp).
#pragma once

#include <memory>

#include "driver/model.hpp"

namespace hpcontact::driver {

/// The model of a two-body scene (scene.pair set) with the slave's operators on `d`.
/// @throws InputError if the run is distributed (two bodies run serially for now).
std::unique_ptr<Model> make_two_body_model(const scene::Scene& scene, const SceneDiscretization& d, OperatorLog* log,
                                           const linalg::Distribution& distribution);

}  // namespace hpcontact::driver
