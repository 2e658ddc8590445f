// Errors of a finite element function on a hexahedral mesh against a known solution.
#pragma once

#include <Eigen/Core>
#include <functional>

#include "space/solid_space.hpp"

namespace hpcontact::postprocess {

struct SolidErrors {
  double l2 = 0.0;             ///< ‖u − u_h‖_{L²(Ω)}
  double h1_semi = 0.0;        ///< |u − u_h|_{H¹(Ω)}
  double exact_h1_semi = 0.0;  ///< |u|_{H¹(Ω)}, to relate the error to
};

/// The function u_h = Σ_i coefficients(i) φ_i (zero on Γ_D) against u with gradient ∇u, integrated
/// with `extra_points` more Gauss points per axis than the assembly's rule.
SolidErrors solid_errors(const space::SolidH1Space& space, const Eigen::VectorXd& coefficients,
                         const std::function<double(const mesh::SolidPoint&)>& exact,
                         const std::function<Eigen::Vector3d(const mesh::SolidPoint&)>& exact_gradient,
                         int extra_points = 2);

}  // namespace hpcontact::postprocess
