// An elastic body as a run's Model: [S^p(T_h)]² with frictionless, Tresca and Coulomb contact and
// the elastic pairings.
#pragma once

#include <memory>

#include "contact/elastic_contact.hpp"
#include "driver/model.hpp"
#include "postprocess/elastic_boundary_samples.hpp"

namespace hpcontact::driver {

/// The elastic model of `scene` with its operators on `d` (see build_model).
std::unique_ptr<Model> make_elastic_model(const scene::Scene& scene, const SceneDiscretization& d, OperatorLog* log,
                                          const linalg::Distribution& distribution);

/// The scene's elastic contact problems as effects, in the order they run.
std::vector<scene::Effect> elastic_problem_effects(const scene::Scene& scene);

/// What a run reports of an elastic contact solve of `seconds` wall time on `setup`.
ContactResult elastic_result(const contact::ElasticContactSetup& setup, const contact::ElasticContactSolution& solution,
                             const postprocess::ElasticBoundarySamples& samples, double seconds);

}  // namespace hpcontact::driver
