// The residual estimator: on a smooth manufactured solution (contact inactive) it converges with
// the energy error under h and under p, its effectivity η / |u − u_h|_1 between 1 and 6 (measured
// 3.9–4.0 under h at p = 2, 4.7–5.6 under p on 4 × 4). The §7 problem (9) is tests/cli/adaptive_test.
#include "adapt/residual_estimator.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/rectangle_mesh.hpp"
#include "postprocess/error_norms.hpp"
#include "support/contact_fixture.hpp"
#include "support/manufactured_solution.hpp"

using namespace hpcontact;

namespace {

struct Measured {
  double estimate = 0.0, error = 0.0;
  adapt::ResidualIndicators indicators;
};

// Signorini with the obstacle far below (λ = 0): the manufactured u with its flux on Γ_N ∪ Γ_C.
Measured manufactured(int n, int p) {
  const auto mesh = mesh::make_paper_square_mesh(n);
  const auto boundary = mesh::BoundaryMesh::uniform(2.0, n);
  auto setup = hpcontact::testing::uniform_setup(mesh, boundary, p, std::max(p - 2, 0));
  setup.f = hpcontact::testing::manufactured_f;
  setup.obstacle = [](const mesh::Point&) { return -10.0; };
  setup.traction = [](const mesh::Point& x, const mesh::Point& normal) {
    return hpcontact::testing::manufactured_gradient(x).dot(normal);
  };
  const auto solution = contact::solve_contact(setup);
  const space::H1Space space(mesh, setup.cell_degrees);
  Measured out;
  out.indicators = adapt::residual_indicators(setup, solution, space);
  out.estimate = std::sqrt(out.indicators.squared());
  out.error = postprocess::compute_errors(
                  space, solution.u, {hpcontact::testing::manufactured_u, hpcontact::testing::manufactured_gradient})
                  .energy;
  return out;
}

}  // namespace

TEST(ResidualEstimator, FollowsTheErrorOfASmoothSolutionUnderHAndP) {
  std::vector<double> effectivity;
  for (const int n : {4, 8, 16}) {
    const auto m = manufactured(n, 2);
    effectivity.push_back(m.estimate / m.error);
    EXPECT_LT(m.indicators.contact, 1e-20) << n;  // λ = 0 and the gap open: nothing to violate
    fmt::print("h: n {} estimate {:.4e} error {:.4e} effectivity {:.3f}\n", n, m.estimate, m.error, effectivity.back());
  }
  for (const int p : {1, 3, 4, 5, 6}) {
    const auto m = manufactured(4, p);
    effectivity.push_back(m.estimate / m.error);
    fmt::print("p: p {} estimate {:.4e} error {:.4e} effectivity {:.3f}\n", p, m.estimate, m.error, effectivity.back());
  }
  for (const double e : effectivity) {
    EXPECT_GE(e, 1.0);
    EXPECT_LE(e, 6.0);
  }
}
