// Non-zero Dirichlet data by a lifting (assembly/dirichlet_lift): the lift interpolates data of
// degree ≤ p on Γ_D exactly, the lifted solve agrees with an independent one on globally assembled
// matrices, reproduces solutions in the space, and converges at rate p (exponentially in p) with
// data that do not vanish on Γ_D.
#include "assembly/dirichlet_lift.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "assembly/condensed_factor.hpp"
#include "assembly/coupling.hpp"
#include "assembly/elastic_load.hpp"
#include "assembly/elastic_system.hpp"
#include "assembly/poisson_assembly.hpp"
#include "contact/elastic_contact.hpp"
#include "linalg/sparse_cholesky.hpp"
#include "mesh/boundary_mesh.hpp"
#include "mesh/contact_boundary.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "operators/elastic_operators.hpp"
#include "operators/poisson_problem.hpp"
#include "postprocess/elastic_errors.hpp"
#include "postprocess/error_norms.hpp"
#include "postprocess/fe_function.hpp"
#include "space/h1_space.hpp"
#include "space/multiplier_space.hpp"
#include "support/contact_fixture.hpp"
#include "support/elastic_manufactured.hpp"
#include "support/manufactured_solution.hpp"

using namespace hpcontact;

namespace {

// The §7 manufactured solution plus q = 1 + xy + y²/2 (Δq = 1): u ≠ 0 on Γ_D.
double shifted_u(const mesh::Point& x) {
  return hpcontact::testing::manufactured_u(x) + 1 + x.x() * x.y() + 0.5 * x.y() * x.y();
}
Eigen::Vector2d shifted_gradient(const mesh::Point& x) {
  return hpcontact::testing::manufactured_gradient(x) + Eigen::Vector2d(x.y(), x.x() + x.y());
}
double shifted_f(const mesh::Point& x) { return hpcontact::testing::manufactured_f(x) - 1.0; }

operators::PoissonData shifted_data() {
  return {shifted_f, [](const mesh::Point& x, const mesh::Point& n) { return shifted_gradient(x).dot(n); }, shifted_u};
}

postprocess::ErrorNorms lifted_errors(const mesh::Mesh& mesh, int p) {
  const space::H1Space space(mesh, p);
  const auto solution = operators::solve_poisson(space, shifted_data());
  const auto field = assembly::total_field(solution.lift.get(), space, solution.coefficients);
  return postprocess::compute_errors(field.space, field.coefficients, {shifted_u, shifted_gradient});
}

// u at a point of Γ_D of the paper square: the top edge y = 1 or the right edge x = 1.
double value_at(const assembly::ScalarField& field, const mesh::Point& x) {
  const postprocess::PointLocator locator(field.space.mesh());
  return postprocess::evaluate_at(field.space, field.coefficients, locator, x).value;
}

// The paper square with its vertices numbered backwards: every global edge (lower index to higher)
// runs the other way, so the odd edge modes of Γ_D change sign.
mesh::Mesh reversed_paper_square(int n) {
  const auto mesh = mesh::make_paper_square_mesh(n);
  const int last = mesh.n_vertices() - 1;
  std::vector<mesh::Point> vertices(mesh.vertices().rbegin(), mesh.vertices().rend());
  std::vector<std::array<int, 4>> cells;
  for (int c = 0; c < mesh.n_cells(); ++c) {
    auto cell = mesh.cells()[c];
    for (int& v : cell) v = last - v;
    cells.push_back(cell);
  }
  mesh::Mesh reversed(std::move(vertices), std::move(cells));
  mesh::assign_paper_boundary_parts(reversed);
  return reversed;
}

}  // namespace

TEST(DirichletData, LiftInterpolatesDataOfTheEdgeDegreeExactly) {
  // Cubic along the top edge, quadratic along the right one: exact for p = 3, not for p = 2.
  auto u_d = [](const mesh::Point& x) { return x.x() * x.x() * x.x() - 2 * x.x() * x.y() * x.y() + x.y(); };
  for (const auto& mesh : {mesh::make_paper_square_mesh(4), reversed_paper_square(4)})
    for (int p : {2, 3, 5}) {
      const space::H1Space space(mesh, p);
      const assembly::DirichletLift lift(space, u_d);
      const auto field = assembly::total_field(&lift, space, Eigen::VectorXd::Zero(space.n_dofs()));
      double worst = 0.0;
      for (double t = -0.97; t < 1.0; t += 0.1) {
        worst = std::max(worst, std::abs(value_at(field, {t, 1.0}) - u_d({t, 1.0})));
        worst = std::max(worst, std::abs(value_at(field, {1.0, 0.5 * (t + 1)}) - u_d({1.0, 0.5 * (t + 1)})));
      }
      if (p >= 3)
        EXPECT_LT(worst, 1e-13) << "p = " << p;
      else
        EXPECT_GT(worst, 1e-4) << "p = 2 cannot hold a cubic: the check must be able to fail";
    }
}

TEST(DirichletData, LiftedSolveEqualsTheSolveOnGloballyAssembledMatrices) {
  // Independent path: K and F of the space with Γ_D kept, assembled globally by quadrature,
  // partitioned into free and fixed dofs: K_ff u_f = F_f − K_fD w_D.
  auto mesh = mesh::make_paper_square_mesh(4);
  mesh::perturb_interior_vertices(mesh, 0.2, 3);
  const space::H1Space space(mesh, 4);
  const auto lifted = operators::solve_poisson(space, shifted_data());
  ASSERT_TRUE(lifted.lift);
  const auto& lift = *lifted.lift;
  const auto& full = lift.extended_scalar();
  const auto k =
      assembly::assemble_volume_matrices(full, {.stiffness = true, .kronecker_parallelograms = false}).stiffness;
  Eigen::VectorXd f = assembly::assemble_volume_load(full, shifted_f) +
                      assembly::assemble_boundary_load(full, {mesh::BoundaryPart::neumann, mesh::BoundaryPart::contact},
                                                       shifted_data().neumann);
  const Eigen::VectorXd w = lift.values();
  // The free dofs of `full` are where the lift's embedding points: u = embed(u_0) + w.
  const Eigen::VectorXd marker = lift.total(Eigen::VectorXd::Ones(space.n_dofs())) - w;
  std::vector<int> free;
  for (int i = 0; i < full.n_dofs(); ++i)
    if (marker(i) == 1.0) free.push_back(i);
  ASSERT_EQ(static_cast<int>(free.size()), space.n_dofs());
  const Eigen::VectorXd rhs_full = f - k * w;
  Eigen::SparseMatrix<double> k_ff(space.n_dofs(), space.n_dofs());
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs(space.n_dofs());
  std::vector<int> position(full.n_dofs(), -1);
  for (std::size_t i = 0; i < free.size(); ++i) position[free[i]] = static_cast<int>(i);
  for (int col = 0; col < k.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(k, col); it; ++it)
      if (position[it.row()] >= 0 && position[col] >= 0)
        entries.emplace_back(position[it.row()], position[col], it.value());
  k_ff.setFromTriplets(entries.begin(), entries.end());
  for (std::size_t i = 0; i < free.size(); ++i) rhs(static_cast<Eigen::Index>(i)) = rhs_full(free[i]);
  const Eigen::VectorXd u_f = linalg::SparseCholesky(k_ff).solve(rhs);
  Eigen::VectorXd independent = w;
  for (std::size_t i = 0; i < free.size(); ++i) independent(free[i]) += u_f(static_cast<Eigen::Index>(i));
  const Eigen::VectorXd ours = lift.total(lifted.coefficients);
  EXPECT_LT((ours - independent).lpNorm<Eigen::Infinity>(), 1e-11 * independent.lpNorm<Eigen::Infinity>());
  EXPECT_GT(w.lpNorm<Eigen::Infinity>(), 0.5);  // the data are not zero
}

TEST(DirichletData, ReproducesASolutionInTheSpace) {
  // u = x² + 3xy − y² + 2 is harmonic and in Q_2 on a rectangle mesh: the discrete solution is u.
  auto u = [](const mesh::Point& x) { return x.x() * x.x() + 3 * x.x() * x.y() - x.y() * x.y() + 2; };
  auto gradient = [](const mesh::Point& x) { return Eigen::Vector2d(2 * x.x() + 3 * x.y(), 3 * x.x() - 2 * x.y()); };
  const auto mesh = mesh::make_paper_square_mesh(4);
  const space::H1Space space(mesh, 2);
  const operators::PoissonData data{[](const mesh::Point&) { return 0.0; },
                                    [&](const mesh::Point& x, const mesh::Point& n) { return gradient(x).dot(n); }, u};
  const auto solution = operators::solve_poisson(space, data);
  const auto field = assembly::total_field(solution.lift.get(), space, solution.coefficients);
  const auto errors = postprocess::compute_errors(field.space, field.coefficients, {u, gradient});
  EXPECT_LT(errors.h1, 1e-11);
}

TEST(DirichletData, EnergyErrorRateIsPWithDataOnTheDirichletBoundary) {
  const int coarse[] = {0, 8, 4, 4, 2};
  for (int p = 1; p <= 4; ++p) {
    const auto a = lifted_errors(mesh::make_paper_square_mesh(2 * coarse[p]), p);
    const auto b = lifted_errors(mesh::make_paper_square_mesh(4 * coarse[p]), p);
    EXPECT_NEAR(std::log2(a.energy / b.energy), p, 0.2) << "p = " << p << ": " << a.energy << " -> " << b.energy;
  }
}

TEST(DirichletData, ExponentialInPOnAPerturbedMesh) {
  auto mesh = mesh::make_paper_square_mesh(2);
  mesh::perturb_interior_vertices(mesh, 0.2, 5);
  double previous = lifted_errors(mesh, 1).energy;
  for (int p = 2; p <= 10; ++p) {
    const double error = lifted_errors(mesh, p).energy;
    EXPECT_LT(error, 0.6 * previous) << "p = " << p;
    previous = error;
  }
  EXPECT_LT(previous, 1e-7);
}

namespace {

// The §7 square with the whole right edge in Γ_D, so that Γ_D reaches Γ_C at (1, −1) and the
// constraints see the lift (B w ≠ 0).
mesh::Mesh square_clamped_on_the_right(int n) {
  auto mesh = mesh::make_paper_square_mesh(n);
  mesh::assign_boundary_part(mesh, mesh::BoundaryPart::dirichlet,
                             [](const mesh::Point& x) { return x.x() > 1.0 - 1e-12; });
  return mesh;
}

// An obstacle that keeps all of Γ_C in contact, up to (1, −1) where Γ_D begins.
double touching_obstacle(const mesh::Point& x) { return -0.1 * (1.0 - x.x()); }

// Harmonic and in Q_2, not zero at (1, −1).
double harmonic(const mesh::Point& x) {
  return 0.05 + 0.1 * x.x() - 0.15 * x.y() + 0.04 * (x.x() * x.x() - x.y() * x.y()) + 0.06 * x.x() * x.y();
}
Eigen::Vector2d harmonic_gradient(const mesh::Point& x) {
  return {0.1 + 0.08 * x.x() + 0.06 * x.y(), -0.15 - 0.08 * x.y() + 0.06 * x.x()};
}

}  // namespace

TEST(DirichletData, SignoriniWithHarmonicDataIsTheShiftedSolution) {
  // With u_D = h, obstacle g + h and traction ∂_n h, the discrete solution is ũ + h with the same λ
  // (ũ: u_D = 0, obstacle g), because h lies in S^p (p ≥ 2) and is harmonic. Γ_C is in contact up
  // to Γ_D, so a constraint that missed B w would move λ there.
  const auto mesh = square_clamped_on_the_right(8);
  const auto boundary = mesh::BoundaryMesh::uniform(2.0, 8);
  const hpcontact::testing::ContactData data;
  auto plain = hpcontact::testing::uniform_setup(mesh, boundary, 3, 1);
  plain.f = data.f;
  plain.obstacle = touching_obstacle;
  auto shifted = plain;
  shifted.dirichlet = harmonic;
  shifted.obstacle = [](const mesh::Point& x) { return touching_obstacle(x) + harmonic(x); };
  shifted.traction = [](const mesh::Point& x, const mesh::Point& n) { return harmonic_gradient(x).dot(n); };
  const auto a = contact::solve_contact(plain);
  const auto b = contact::solve_contact(shifted);
  hpcontact::testing::expect_kkt(b, "u_D = h");
  ASSERT_GT(a.lambda.lpNorm<Eigen::Infinity>(), 0.1);
  EXPECT_LT((a.lambda - b.lambda).lpNorm<Eigen::Infinity>(), 1e-9 * a.lambda.lpNorm<Eigen::Infinity>());
  const space::H1Space space(mesh, 3);
  const auto ua = assembly::total_field(nullptr, space, a.u);
  const auto ub = assembly::total_field(b.lift.get(), space, b.u);
  double worst = 0.0;
  for (double x = -0.95; x < 1.0; x += 0.15)
    for (double y = -1.0; y <= 1.0; y += 0.25)
      worst = std::max(worst, std::abs(value_at(ub, {x, y}) - value_at(ua, {x, y}) - harmonic({x, y})));
  EXPECT_LT(worst, 1e-10);
}

TEST(DirichletData, EnergyOfAConstantShift) {
  // u_D = c, obstacle g + c: u = ũ + c, so E = ½ a(ũ, ũ) − (f, ũ + c) = Ẽ − c ∫f = Ẽ + 4c for f = −1.
  const auto mesh = square_clamped_on_the_right(4);
  const auto boundary = mesh::BoundaryMesh::uniform(2.0, 4);
  const hpcontact::testing::ContactData data;
  auto plain = hpcontact::testing::uniform_setup(mesh, boundary, 4, 2);
  plain.f = data.f;
  plain.obstacle = touching_obstacle;
  auto shifted = plain;
  const double c = 0.3;
  shifted.dirichlet = [=](const mesh::Point&) { return c; };
  shifted.obstacle = [=](const mesh::Point& x) { return touching_obstacle(x) + c; };
  const auto a = contact::solve_contact(plain);
  const auto b = contact::solve_contact(shifted);
  EXPECT_NEAR(b.energy, a.energy + 4 * c, 1e-10);
  EXPECT_LT((a.lambda - b.lambda).lpNorm<Eigen::Infinity>(), 1e-9 * a.lambda.lpNorm<Eigen::Infinity>());
}

TEST(DirichletData, FrictionConstraintsSeeTheWholeField) {
  // (13) and (15) with u_D = h touching Γ_C: KKT at the constraint points, and λ · gap equals
  // ∫ λ_H s γ(u_0 + w) (s = 1 for (15)) by the independently assembled coupling of the space with
  // Γ_D kept: the gap is that of the whole field, not of u_0.
  const auto mesh = square_clamped_on_the_right(8);
  const auto boundary = mesh::BoundaryMesh::uniform(2.0, 8);
  const hpcontact::testing::ContactData data;
  for (auto problem : {contact::ContactProblem::friction, contact::ContactProblem::friction_s}) {
    auto setup = hpcontact::testing::uniform_setup(mesh, boundary, 3, 1);
    setup.problem = problem;
    setup.f = data.f;
    setup.bound = data.bound;
    setup.dirichlet = harmonic;
    const auto solution = contact::solve_contact(setup);
    const std::string label = problem == contact::ContactProblem::friction ? "(13)" : "(15)";
    hpcontact::testing::expect_kkt(solution, label);
    const space::MultiplierSpace multipliers(boundary, 1);
    const mesh::ContactBoundary contact(mesh);
    const auto coupling = assembly::assemble_coupling(
        solution.lift->extended_scalar(), contact, multipliers,
        problem == contact::ContactProblem::friction ? data.bound : assembly::BoundaryFunction{});
    const double whole = solution.lambda_legendre.dot(coupling * solution.lift->total(solution.u));
    const double without_lift =
        solution.lambda_legendre.dot(coupling * (solution.lift->total(solution.u) - solution.lift->values()));
    EXPECT_NEAR(solution.lambda.dot(solution.gap), whole, 1e-10 * std::abs(whole) + 1e-13) << label;
    EXPECT_GT(std::abs(whole - without_lift), 1e-4 * std::abs(whole)) << label << ": the lift must matter here";
  }
}

namespace {

using hpcontact::testing::elastic_gradient;
using hpcontact::testing::elastic_u;

const assembly::Material kMaterial = assembly::lame_parameters(1.0, 0.3, assembly::PlaneModel::strain);

// An affine displacement (constant strain, no body force) that does not vanish on Γ_D.
Eigen::Vector2d affine(const mesh::Point& x) {
  return {0.1 + 0.05 * x.x() - 0.02 * x.y(), -0.04 + 0.02 * x.x() + 0.06 * x.y()};
}
Eigen::Matrix2d affine_gradient(const mesh::Point&) {
  return (Eigen::Matrix2d() << 0.05, -0.02, 0.02, 0.06).finished();
}
Eigen::Vector2d stress_times(const Eigen::Matrix2d& g, const mesh::Point& normal) {
  return (kMaterial.lambda * g.trace() * Eigen::Matrix2d::Identity() + kMaterial.mu * (g + g.transpose())) * normal;
}

// Elasticity on the §7 square with u = elastic_u + `scale` · affine: Dirichlet data on Γ_D (where
// elastic_u vanishes), traction on the rest; the energy error of u_0 + w.
double elastic_lifted_error(const mesh::Mesh& mesh, int p, double elastic_scale) {
  const space::H1Space scalar(mesh, p);
  const space::VectorSpace space(scalar);
  const std::vector<assembly::Material> materials(mesh.n_cells(), kMaterial);
  const assembly::DirichletLift lift(
      space, {[](const mesh::Point& x) { return affine(x).x(); }, [](const mesh::Point& x) { return affine(x).y(); }});
  const Eigen::VectorXd extended_load = assembly::assemble_elastic_load(
      *lift.extended_vector(),
      [&](const mesh::Point& x) -> Eigen::Vector2d {
        return elastic_scale * hpcontact::testing::elastic_body_force(x, kMaterial);
      },
      {mesh::BoundaryPart::neumann, mesh::BoundaryPart::contact},
      [&](const mesh::Point& x, const mesh::Point& n) {
        return Eigen::Vector2d(elastic_scale * hpcontact::testing::elastic_traction(x, n, kMaterial) +
                               stress_times(affine_gradient(x), n));
      });
  const assembly::ElasticCellSystem system(space, materials);
  const auto lifted = lift.lifted_load(system, extended_load);
  const assembly::CondensedFactor factor(std::make_unique<assembly::ElasticCellSystem>(space, materials));
  const auto u = assembly::total_field(&lift, space, factor.solve(lifted.load));
  return postprocess::compute_elastic_errors(
             u.space, materials, u.coefficients,
             {[&](const mesh::Point& x) { return Eigen::Vector2d(elastic_scale * elastic_u(x) + affine(x)); },
              [&](const mesh::Point& x) {
                return Eigen::Matrix2d(elastic_scale * elastic_gradient(x) + affine_gradient(x));
              }})
      .energy;
}

}  // namespace

TEST(DirichletData, ElasticAffineDisplacementIsReproducedOnAPerturbedMesh) {
  auto mesh = mesh::make_paper_square_mesh(4);
  mesh::perturb_interior_vertices(mesh, 0.2, 11);
  for (int p : {1, 3}) EXPECT_LT(elastic_lifted_error(mesh, p, 0.0), 1e-12) << "p = " << p;
}

TEST(DirichletData, ElasticEnergyErrorRateIsPWithDataOnTheDirichletBoundary) {
  const int coarse[] = {0, 8, 4, 2};
  for (int p = 1; p <= 3; ++p) {
    const double a = elastic_lifted_error(mesh::make_paper_square_mesh(2 * coarse[p]), p, 1.0);
    const double b = elastic_lifted_error(mesh::make_paper_square_mesh(4 * coarse[p]), p, 1.0);
    EXPECT_NEAR(std::log2(a / b), p, 0.25) << "p = " << p << ": " << a << " -> " << b;
  }
}

namespace {

// A small rigid motion: no strain, so adding it to u changes neither stress nor pressure.
Eigen::Vector2d rigid(const mesh::Point& x) {
  return Eigen::Vector2d(0.02, -0.03) + 0.01 * Eigen::Vector2d(-x.y(), x.x());
}

// The square clamped on the right edge (Γ_D reaching Γ_C at (1, −1)), hanging over an obstacle
// below its bottom edge (n = (0, −1)) under f = (0, −1); in contact up to Γ_D.
struct ElasticBlock {
  mesh::Mesh mesh = square_clamped_on_the_right(8);
  std::vector<assembly::Material> materials = std::vector<assembly::Material>(mesh.n_cells(), kMaterial);
  operators::ElasticOperators operators{mesh, std::vector<int>(mesh.n_cells(), 3), materials};
  mesh::BoundaryMesh boundary = mesh::BoundaryMesh::uniform(2.0, 8);

  contact::ElasticContactSetup setup(contact::ElasticContactProblem problem) const {
    contact::ElasticContactSetup s;
    s.operators = &operators;
    s.boundary_mesh = &boundary;
    s.segment_degrees.assign(boundary.n_segments(), 1);
    s.problem = problem;
    s.body_force = [](const mesh::Point&) { return Eigen::Vector2d(0.0, -1.0); };
    s.gap = [](const mesh::Point& x) { return 0.02 * (1.0 - x.x()); };
    s.threshold = [](const mesh::Point&) { return 0.1; };
    return s;
  }
};

}  // namespace

TEST(DirichletData, FrictionlessContactWithRigidMotionDataIsTheMovedSolution) {
  // u_D = r (rigid) and gap g + r·n: the solution is ũ + r with the same pressure, and
  // E = Ẽ − (f, r) = Ẽ + ∫ r_y.
  const ElasticBlock block;
  const auto plain = contact::solve_elastic_contact(block.setup(contact::ElasticContactProblem::frictionless));
  auto setup = block.setup(contact::ElasticContactProblem::frictionless);
  setup.dirichlet = {[](const mesh::Point& x) { return rigid(x).x(); },
                     [](const mesh::Point& x) { return rigid(x).y(); }};
  setup.gap = [](const mesh::Point& x) { return 0.02 * (1.0 - x.x()) - rigid(x).y(); };
  const auto moved = contact::solve_elastic_contact(setup);
  // The nodal normal multiplier at (1, −1), where Γ_C meets Γ_D: −σ_nn > 0.
  const double pressure_at_the_end = -plain.lambda(plain.n_normal - 1);
  ASSERT_GT(pressure_at_the_end, 1e-3 * plain.lambda.lpNorm<Eigen::Infinity>()) << "contact must reach Γ_D";
  EXPECT_LT((moved.pressure - plain.pressure).lpNorm<Eigen::Infinity>(), 1e-9 * plain.pressure.maxCoeff());
  EXPECT_NEAR(moved.energy, plain.energy + 4 * (-0.03), 1e-10);  // ∫ r_y over (−1, 1)²: the rotation integrates to 0
  // u − ũ on the space with Γ_D kept, against r.
  const auto& lift = *moved.lift;
  const Eigen::VectorXd difference = lift.total(moved.u) - (lift.total(plain.u) - lift.values());
  const auto errors = postprocess::compute_elastic_errors(
      *lift.extended_vector(), block.materials, difference,
      {rigid, [](const mesh::Point&) { return (Eigen::Matrix2d() << 0.0, -0.01, 0.01, 0.0).finished(); }});
  EXPECT_LT(errors.l2, 1e-10);
}

TEST(DirichletData, TrescaGapsAreThoseOfTheWholeDisplacement) {
  // The QP converged, and λ · gap = (p, u·n − g) − (σ_nt, u·t) with the couplings of
  // the space with Γ_D kept applied to u_0 + w: the constraints see the whole displacement.
  const ElasticBlock block;
  auto setup = block.setup(contact::ElasticContactProblem::tresca);
  setup.dirichlet = {[](const mesh::Point& x) { return rigid(x).x(); },
                     [](const mesh::Point& x) { return rigid(x).y(); }};
  const auto solution = contact::solve_elastic_contact(setup);
  const auto& lift = *solution.lift;
  const space::MultiplierSpace multipliers(block.boundary, 1);
  const auto& contact = block.operators.contact();
  auto pairing = [&](const Eigen::VectorXd& u) {
    const auto normal = assembly::assemble_directional_coupling(*lift.extended_vector(), contact, multipliers,
                                                                assembly::TraceDirection::normal);
    const auto tangent = assembly::assemble_directional_coupling(*lift.extended_vector(), contact, multipliers,
                                                                 assembly::TraceDirection::tangent);
    const Eigen::VectorXd g = assembly::assemble_multiplier_load(contact, multipliers, setup.gap);
    return solution.pressure.dot(normal * u - g) - solution.shear.dot(tangent * u);
  };
  const double whole = pairing(lift.total(solution.u));
  EXPECT_NEAR(solution.lambda.dot(solution.gap), whole, 1e-10 * solution.gap_scale * solution.lambda.lpNorm<1>());
  EXPECT_GT(std::abs(whole - pairing(lift.total(solution.u) - lift.values())), 1e-4 * std::abs(whole));
  EXPECT_LT(solution.qp.kkt_residual, 1e-10);
  EXPECT_GT(solution.shear.lpNorm<Eigen::Infinity>(), 1e-3);
}
