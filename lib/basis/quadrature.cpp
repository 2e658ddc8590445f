// Gauss–Legendre rules from GSL's fixed-order tables and the collapsed triangle and tetrahedron
// rules built from them, cached per size.
#include "basis/quadrature.hpp"

#include <gsl/gsl_integration.h>

#include <cmath>
#include <map>
#include <mutex>

#include "core/error.hpp"

namespace hpcontact::basis {

const QuadratureRule1D& gauss_legendre(int n) {
  if (n < 1) throw_bad_input("quadrature", "points", std::to_string(n), "must be >= 1");
  static std::map<int, QuadratureRule1D> cache;
  static std::mutex mutex;
  std::lock_guard lock(mutex);
  auto [it, inserted] = cache.try_emplace(n);
  if (!inserted) return it->second;
  gsl_integration_glfixed_table* table = gsl_integration_glfixed_table_alloc(n);
  HPC_VERIFY(table != nullptr, "GSL could not allocate a Gauss-Legendre table");
  QuadratureRule1D& rule = it->second;
  rule.points.resize(n);
  rule.weights.resize(n);
  for (int i = 0; i < n; ++i) gsl_integration_glfixed_point(-1.0, 1.0, i, &rule.points[i], &rule.weights[i], table);
  gsl_integration_glfixed_table_free(table);
  return rule;
}

const QuadratureRule2D& collapsed_triangle_rule(int n) {
  const QuadratureRule1D& line = gauss_legendre(n);
  static std::map<int, QuadratureRule2D> cache;
  static std::mutex mutex;
  std::lock_guard lock(mutex);
  auto [it, inserted] = cache.try_emplace(n);
  if (!inserted) return it->second;
  QuadratureRule2D& rule = it->second;
  for (int b = 0; b < n; ++b)
    for (int a = 0; a < n; ++a) {
      const double u = line.points[a], v = line.points[b];
      rule.xi.push_back(0.5 * (1.0 + u) * (1.0 - v) - 1.0);
      rule.eta.push_back(v);
      rule.weights.push_back(line.weights[a] * line.weights[b] * 0.5 * (1.0 - v));
    }
  return rule;
}

const QuadratureRule3D& collapsed_tetrahedron_rule(int n) {
  const QuadratureRule1D& line = gauss_legendre(n);
  static std::map<int, QuadratureRule3D> cache;
  static std::mutex mutex;
  std::lock_guard lock(mutex);
  auto [it, inserted] = cache.try_emplace(n);
  if (!inserted) return it->second;
  QuadratureRule3D& rule = it->second;
  for (int c = 0; c < n; ++c)
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < n; ++a) {
        const double u = line.points[a], v = line.points[b], w = line.points[c];
        rule.xi.push_back(0.25 * (1.0 + u) * (1.0 - v) * (1.0 - w) - 1.0);
        rule.eta.push_back(0.5 * (1.0 + v) * (1.0 - w) - 1.0);
        rule.zeta.push_back(w);
        rule.weights.push_back(line.weights[a] * line.weights[b] * line.weights[c] * (1.0 - v) * (1.0 - w) * (1.0 - w) /
                               8.0);
      }
  return rule;
}

std::vector<std::pair<Eigen::Vector2d, double>> plane_triangle_rule(const Eigen::Vector2d& a0,
                                                                    const Eigen::Vector2d& a1,
                                                                    const Eigen::Vector2d& a2, int n) {
  const Eigen::Vector2d e1 = a1 - a0, e2 = a2 - a0;
  const double area_factor = std::abs(e1(0) * e2(1) - e1(1) * e2(0)) / 4.0;  // (the reference triangle's area is 2)
  const QuadratureRule2D& rule = collapsed_triangle_rule(n);
  std::vector<std::pair<Eigen::Vector2d, double>> out;
  out.reserve(rule.weights.size());
  for (std::size_t q = 0; q < rule.weights.size(); ++q)
    out.emplace_back(a0 + 0.5 * (rule.xi[q] + 1.0) * e1 + 0.5 * (rule.eta[q] + 1.0) * e2,
                     rule.weights[q] * area_factor);
  return out;
}

}  // namespace hpcontact::basis
