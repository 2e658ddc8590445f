// Evaluation of a discrete function u_h ∈ S^p(T_h) (coefficients over the free dofs) and of its
// gradient at reference or physical points.
#pragma once

#include <Eigen/Core>

#include "postprocess/point_locator.hpp"
#include "space/h1_space.hpp"

namespace hpcontact::postprocess {

struct PointValue {
  double value = 0.0;
  Eigen::Vector2d gradient = Eigen::Vector2d::Zero();
};

/// u_h and ∇u_h at a point given in reference coordinates of a cell.
PointValue evaluate(const space::H1Space& space, const Eigen::VectorXd& coefficients, const CellPoint& where);

/// u_h and ∇u_h at a physical point. @throws InputError if x lies outside the mesh.
PointValue evaluate_at(const space::H1Space& space, const Eigen::VectorXd& coefficients, const PointLocator& locator,
                       const mesh::Point& x);

}  // namespace hpcontact::postprocess
