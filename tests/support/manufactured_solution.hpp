// The analytic manufactured solution shared by the convergence and contact tests:
// u = sin(1-x) sin(1-y) e^{(x+y)/2}, zero on x = 1 and y = 1, so u ∈ H¹(Ω, Γ_D) of §7.
#pragma once

#include <Eigen/Core>
#include <cmath>

#include "mesh/mesh.hpp"

namespace hpcontact::testing {

inline double manufactured_u(const mesh::Point& p) {
  return std::sin(1 - p.x()) * std::sin(1 - p.y()) * std::exp(0.5 * (p.x() + p.y()));
}

inline Eigen::Vector2d manufactured_gradient(const mesh::Point& p) {
  const double s = std::sin(1 - p.x()), c = std::cos(1 - p.x());
  const double S = std::sin(1 - p.y()), C = std::cos(1 - p.y());
  const double E = std::exp(0.5 * (p.x() + p.y()));
  return {(-c + 0.5 * s) * S * E, s * (-C + 0.5 * S) * E};
}

/// f = -Δu.
inline double manufactured_f(const mesh::Point& p) {
  const double s = std::sin(1 - p.x()), c = std::cos(1 - p.x());
  const double S = std::sin(1 - p.y()), C = std::cos(1 - p.y());
  return std::exp(0.5 * (p.x() + p.y())) * (1.5 * s * S + c * S + s * C);
}

}  // namespace hpcontact::testing
