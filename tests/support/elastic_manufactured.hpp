// A smooth manufactured displacement on the paper's square (-1,1)², zero on Γ_D (the top edge
// and {1} × [0,1], both inside the lines x = 1 and y = 1):
//   u = (1 − x)(1 − y) (sin(x + 2y), cos(2x − y)),
// with its gradient, the body force f = −div σ(u) = −((λ + μ) ∇ div u + μ Δu) and the traction
// σ(u) n, for Lamé parameters (λ, μ).
#pragma once

#include <Eigen/Core>
#include <cmath>

#include "assembly/elastic_system.hpp"
#include "mesh/mesh.hpp"

namespace hpcontact::testing {

inline Eigen::Vector2d elastic_u(const mesh::Point& p) {
  const double x = p.x(), y = p.y(), w = (1 - x) * (1 - y);
  return {w * std::sin(x + 2 * y), w * std::cos(2 * x - y)};
}

inline Eigen::Matrix2d elastic_gradient(const mesh::Point& p) {
  const double x = p.x(), y = p.y(), s = std::sin(x + 2 * y), c = std::cos(x + 2 * y), s2 = std::sin(2 * x - y),
               c2 = std::cos(2 * x - y);
  Eigen::Matrix2d g;
  g << (1 - x) * (1 - y) * c - (1 - y) * s, 2 * (1 - x) * (1 - y) * c - (1 - x) * s,
      -2 * (1 - x) * (1 - y) * s2 - (1 - y) * c2, (1 - x) * (1 - y) * s2 - (1 - x) * c2;
  return g;
}

inline Eigen::Vector2d elastic_body_force(const mesh::Point& p, const assembly::Material& m) {
  const double x = p.x(), y = p.y(), s = std::sin(x + 2 * y), c = std::cos(x + 2 * y), s2 = std::sin(2 * x - y),
               c2 = std::cos(2 * x - y);
  // Second derivatives of u_x and u_y.
  const double xxx = (1 - y) * ((x - 1) * s - 2 * c);
  const double xxy = -2 * (x - 1) * (y - 1) * s + (x - 1) * c + (2 * y - 2) * c + s;
  const double xyy = (4 - 4 * x) * ((y - 1) * s - c);
  const double yxx = (4 - 4 * y) * ((x - 1) * c2 + s2);
  const double yxy = (2 - 2 * x) * s2 + 2 * (x - 1) * (y - 1) * c2 + (y - 1) * s2 + c2;
  const double yyy = (1 - x) * ((y - 1) * c2 - 2 * s2);
  const Eigen::Vector2d grad_div(xxx + yxy, xxy + yyy), laplacian(xxx + xyy, yxx + yyy);
  return -((m.lambda + m.mu) * grad_div + m.mu * laplacian);
}

inline Eigen::Vector2d elastic_traction(const mesh::Point& p, const mesh::Point& normal, const assembly::Material& m) {
  const Eigen::Matrix2d g = elastic_gradient(p);
  const Eigen::Matrix2d stress = m.lambda * g.trace() * Eigen::Matrix2d::Identity() + m.mu * (g + g.transpose());
  return stress * normal;
}

}  // namespace hpcontact::testing
