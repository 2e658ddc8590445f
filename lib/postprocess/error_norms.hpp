// L², H¹-seminorm (energy) and H¹ errors of u_h against an exact solution.
#pragma once

#include <Eigen/Core>
#include <functional>

#include "space/h1_space.hpp"

namespace hpcontact::postprocess {

struct ExactSolution {
  std::function<double(const mesh::Point&)> value;
  std::function<Eigen::Vector2d(const mesh::Point&)> gradient;
};

struct ErrorNorms {
  double l2 = 0.0;      ///< ‖u - u_h‖_0
  double energy = 0.0;  ///< |u - u_h|_1 = ‖∇(u - u_h)‖_0
  double h1 = 0.0;      ///< ‖u - u_h‖_1 = sqrt(l2² + energy²)
};

/// Integrates with p_T + 4 Gauss points per direction in each cell, so the quadrature error
/// stays far below the discretization error.
ErrorNorms compute_errors(const space::H1Space& space, const Eigen::VectorXd& coefficients, const ExactSolution& exact);

}  // namespace hpcontact::postprocess
