// Errors of a displacement u_h ∈ [S^p(T_h)]² against an exact one: L² and energy norm.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "assembly/elastic_system.hpp"
#include "space/vector_space.hpp"

namespace hpcontact::postprocess {

struct ExactDisplacement {
  std::function<Eigen::Vector2d(const mesh::Point&)> value;
  /// ∇u: row i is the gradient of component i (∂u_i/∂x_j at (i, j)).
  std::function<Eigen::Matrix2d(const mesh::Point&)> gradient;
};

struct ElasticErrors {
  double l2 = 0.0;      ///< ‖u − u_h‖_0
  double energy = 0.0;  ///< ‖u − u_h‖_E = a(u − u_h, u − u_h)^{1/2}
};

/// `u` numbered by space::VectorSpace::dof; p_T + 4 Gauss points per direction in each cell.
ElasticErrors compute_elastic_errors(const space::VectorSpace& vector_space,
                                     const std::vector<assembly::Material>& materials, const Eigen::VectorXd& u,
                                     const ExactDisplacement& exact);

}  // namespace hpcontact::postprocess
