// Hard cases: degrees up to 16 (u) and 15 (λ), a fine mesh, extreme ratios h/H,
// contact sets that are the whole of Γ_C, empty, or touch tangentially, friction bounds vanishing
// on part of Γ_C or tiny, data scaled by 1e±6, and solver failures reported with residuals.
// Every case checks against an independent path or an exact property, never a stored number.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <iostream>

#include "assembly/poisson_assembly.hpp"
#include "core/error.hpp"
#include "infsup/infsup_analysis.hpp"
#include "linalg/sparse_cholesky.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "operators/poisson_problem.hpp"
#include "postprocess/bound_violation.hpp"
#include "postprocess/fe_function.hpp"
#include "postprocess/point_locator.hpp"
#include "support/contact_fixture.hpp"
#include "support/manufactured_solution.hpp"
#include "support/paper_alpha.hpp"
#include "support/slepc_test_environment.hpp"

using namespace hpcontact;
using contact::ContactProblem;
using hpcontact::testing::ContactData;
using hpcontact::testing::expect_kkt;
using hpcontact::testing::solve_paper_contact;

namespace {

double condition_number(const Eigen::MatrixXd& a) {
  const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(a).eigenvalues();
  return eigenvalues.maxCoeff() / eigenvalues.minCoeff();
}

using hpcontact::testing::paper_alpha;

}  // namespace

// Condition numbers against p, printed as a table and bounded: the element matrix K_T + M_T of
// one cell and the global K on the §7 square with 2 × 2 cells. The Lobatto basis keeps both
// algebraic in p. Independent path: CHOLMOD against a dense Cholesky (LAPACK-style) solve of the
// same K at p = 16, and the solution against the exact one.
TEST(HardCases, DegreeSixteenAssemblyAndSolveStayAccurate) {
  const auto cell = mesh::make_rectangle_mesh({-1, 1, -1, 1}, 1, 1);
  const auto square = mesh::make_paper_square_mesh(2);
  std::cout << "[ condition ] p, cond(K_T + M_T), cond(K) on 2x2 cells\n";
  double previous_global = 0.0;
  for (int p = 1; p <= 16; ++p) {
    const space::H1Space element_space(cell, p), global_space(square, p);
    const auto element = assembly::assemble_volume_matrices(element_space, {.stiffness = true, .mass = true});
    const double element_condition = condition_number(Eigen::MatrixXd(element.stiffness + element.mass));
    const auto global = assembly::assemble_volume_matrices(global_space, {.stiffness = true, .mass = false});
    const double global_condition = condition_number(Eigen::MatrixXd(global.stiffness));
    std::cout << fmt::format("[ condition ] {:2d} {:.3e} {:.3e}\n", p, element_condition, global_condition);
    // Measured: 1.0e4 and 2.4e3 at p = 16, growing like p^3 at most.
    EXPECT_LT(element_condition, 10.0 * std::pow(p, 3) + 10.0) << "p " << p;
    EXPECT_LT(global_condition, 10.0 * std::pow(p, 3) + 10.0) << "p " << p;
    EXPECT_GT(global_condition, previous_global * 0.99) << "p " << p;
    previous_global = global_condition;
  }
  const space::H1Space space(square, 16);
  operators::PoissonData data{hpcontact::testing::manufactured_f,
                              [](const mesh::Point& x, const mesh::Point& normal) {
                                return hpcontact::testing::manufactured_gradient(x).dot(normal);
                              },
                              {}};
  const auto sparse = operators::solve_poisson(space, data).coefficients;
  const auto k = assembly::assemble_volume_matrices(space, {.stiffness = true, .mass = false}).stiffness;
  const Eigen::VectorXd dense = Eigen::MatrixXd(k).llt().solve(Eigen::MatrixXd(k) * sparse);
  EXPECT_LT((dense - sparse).norm(), 1e-11 * sparse.norm());
  const auto point = mesh::Point(0.3, -0.2);
  const postprocess::PointLocator locator(square);
  EXPECT_NEAR(postprocess::evaluate(space, sparse, *locator.locate(point)).value,
              hpcontact::testing::manufactured_u(point), 1e-12);
}

// α at p = 16, p_C = 15: SLEPc and the dense path agree for the stable (h/H = 1/2) and the
// unstable (h/H = 1) pairing, and α is a finite non-negative number.
TEST(HardCases, AlphaAtDegreeSixteenSlepcAgreesWithDense) {
  for (const int m : {2, 4}) {
    const auto slepc = paper_alpha(4, 16, 15, m, infsup::EigenBackend::slepc);
    const auto dense = paper_alpha(4, 16, 15, m, infsup::EigenBackend::dense);
    EXPECT_TRUE(std::isfinite(slepc.alpha) && slepc.alpha >= 0.0);
    EXPECT_NEAR(slepc.alpha, dense.alpha, 1e-8 * std::max(1.0, dense.alpha)) << "m " << m;
    if (m == 2) {
      EXPECT_GT(dense.alpha, 0.1);
    }
  }
}

TEST(HardCases, ContactAtDegreeSixteenReachesKkt) {
  for (auto problem : {ContactProblem::signorini, ContactProblem::friction, ContactProblem::friction_s}) {
    const auto high = solve_paper_contact(problem, 4, 16, 15, 2);
    expect_kkt(high, fmt::format("p 16 pC 15 problem {}", int(problem)));
    // The same problem at p = 8, p_C = 7: energies within the discretization error (the
    // singularity at (1, 0) caps the accuracy at any degree on this mesh).
    const auto lower = solve_paper_contact(problem, 4, 8, 7, 2);
    EXPECT_NEAR(high.energy, lower.energy, 0.01 * std::abs(lower.energy)) << int(problem);
  }
}

// n = 512 (263 169 dofs at p = 1, 256 segments): the solver converges to a KKT point and the energy
// agrees with a p = 3, n = 64 solve.
TEST(HardCases, FineMeshSignorini) {
  const auto fine = solve_paper_contact(ContactProblem::signorini, 512, 1, 0, 256);
  expect_kkt(fine, "n 512");
  const auto reference = solve_paper_contact(ContactProblem::signorini, 64, 3, 1, 32);
  EXPECT_NEAR(fine.energy, reference.energy, 5e-4);
}

// h/H from 1/8 to 4: every ratio reaches a KKT point; where the multiplier mesh is finer than the
// trace space allows (h/H ≥ 2 with p_C = p − 1) S is singular, α is reported as 0 (never NaN or
// negative) by both eigen paths, and u still agrees with a stable pairing.
TEST(HardCases, ExtremeMeshRatios) {
  const int n = 16, p = 2, pc = 1;
  const double stable_energy = solve_paper_contact(ContactProblem::signorini, n, p, pc, n / 2).energy;
  for (const double ratio : {0.125, 0.25, 0.5, 1.0, 2.0, 4.0}) {
    const int m = static_cast<int>(n * ratio);
    const std::string label = fmt::format("h/H {}", ratio);
    for (auto problem : {ContactProblem::signorini, ContactProblem::friction_s}) {
      const auto solution = solve_paper_contact(problem, n, p, pc, m);
      expect_kkt(solution, label);
      if (problem == ContactProblem::signorini && ratio >= 0.5) {
        EXPECT_NEAR(solution.energy, stable_energy, 0.01 * std::abs(stable_energy)) << label;
      }
    }
    const auto slepc = paper_alpha(n, p, pc, m, infsup::EigenBackend::slepc);
    const auto dense = paper_alpha(n, p, pc, m, infsup::EigenBackend::dense);
    EXPECT_TRUE(std::isfinite(slepc.alpha) && slepc.alpha >= 0.0) << label;
    EXPECT_EQ(slepc.singular, dense.singular) << label;
    EXPECT_EQ(dense.singular, ratio >= 2.0) << label;
    if (!dense.singular)
      EXPECT_NEAR(slepc.alpha, dense.alpha, 1e-8) << label;
    else
      EXPECT_EQ(slepc.alpha, 0.0) << label;
  }
}

// The obstacle holds the whole of Γ_C (g = 0 under a strong load), none of it (g far below), or
// touches exactly where the free solution lies (g = γ_C u_free: λ = 0 and u − g = 0 at once).
TEST(HardCases, ContactSetsWholeEmptyAndTangential) {
  const int n = 16, p = 2, pc = 1, m = 8;
  ContactData whole;
  whole.f = [](const mesh::Point&) { return -50.0; };
  whole.obstacle = [](const mesh::Point&) { return 0.0; };
  const auto all = solve_paper_contact(ContactProblem::signorini, n, p, pc, m, {}, whole);
  expect_kkt(all, "whole");
  EXPECT_LT(all.lambda.maxCoeff(), 0.0) << "every nodal value of λ active";

  ContactData never;
  never.obstacle = [](const mesh::Point&) { return -100.0; };
  const auto none = solve_paper_contact(ContactProblem::signorini, n, p, pc, m, {}, never);
  expect_kkt(none, "never");
  EXPECT_EQ(none.lambda.lpNorm<Eigen::Infinity>(), 0.0);
  EXPECT_LE(none.qp.iterations, 2);
  // λ = 0: u is the free solution of −Δu = f with ∂_n u = 0 on Γ_C.
  const auto square = mesh::make_paper_square_mesh(n);
  const space::H1Space space(square, p);
  const auto free = operators::solve_poisson(space, {[](const mesh::Point&) { return -1.0; }, {}, {}}).coefficients;
  EXPECT_LT((none.u - free).lpNorm<Eigen::Infinity>(), 1e-12 * free.lpNorm<Eigen::Infinity>());

  // Tangential: the obstacle is the trace of the free solution.
  const postprocess::PointLocator locator(square);
  ContactData touching;
  touching.obstacle = [&](const mesh::Point& x) {
    return postprocess::evaluate(space, free, *locator.locate(mesh::Point(x.x(), -1.0))).value;
  };
  const auto tangential = solve_paper_contact(ContactProblem::signorini, n, p, pc, m, {}, touching);
  expect_kkt(tangential, "tangential");
  EXPECT_LT(tangential.lambda.lpNorm<Eigen::Infinity>(), 1e-10);
  EXPECT_LT(tangential.gap.lpNorm<Eigen::Infinity>(), 1e-10);
  EXPECT_LT((tangential.u - free).lpNorm<Eigen::Infinity>(), 1e-9 * free.lpNorm<Eigen::Infinity>());
}

// Friction bounds: s = 0 on the right half of Γ_C (supp s ≠ Γ_C), and s = 1e-8 everywhere.
TEST(HardCases, FrictionBoundVanishingOnPartOrTiny) {
  const int n = 16, m = 8;
  ContactData half;
  half.bound = [](const mesh::Point& x) { return x.x() < 0 ? x.x() * x.x() : 0.0; };
  const auto s13 = solve_paper_contact(ContactProblem::friction, n, 2, 1, m, {}, half);
  expect_kkt(s13, "(13) half support");
  // Segments entirely in x > 0 lie outside supp s: λ = 0 there.
  EXPECT_EQ(s13.lambda.tail(m).lpNorm<Eigen::Infinity>(), 0.0);
  EXPECT_GT(s13.lambda.head(m).lpNorm<Eigen::Infinity>(), 0.1);
  const auto s15 = solve_paper_contact(ContactProblem::friction_s, n, 2, 1, m, {}, half);
  expect_kkt(s15, "(15) half support");
  EXPECT_EQ(s15.lambda.tail(m).lpNorm<Eigen::Infinity>(), 0.0);

  ContactData tiny;
  tiny.bound = [](const mesh::Point&) { return 1e-8; };
  for (const int q : {2, 5}) {  // the bounds as coefficient boxes, and as general inequalities
    const auto small = solve_paper_contact(ContactProblem::friction_s, n, 2, 1, m, q, tiny);
    expect_kkt(small, fmt::format("(15) s = 1e-8, q {}", q));
    EXPECT_LE(small.lambda.lpNorm<Eigen::Infinity>(), 1e-8 * (1 + 1e-12));
    EXPECT_GT(small.lambda.lpNorm<Eigen::Infinity>(), 0.5e-8) << "the bound is active somewhere";
  }
}

// Multiplying f, g and s by t scales u and λ by t ((13): λ ∈ M_1 does not scale, u does), with the
// same number of solver iterations, for both solvers; t = 2^±20 scales every operation exactly.
// (13) is the sharp case: S and d scale like t² while the box |λ| ≤ 1 does not, which exposed
// tolerances and a KKT residual that mixed the units of λ and of the gradient.
TEST(HardCases, ScalingTheDataScalesTheSolution) {
  struct Case {
    ContactProblem problem;
    int pc;
    std::optional<int> q;
  };
  for (const auto& c : {Case{ContactProblem::signorini, 1, {}}, Case{ContactProblem::signorini, 2, 6},
                        Case{ContactProblem::friction, 1, {}}, Case{ContactProblem::friction_s, 1, {}},
                        Case{ContactProblem::friction_s, 1, 4}}) {
    const auto reference = solve_paper_contact(c.problem, 8, 3, c.pc, 4, c.q);
    for (const double t : {1e-6, 1e6, std::ldexp(1.0, -20), std::ldexp(1.0, 20)}) {
      ContactData scaled;
      scaled.f = [t](const mesh::Point&) { return -t; };
      scaled.obstacle = [t](const mesh::Point& x) { return -t * x.x() * x.x(); };
      scaled.bound = [t](const mesh::Point& x) { return t * (1.0 - x.x()) * (1.0 - x.x()); };
      const auto solution = solve_paper_contact(c.problem, 8, 3, c.pc, 4, c.q, scaled);
      const std::string label = fmt::format("problem {} pC {} t {}", int(c.problem), c.pc, t);
      expect_kkt(solution, label);
      const double lambda_factor = c.problem == ContactProblem::friction ? 1.0 : t;
      EXPECT_LT((solution.u / t - reference.u).lpNorm<Eigen::Infinity>(), 1e-8 * reference.u.lpNorm<Eigen::Infinity>())
          << label;
      EXPECT_LT((solution.lambda / lambda_factor - reference.lambda).lpNorm<Eigen::Infinity>(),
                1e-8 * reference.lambda.lpNorm<Eigen::Infinity>())
          << label;
      EXPECT_EQ(solution.qp.iterations, reference.qp.iterations) << label;
    }
  }
}

// A solver stopped short is an error carrying its residuals, never a silent answer. A stalled
// active-set method hands over to the interior-point method (reported in the solver report);
// when both are starved the error carries both sets of residuals.
TEST(HardCases, SolverFailuresAreReportedWithResiduals) {
  auto starve_active_set = [](contact::ContactSetup& setup) {
    setup.qp.max_newton = 1;
    setup.qp.max_proximal = 1;
  };
  auto starve_interior_point = [](contact::ContactSetup& setup) { setup.interior_point.max_iterations = 2; };
  auto starve_both = [&](contact::ContactSetup& setup) {
    starve_active_set(setup);
    starve_interior_point(setup);
  };
  const auto rescued = solve_paper_contact(ContactProblem::signorini, 16, 2, 1, 8, {}, {}, starve_active_set);
  EXPECT_EQ(rescued.qp.method, "interior-point");
  EXPECT_NE(rescued.qp.fallback_reason.find("KKT residual"), std::string::npos) << rescued.qp.fallback_reason;
  expect_kkt(rescued, "fallback");
  try {
    solve_paper_contact(ContactProblem::signorini, 16, 2, 1, 8, {}, {}, starve_both);
    FAIL() << "one active-set step and two interior-point iterations cannot solve the §7 problem";
  } catch (const NumericalError& error) {
    EXPECT_NE(std::string(error.what()).find("KKT residual"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("complementarity"), std::string::npos) << error.what();
  }
  try {
    solve_paper_contact(ContactProblem::signorini, 16, 3, 2, 8, 6, {}, starve_interior_point);
    FAIL() << "two interior-point iterations cannot solve the §7 problem";
  } catch (const NumericalError& error) {
    EXPECT_NE(std::string(error.what()).find("complementarity"), std::string::npos) << error.what();
  }
}

// The bound check of the boundary samples: the largest distance outside [lower, upper] relative
// to max |value|, where, and how far from the nearest change between zero and non-zero.
TEST(HardCases, BoundViolationFindsTheWrongSignLobeBesideTheFreeBoundary) {
  // λ = -1 on [0, 0.5), 0 on [0.5, 0.8), +0.1 (wrong sign) at 0.9, 0 after: zone 0; zone 1 all 0.
  const std::vector<double> s{0.0, 0.25, 0.45, 0.55, 0.7, 0.9, 1.0, 1.1, 1.2};
  const std::vector<int> zone{0, 0, 0, 0, 0, 0, 0, 1, 1};
  const std::vector<double> lambda{-1.0, -1.0, -0.5, 0.0, 0.0, 0.1, 0.0, 0.0, 0.0};
  const auto signorini = [](std::size_t) { return std::pair{-std::numeric_limits<double>::infinity(), 0.0}; };
  const auto v = postprocess::bound_violation(s, zone, lambda, signorini);
  EXPECT_DOUBLE_EQ(v.relative, 0.1);
  EXPECT_DOUBLE_EQ(v.s, 0.9);
  ASSERT_TRUE(v.to_free_boundary.has_value());
  EXPECT_NEAR(*v.to_free_boundary, 0.05, 1e-15);  // changes at 0.5, 0.8 and 0.95: the nearest
  const std::vector<double> inside{-1.0, -1.0, -0.5, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  EXPECT_EQ(postprocess::bound_violation(s, zone, inside, signorini).relative, 0.0);
  // A box |λ| ≤ 1: 1.2 is 0.2 outside, relative to max |λ| = 1.2.
  const std::vector<double> box{0.5, 1.2, -0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  EXPECT_NEAR(postprocess::bound_violation(s, zone, box,
                                           [](std::size_t) {
                                             return std::pair{-1.0, 1.0};
                                           })
                  .relative,
              0.2 / 1.2, 1e-15);
}
