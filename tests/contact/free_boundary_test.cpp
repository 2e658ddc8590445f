// Free boundary: locating the ends of the contact set / stick zone on the constraint
// points (exact for a square-root onset). Fitting meshes to them: driver/free_boundary_fit_test.cpp.
#include "contact/free_boundary.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace hpcontact;

namespace {

/// Constraint points s_j = j/n with λ(s_j) = profile(s_j), bounds lo ≤ λ ≤ hi, identity C.
contact::ContactSolution synthetic(int n, const std::function<double(double)>& profile, double lo, double hi) {
  contact::ContactSolution solution;
  solution.lambda.resize(n + 1);
  solution.lower = Eigen::VectorXd::Constant(n + 1, lo);
  solution.upper = Eigen::VectorXd::Constant(n + 1, hi);
  solution.constraint_matrix = Eigen::MatrixXd::Identity(n + 1, n + 1);
  for (int j = 0; j <= n; ++j) {
    solution.constraint_s.push_back(static_cast<double>(j) / n);
    solution.lambda[j] = profile(static_cast<double>(j) / n);
  }
  return solution;
}

}  // namespace

// A square-root onset is located exactly, whichever side is in contact and whichever bound holds:
// Signorini (λ ≤ 0 held at 0 off the contact set) and friction (|λ| ≤ 1 held at -1 in slip).
TEST(FreeBoundary, SquareRootOnsetIsLocatedExactly) {
  const double left = 0.3137, right = 0.7071;
  // Contact on (left, right): λ = -sqrt((s - left)(right - s)), a square root at each end up to
  // a smooth factor, so the estimate is only approximate there; the bracket must hold the end.
  const auto signorini = synthetic(
      40, [&](double s) { return s > left && s < right ? -std::sqrt((s - left) * (right - s)) : 0.0; }, -INFINITY, 0.0);
  // Pure square roots are located exactly.
  const auto contact_left = synthetic(
      40, [&](double s) { return s < right ? -2.0 * std::sqrt(right - s) : 0.0; }, -INFINITY, 0.0);
  auto points = contact::locate_free_boundary(contact_left);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_NEAR(points[0].s, right, 1e-12);
  EXPECT_LE(points[0].bracket_begin, right);
  EXPECT_GE(points[0].bracket_end, right);

  const auto stick_right = synthetic(
      40, [&](double s) { return s > left ? -1.0 + 0.5 * std::sqrt(s - left) : -1.0; }, -1.0, 1.0);
  points = contact::locate_free_boundary(stick_right);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_NEAR(points[0].s, left, 1e-12);

  // Two ends: each bracket holds its end, and the estimate stays inside it.
  points = contact::locate_free_boundary(signorini);
  ASSERT_EQ(points.size(), 2u);
  for (const auto& point : points) {
    EXPECT_LE(point.bracket_begin, point.s);
    EXPECT_GE(point.bracket_end, point.s);
  }
  EXPECT_TRUE(points[0].bracket_begin <= left && left <= points[0].bracket_end);
  EXPECT_TRUE(points[1].bracket_begin <= right && right <= points[1].bracket_end);
}
