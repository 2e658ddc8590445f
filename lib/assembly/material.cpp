// Lamé parameters of Young's modulus and Poisson's ratio, checked.
#include "assembly/material.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/error.hpp"

namespace hpcontact::assembly {

std::string to_string(PlaneModel model) { return model == PlaneModel::strain ? "plane_strain" : "plane_stress"; }

Material lame_parameters(double young, double poisson, PlaneModel model) {
  if (!(young > 0.0) || !std::isfinite(young))
    throw InputError(fmt::format("Young's modulus E = {} must be a finite number > 0", young));
  if (!(poisson > -1.0 && poisson < 0.5))
    throw InputError(fmt::format("Poisson's ratio ν = {} must lie in (-1, 0.5)", poisson));
  const double mu = young / (2.0 * (1.0 + poisson));
  const double lambda = model == PlaneModel::strain ? young * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson))
                                                    : young * poisson / (1.0 - poisson * poisson);
  return {lambda, mu, model == PlaneModel::strain ? lambda : 0.0};
}

}  // namespace hpcontact::assembly
