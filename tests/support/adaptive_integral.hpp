// Reference integrals for the tests: GSL's adaptive quadrature (qagp) with the points where the
// integrand has kinks given, so that the exact integration of the library can be checked against
// an independent path.
#pragma once

#include <gsl/gsl_integration.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace hpcontact::testing {

/// ∫ f(s, data) ds over [min(points), max(points)], the points (sorted here, those within 1e-13
/// of another merged) the breakpoints of the integrand; to 1e-14 absolute or 1e-12 relative.
inline double adaptive_integral(double (*f)(double, void*), void* data, std::vector<double> points) {
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end(), [](double a, double b) { return std::abs(a - b) < 1e-13; }),
               points.end());
  constexpr std::size_t kIntervals = 2000;
  gsl_integration_workspace* workspace = gsl_integration_workspace_alloc(kIntervals);
  gsl_function function{f, data};
  double result = 0.0, error = 0.0;
  gsl_integration_qagp(&function, points.data(), points.size(), 1e-14, 1e-12, kIntervals, workspace, &result, &error);
  gsl_integration_workspace_free(workspace);
  return result;
}

}  // namespace hpcontact::testing
