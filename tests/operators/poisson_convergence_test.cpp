// Convergence against a manufactured solution on the paper's §7 square (Γ_D: top edge
// and {1}×[0,1]; Neumann data on the rest): algebraic rates in h for p = 1..6, exponential decay
// in p = 1..12 on straight and perturbed meshes.
#include <gtest/gtest.h>

#include <cmath>

#include "assembly/poisson_assembly.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "operators/poisson_problem.hpp"
#include "postprocess/error_norms.hpp"
#include "space/h1_space.hpp"
#include "support/manufactured_solution.hpp"

using namespace hpcontact;

namespace {

using hpcontact::testing::manufactured_f;
using hpcontact::testing::manufactured_gradient;
using hpcontact::testing::manufactured_u;

postprocess::ErrorNorms solve_and_measure(int n, int p, double perturbation = 0.0) {
  auto m = mesh::make_paper_square_mesh(n);
  if (perturbation > 0) mesh::perturb_interior_vertices(m, perturbation, 5);
  const space::H1Space s(m, p);
  operators::PoissonData data{
      manufactured_f,
      [](const mesh::Point& x, const mesh::Point& normal) { return manufactured_gradient(x).dot(normal); },
      {}};
  return postprocess::compute_errors(s, operators::solve_poisson(s, data).coefficients,
                                     {manufactured_u, manufactured_gradient});
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

// Parallelogram cells take their element matrices from Kronecker products of 1D matrices; on a
// sheared, stretched mesh with mixed degrees (minimum rule, so some edge modes are dropped) and on
// a perturbed mesh (general quadrilaterals, quadrature everywhere) they equal the quadrature path.
TEST(Assembly, KroneckerParallelogramsEqualQuadrature) {
  auto sheared = mesh::make_rectangle_mesh(mesh::Rectangle{0.0, 3.0, -1.0, 0.5}, 5, 3);
  std::vector<mesh::Point> moved;
  for (int v = 0; v < sheared.n_vertices(); ++v) {
    const auto& x = sheared.vertex(v);
    moved.emplace_back(x.x() + 0.4 * x.y(), 0.7 * x.y() - 0.2 * x.x());
  }
  sheared.move_vertices(moved, "test");
  auto perturbed = mesh::make_rectangle_mesh(mesh::Rectangle{}, 4, 4);
  mesh::perturb_interior_vertices(perturbed, 0.2, 7);
  for (const auto* mesh : {&sheared, &perturbed}) {
    std::vector<int> degrees;
    for (int c = 0; c < mesh->n_cells(); ++c) degrees.push_back(1 + (3 * c) % 7);
    const space::H1Space space(*mesh, degrees);
    const auto fast = assembly::assemble_volume_matrices(space, {.stiffness = true, .mass = true});
    const auto quadrature =
        assembly::assemble_volume_matrices(space, {.stiffness = true, .mass = true, .kronecker_parallelograms = false});
    const Eigen::MatrixXd k_difference = Eigen::MatrixXd(fast.stiffness) - Eigen::MatrixXd(quadrature.stiffness);
    const Eigen::MatrixXd m_difference = Eigen::MatrixXd(fast.mass) - Eigen::MatrixXd(quadrature.mass);
    EXPECT_LT(k_difference.cwiseAbs().maxCoeff(), 1e-12 * Eigen::MatrixXd(quadrature.stiffness).cwiseAbs().maxCoeff());
    EXPECT_LT(m_difference.cwiseAbs().maxCoeff(), 1e-12 * Eigen::MatrixXd(quadrature.mass).cwiseAbs().maxCoeff());
    EXPECT_GT(quadrature.stiffness.nonZeros(), 0);
  }
}
