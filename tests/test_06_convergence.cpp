// Stage 6, convergence against a manufactured solution on the paper's §7 square (Γ_D: top edge
// and {1}×[0,1]; Neumann data on the rest): algebraic rates in h for p = 1..6, exponential decay
// in p = 1..12 on straight and perturbed meshes.
#include <gtest/gtest.h>

#include <cmath>

#include "fe/error_norms.hpp"
#include "manufactured_solution.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "problems/poisson_problem.hpp"

using namespace hpcontact;

namespace {

using hpcontact::testing::manufactured_f;
using hpcontact::testing::manufactured_gradient;
using hpcontact::testing::manufactured_u;

fe::ErrorNorms solve_and_measure(int n, int p, double perturbation = 0.0) {
  auto m = mesh::make_paper_square_mesh(n);
  if (perturbation > 0) mesh::perturb_interior_vertices(m, perturbation, 5);
  const space::H1Space s(m, p);
  problems::PoissonData data{manufactured_f, [](const mesh::Point& x, const mesh::Point& normal) {
                               return manufactured_gradient(x).dot(normal);
                             }};
  return fe::compute_errors(s, problems::solve_poisson(s, data).coefficients, {manufactured_u, manufactured_gradient});
}

}  // namespace

TEST(Convergence, EnergyErrorRateIsPUnderUniformRefinement) {
  // Coarsest level per degree chosen so that the two finest levels are asymptotic and the
  // finest error stays far above round-off.
  const int coarse[] = {0, 8, 4, 4, 2, 2, 2};
  for (int p = 1; p <= 6; ++p) {
    const auto a = solve_and_measure(2 * coarse[p], p);
    const auto b = solve_and_measure(4 * coarse[p], p);
    const double rate = std::log2(a.energy / b.energy);
    EXPECT_NEAR(rate, p, 0.2) << "p = " << p << ": errors " << a.energy << " -> " << b.energy;
    // L² converges one order faster (Aubin–Nitsche; the domain has no reentrant corner but
    // the Γ_D/Γ_N junction at (1,0) limits duality, so only ask for more than p + 0.5).
    EXPECT_GT(std::log2(a.l2 / b.l2), p + 0.5) << "p = " << p;
  }
}

TEST(Convergence, ExponentialInPOnFixedMeshes) {
  for (double perturbation : {0.0, 0.2}) {
    std::vector<double> errors;
    for (int p = 1; p <= 12; ++p) errors.push_back(solve_and_measure(2, p, perturbation).energy);
    for (int p = 2; p <= 12; ++p)
      EXPECT_LT(errors[p - 1], 0.6 * errors[p - 2]) << "p = " << p << ", perturbation " << perturbation;
    // Least-squares slope of log(error) against p: an algebraic rate would flatten out.
    double mean_p = 6.5, mean_log = 0.0, covariance = 0.0, variance = 0.0;
    for (double e : errors) mean_log += std::log(e) / 12.0;
    for (int p = 1; p <= 12; ++p) {
      covariance += (p - mean_p) * (std::log(errors[p - 1]) - mean_log);
      variance += (p - mean_p) * (p - mean_p);
    }
    EXPECT_LT(covariance / variance, -1.5) << "perturbation " << perturbation;
    EXPECT_LT(errors.back(), 1e-9) << "perturbation " << perturbation;
  }
}
