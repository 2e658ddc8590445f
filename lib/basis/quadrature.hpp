// Gauss–Legendre quadrature on [-1,1] (GSL) and its tensor product on [-1,1]².
#pragma once

#include <vector>

namespace hpcontact::basis {

/// n-point Gauss–Legendre rule on [-1,1], exact for polynomials of degree ≤ 2n - 1.
struct QuadratureRule1D {
  std::vector<double> points;   ///< shape (n), ascending
  std::vector<double> weights;  ///< shape (n), sum 2
};

/// @throws InputError if n < 1. Rules are cached: repeated calls are cheap.
const QuadratureRule1D& gauss_legendre(int n);

/// Number of Gauss points that integrates polynomials of degree `degree` exactly.
inline int gauss_points_for_degree(int degree) { return degree / 2 + 1; }

}  // namespace hpcontact::basis
