// exact_errors_of.
#include "driver/exact_check.hpp"

#include "core/error.hpp"
#include "driver/scene_discretization.hpp"
#include "postprocess/exact_errors.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::driver {

std::optional<ExactErrors> exact_errors_of(const std::vector<BodyField>& bodies,
                                           const contact::ElasticContactSetup& setup, const Eigen::VectorXd& pressure,
                                           const linalg::Distribution& distribution) {
  const scene::Scene& slave = *bodies.front().scene;
  bool displacement = false;
  for (const auto& body : bodies) displacement = displacement || !body.scene->exact_x.empty();
  if (!displacement && slave.exact_pressure.empty()) return std::nullopt;
  if (distribution.distributed())
    throw InputError(slave.file + ": [exact] is compared in serial runs only; run the scene without mpirun");
  ExactErrors out;
  if (displacement) {
    postprocess::MaxDeviation deviation;
    for (const auto& body : bodies) {
      if (body.scene->exact_x.empty()) continue;
      const auto ux = scene_function(*body.scene, "exact.u_x", body.scene->exact_x);
      const auto uy = scene_function(*body.scene, "exact.u_y", body.scene->exact_y);
      deviation.add(postprocess::displacement_deviation(
          body.u, *body.mesh, [&](const mesh::Point& x) { return Eigen::Vector2d(ux(x), uy(x)); }));
    }
    out.displacement = deviation.relative();
  }
  if (!slave.exact_pressure.empty()) {
    const space::MultiplierSpace multipliers(*setup.boundary_mesh, setup.segment_degrees);
    out.pressure = postprocess::pressure_deviation(multipliers, pressure, setup.operators->contact(),
                                                   scene_function(slave, "exact.pressure", slave.exact_pressure))
                       .relative();
  }
  return out;
}

}  // namespace hpcontact::driver
