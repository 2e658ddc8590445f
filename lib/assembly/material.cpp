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

std::array<double, 4> plane_stress_of(const Material& m, double exx, double eyy, double exy) {
  return {m.lambda * (exx + eyy) + 2 * m.mu * exx, m.lambda * (exx + eyy) + 2 * m.mu * eyy,
          m.out_of_plane * (exx + eyy), 2 * m.mu * exy};
}

double von_mises_of(const std::array<double, 4>& s) {
  const auto [xx, yy, zz, xy] = s;
  return std::sqrt(0.5 * ((xx - yy) * (xx - yy) + (yy - zz) * (yy - zz) + (zz - xx) * (zz - xx)) + 3 * xy * xy);
}

}  // namespace hpcontact::assembly
