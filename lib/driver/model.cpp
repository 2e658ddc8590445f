// build_model: the scene's model chosen once, where a run starts.
#include "driver/model.hpp"

#include "driver/elastic_model.hpp"
#include "driver/scalar_model.hpp"
#include "driver/two_body_model.hpp"

namespace hpcontact::driver {

std::unique_ptr<Model> build_model(const scene::Scene& scene, const SceneDiscretization& d, OperatorLog* log,
                                   const linalg::Distribution& distribution) {
  if (scene.pair) return make_two_body_model(scene, d, log, distribution);
  if (scene.is_elastic()) return make_elastic_model(scene, d, log, distribution);
  return make_scalar_model(scene, d, log, distribution);
}

}  // namespace hpcontact::driver
