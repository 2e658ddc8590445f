// The elastic residual estimator: on a smooth manufactured displacement (contact inactive: the
// obstacle far, σ(u)n = 0 on Γ_C) it follows the energy error a(u − u_h, u − u_h)^{1/2} under h and
// under p, its effectivity η / ‖u − u_h‖_E between 1 and 6, and its contact terms vanish. The Hertz
// problem through the adaptive loop is tests/cli/adaptive_test.
#include "adapt/elastic_residual_estimator.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/rectangle_mesh.hpp"
#include "postprocess/elastic_errors.hpp"

using namespace hpcontact;

namespace {

const assembly::Material kMaterial = assembly::lame_parameters(1.0, 0.3, assembly::PlaneModel::strain);

// u = w (sin(x + 2y), cos(2x − y)), w = (1 − x)(1 − y)(1 + y)²: zero on Γ_D of the paper's square
// (the top edge and {1} × [0, 1]), and ∇u = 0 on Γ_C (y = −1), so that Γ_C carries no traction.
double weight(const mesh::Point& p) { return (1 - p.x()) * (1 - p.y()) * (1 + p.y()) * (1 + p.y()); }
Eigen::Vector2d u_exact(const mesh::Point& p) {
  return weight(p) * Eigen::Vector2d(std::sin(p.x() + 2 * p.y()), std::cos(2 * p.x() - p.y()));
}
Eigen::Matrix2d gradient_exact(const mesh::Point& p) {
  const double x = p.x(), y = p.y(), w = weight(p);
  const Eigen::RowVector2d dw(-(1 - y) * (1 + y) * (1 + y), (1 - x) * (2 * (1 - y) * (1 + y) - (1 + y) * (1 + y)));
  const double c = std::cos(x + 2 * y), s2 = std::sin(2 * x - y);
  Eigen::Matrix2d g;
  g.row(0) = std::sin(x + 2 * y) * dw + w * Eigen::RowVector2d(c, 2 * c);
  g.row(1) = std::cos(2 * x - y) * dw + w * Eigen::RowVector2d(-2 * s2, s2);
  return g;
}
Eigen::Matrix2d stress_exact(const mesh::Point& p) {
  const Eigen::Matrix2d g = gradient_exact(p);
  return kMaterial.lambda * g.trace() * Eigen::Matrix2d::Identity() + kMaterial.mu * (g + g.transpose());
}
// f = −div σ(u) by central differences of the exact stress (step 1e-5: error near 1e-10).
Eigen::Vector2d body_force(const mesh::Point& p) {
  constexpr double d = 1e-5;
  const mesh::Point dx(d, 0.0), dy(0.0, d);
  const Eigen::Matrix2d sx = (stress_exact(p + dx) - stress_exact(p - dx)) / (2 * d);
  const Eigen::Matrix2d sy = (stress_exact(p + dy) - stress_exact(p - dy)) / (2 * d);
  return -(sx.col(0) + sy.col(1));
}

struct Measured {
  double estimate = 0.0, error = 0.0;
  adapt::ResidualIndicators indicators;
};

Measured manufactured(int n, int p) {
  const auto mesh = mesh::make_paper_square_mesh(n);
  const operators::ElasticOperators operators(mesh, std::vector<int>(mesh.n_cells(), p),
                                              std::vector<assembly::Material>(mesh.n_cells(), kMaterial));
  const auto boundary = mesh::BoundaryMesh::uniform(2.0, n);
  contact::ElasticContactSetup setup;
  setup.operators = &operators;
  setup.boundary_mesh = &boundary;
  setup.segment_degrees.assign(boundary.n_segments(), std::max(p - 2, 0));
  setup.problem = contact::ElasticContactProblem::frictionless;
  setup.body_force = body_force;
  setup.traction = [](const mesh::Point& x, const mesh::Point& normal) {
    return Eigen::Vector2d(stress_exact(x) * normal);
  };
  setup.gap = [](const mesh::Point&) { return 10.0; };
  const auto solution = contact::solve_elastic_contact(setup);
  Measured out;
  out.indicators = adapt::elastic_residual_indicators(setup, solution);
  out.estimate = std::sqrt(out.indicators.squared());
  out.error = postprocess::compute_elastic_errors(operators.vector_space(), operators.materials(), solution.u,
                                                  {u_exact, gradient_exact})
                  .energy;
  return out;
}

}  // namespace

TEST(ElasticResidualEstimator, FollowsTheEnergyErrorOfASmoothDisplacementUnderHAndP) {
  std::vector<double> effectivity;
  for (const int n : {4, 8, 16}) {
    const auto m = manufactured(n, 2);
    effectivity.push_back(m.estimate / m.error);
    EXPECT_LT(m.indicators.contact, 1e-20) << n;  // no pressure and the gap open: nothing to violate
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
