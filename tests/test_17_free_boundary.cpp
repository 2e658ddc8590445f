// Stage 17, free boundary: locating the ends of the contact set / stick zone on the constraint
// points (exact for a square-root onset), and fitting meshes to them, which is what makes hp
// refinement of the §7 problems converge exponentially (the work–precision references).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "contact/free_boundary.hpp"
#include "driver/free_boundary_fit.hpp"
#include "driver/scene_discretization.hpp"
#include "scene/scene_mesh.hpp"
#include "scene/scene_reader.hpp"

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

namespace {

scene::Scene paper_scene(const std::string& effect, int p, int layers) {
  return scene::parse_scene(fmt::format(R"TOML(
[domain]
n_x = 8
n_y = 8
grading_points = [[1, 0], [1, -1]]
grading = 0.2
grading_layers = {}
[boundary]
contact = "abs(y + 1) < 1e-9"
dirichlet = "abs(y - 1) < 1e-9 || (abs(x - 1) < 1e-9 && y > 0)"
[contact_mesh]
ratio = 1
[discretization]
p = {}
pC = {}
[data]
g = "-x^2"
s = "(1 - x)^2"
[run]
effects = ["{}"]
)TOML",
                                        layers, p, p - 2, effect),
                            "paper_scene.toml");
}

double energy(const scene::Scene& scene, const std::string& effect) {
  return driver::solve_scene_contact(scene, *scene::contact_problem_of(*scene::effect_named(effect))).solution.energy;
}

}  // namespace

// On meshes fitted to the free boundary, raising p from 8 to 10 changes the energy 30 times less
// than on the same meshes graded only at the corners: the fit turns algebraic into exponential
// convergence.
TEST(FreeBoundary, FittedMeshesConvergeExponentially) {
  for (const std::string effect : {"signorini", "friction_s"}) {
    const auto fit = driver::fit_free_boundary(paper_scene(effect, 8, 8),
                                               {*scene::contact_problem_of(*scene::effect_named(effect))});
    EXPECT_EQ(fit.points.size(), effect == "signorini" ? 2u : 1u) << effect;
    EXPECT_LE(fit.moved, 1e-6 * 2.0) << effect;
    EXPECT_LE(fit.solves, 12) << effect;
    auto fitted_p10 = paper_scene(effect, 10, 8);
    fitted_p10.grading_points = fit.scene.grading_points;
    const double fitted_change = std::abs(energy(fit.scene, effect) - energy(fitted_p10, effect));
    const double unfitted_change =
        std::abs(energy(paper_scene(effect, 8, 8), effect) - energy(paper_scene(effect, 10, 8), effect));
    EXPECT_LT(30 * fitted_change, unfitted_change)
        << effect << ": fitted " << fitted_change << ", unfitted " << unfitted_change;
    EXPECT_LT(fitted_change, 3e-9) << effect;
  }
}
