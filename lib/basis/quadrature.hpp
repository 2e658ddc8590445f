// Gauss–Legendre quadrature on [-1,1] (GSL), and the collapsed (Duffy) rules on the reference
// triangle (-1,-1), (1,-1), (-1,1) (also mapped onto any plane triangle) and tetrahedron built from it.
#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

namespace hpcontact::basis {

/// n-point Gauss–Legendre rule on [-1,1], exact for polynomials of degree ≤ 2n - 1.
struct QuadratureRule1D {
  std::vector<double> points;   ///< shape (n), ascending
  std::vector<double> weights;  ///< shape (n), sum 2
};

/// @throws InputError if n < 1. Rules are cached: repeated calls are cheap.
const QuadratureRule1D& gauss_legendre(int n);

/// Points (ξ_q, η_q) and weights of a rule on a 2-D reference cell.
struct QuadratureRule2D {
  std::vector<double> xi, eta, weights;
};

/// The n²-point collapsed rule on the reference triangle: the tensor Gauss rule on the square
/// mapped by ξ = (1 + u)(1 − v)/2 − 1, η = v, weights times (1 − v)/2. Exact for polynomials of
/// total degree ≤ 2n − 2. Cached like gauss_legendre.
const QuadratureRule2D& collapsed_triangle_rule(int n);

/// Points (ξ_q, η_q, ζ_q) and weights of a rule on a 3-D reference cell.
struct QuadratureRule3D {
  std::vector<double> xi, eta, zeta, weights;
};

/// The n³-point collapsed rule on the reference tetrahedron (−1,−1,−1), (1,−1,−1), (−1,1,−1),
/// (−1,−1,1): the tensor Gauss rule on the cube (u, v, w) mapped by ξ = (1 + u)(1 − v)(1 − w)/4 − 1,
/// η = (1 + v)(1 − w)/2 − 1, ζ = w, weights times (1 − v)(1 − w)²/8. Exact for polynomials of total
/// degree ≤ 2n − 3; weights sum to 4/3. Cached like gauss_legendre.
const QuadratureRule3D& collapsed_tetrahedron_rule(int n);

/// collapsed_triangle_rule(n) mapped affinely onto the plane triangle (a0, a1, a2) (either
/// orientation): (point, weight) pairs whose weights sum to its area.
std::vector<std::pair<Eigen::Vector2d, double>> plane_triangle_rule(const Eigen::Vector2d& a0,
                                                                    const Eigen::Vector2d& a1,
                                                                    const Eigen::Vector2d& a2, int n);

/// Number of Gauss points that integrates polynomials of degree `degree` exactly.
inline int gauss_points_for_degree(int degree) { return degree / 2 + 1; }

}  // namespace hpcontact::basis
