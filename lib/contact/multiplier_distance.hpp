// Distances between multipliers on different boundary meshes of the same Γ_C: how far λ_H of one
// discretization is from that of another (a finer reference), in L²(Γ_C).
#pragma once

#include <Eigen/Core>
#include <functional>

#include "space/multiplier_space.hpp"

namespace hpcontact::contact {

/// ‖w (μ_a − μ_b)‖_{L²(Γ_C)} for μ_a ∈ `a` (Legendre coefficients `ca`) and μ_b ∈ `b`, by
/// Gauss–Legendre quadrature on the common refinement of both meshes: exact without a weight, and
/// for weights w(s) (s = arc length) that are polynomials of degree ≤ 2 on each interval. Both
/// meshes must cover the same Γ_C (lengths equal to 1e-10). @throws std::invalid_argument otherwise.
double multiplier_l2_distance(const space::MultiplierSpace& a, const Eigen::VectorXd& ca,
                              const space::MultiplierSpace& b, const Eigen::VectorXd& cb,
                              const std::function<double(double)>& weight = {});

}  // namespace hpcontact::contact
