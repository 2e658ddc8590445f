// Γ_C pieces shared by inf-sup and contact: the chain Γ_C, the independent boundary
// mesh T_{C,H}, the multiplier space, and the coupling B integrated exactly on the common
// refinement (checked against adaptive GSL quadrature of μ·u_h evaluated through the point locator).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "assembly/coupling.hpp"
#include "contact/multiplier_distance.hpp"
#include "core/error.hpp"
#include "mesh/contact_boundary.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "mesh/refine.hpp"
#include "postprocess/fe_function.hpp"
#include "support/adaptive_integral.hpp"

using namespace hpcontact;

TEST(ContactBoundary, PaperSquareIsTheBottomEdgeWithSEqualXPlusOne) {
  const auto m = mesh::make_paper_square_mesh(6);
  const mesh::ContactBoundary contact(m);
  EXPECT_NEAR(contact.length(), 2.0, 1e-14);
  EXPECT_EQ(contact.edges().size(), 6u);
  for (double s : {0.0, 0.3, 1.0, 1.7, 2.0}) {
    EXPECT_NEAR(contact.point_at(s).x(), s - 1.0, 1e-14);
    EXPECT_NEAR(contact.point_at(s).y(), -1.0, 1e-14);
  }
}

TEST(ContactBoundary, EmptyContactIsAnInputError) {
  auto m = mesh::make_rectangle_mesh({}, 4, 4);
  EXPECT_THROW(mesh::ContactBoundary{m}, InputError);
}

TEST(BoundaryMesh, UniformGradedAndCommonRefinement) {
  const auto uniform = mesh::BoundaryMesh::uniform(2.0, 3);
  EXPECT_NEAR(uniform.mesh_size(), 2.0 / 3.0, 1e-15);
  const auto graded = mesh::BoundaryMesh::graded(2.0, 6, 0.5);
  EXPECT_NEAR(graded.length(), 2.0, 1e-15);
  EXPECT_LT(graded.segment_end(0) - graded.segment_begin(0), graded.segment_end(2) - graded.segment_begin(2));
  const auto merged = mesh::common_refinement({0, 0.5, 1, 1.5, 2}, uniform.nodes());
  EXPECT_EQ(merged.size(), 7u);
  EXPECT_THROW(mesh::BoundaryMesh({0.0, 1.0, 0.5, 2.0}), InputError);
}

TEST(Refine, UniformRefinementKeepsGeometryAndParts) {
  const auto coarse = mesh::make_paper_square_mesh(4);
  const auto fine = mesh::refine_uniformly(coarse);
  EXPECT_EQ(fine.n_cells(), 64);
  double contact = 0.0, dirichlet = 0.0;
  for (int e : fine.boundary_edges()) {
    if (fine.edge_part(e) == mesh::BoundaryPart::contact) contact += fine.edge_length(e);
    if (fine.edge_part(e) == mesh::BoundaryPart::dirichlet) dirichlet += fine.edge_length(e);
  }
  EXPECT_NEAR(contact, 2.0, 1e-14);
  EXPECT_NEAR(dirichlet, 3.0, 1e-14);
}

namespace {

struct Integrand {
  const space::H1Space* space;
  const Eigen::VectorXd* u;
  const space::MultiplierSpace* multipliers;
  const Eigen::VectorXd* mu;
  const postprocess::PointLocator* locator;
  bool weighted;
};

double integrand(double x, void* data) {
  const auto& d = *static_cast<Integrand*>(data);
  const double s = x + 1.0;
  double value =
      postprocess::evaluate_at(*d.space, *d.u, *d.locator, {x, -1.0}).value * d.multipliers->evaluate(*d.mu, s);
  if (d.weighted) value *= (1.0 - x) * (1.0 - x);
  return value;
}

// μᵀ B u by adaptive quadrature with the break points of both meshes as singular points.
double reference_pairing(Integrand data, int n, const mesh::BoundaryMesh& boundary) {
  std::vector<double> points;
  for (int i = 0; i <= n; ++i) points.push_back(-1.0 + 2.0 * i / n);
  for (double s : boundary.nodes()) points.push_back(s - 1.0);
  return hpcontact::testing::adaptive_integral(integrand, &data, points);
}

}  // namespace

// Nested and non-nested ratios h/H, mixed degrees on both sides, with and without the weight s.
TEST(Coupling, ExactOnTheCommonRefinement) {
  std::mt19937 generator(3);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (const auto& [n, m] : std::vector<std::pair<int, int>>{{6, 6}, {6, 3}, {6, 2}, {6, 4}, {6, 12}, {4, 7}}) {
    const auto mesh = mesh::make_paper_square_mesh(n);
    std::vector<int> degrees(mesh.n_cells());
    for (int& p : degrees) p = std::uniform_int_distribution<int>(1, 5)(generator);
    const space::H1Space space(mesh, degrees);
    const mesh::ContactBoundary contact(mesh);
    const auto boundary = mesh::BoundaryMesh::uniform(2.0, m);
    std::vector<int> pc(m);
    for (int& d : pc) d = std::uniform_int_distribution<int>(0, 4)(generator);
    const space::MultiplierSpace multipliers(boundary, pc);
    Eigen::VectorXd u(space.n_dofs()), mu(multipliers.n_dofs());
    for (auto& v : u) v = uniform(generator);
    for (auto& v : mu) v = uniform(generator);
    const postprocess::PointLocator locator(mesh);
    for (bool weighted : {false, true}) {
      const auto b = assembly::assemble_coupling(
          space, contact, multipliers,
          weighted ? assembly::BoundaryFunction([](const mesh::Point& x) { return (1 - x.x()) * (1 - x.x()); })
                   : assembly::BoundaryFunction{});
      const double pairing = mu.dot(b * u);
      const double reference = reference_pairing({&space, &u, &multipliers, &mu, &locator, weighted}, n, boundary);
      EXPECT_NEAR(pairing, reference, 1e-11 * (1.0 + std::abs(reference)))
          << "n = " << n << ", m = " << m << ", weighted " << weighted;
    }
  }
}

TEST(Coupling, MultiplierLoadIntegratesTheObstacle) {
  const auto mesh = mesh::make_paper_square_mesh(4);
  const mesh::ContactBoundary contact(mesh);
  const auto boundary = mesh::BoundaryMesh::uniform(2.0, 3);
  const space::MultiplierSpace multipliers(boundary, 2);
  const auto g =
      assembly::assemble_multiplier_load(contact, multipliers, [](const mesh::Point& x) { return -x.x() * x.x(); });
  // Σ over segments of the P_0 coefficient integrals = ∫_{-1}^{1} -x² dx = -2/3.
  double total = 0.0;
  for (int k = 0; k < 3; ++k) total += g(multipliers.first_dof(k));
  EXPECT_NEAR(total, -2.0 / 3.0, 1e-14);
}

namespace {

struct DistanceIntegrand {
  const space::MultiplierSpace *a, *b;
  const Eigen::VectorXd *ca, *cb;
  std::function<double(double)> weight = [](double) { return 1.0; };
};

double squared_difference(double s, void* data) {
  const auto& d = *static_cast<DistanceIntegrand*>(data);
  const double difference = d.weight(s) * (d.a->evaluate(*d.ca, s) - d.b->evaluate(*d.cb, s));
  return difference * difference;
}

}  // namespace

// ‖μ_a − μ_b‖_{L²} of multipliers on non-nested meshes with different degrees, against adaptive
// GSL quadrature with every breakpoint of both meshes given.
TEST(MultiplierDistance, ExactOnTheCommonRefinement) {
  const mesh::BoundaryMesh mesh_a = mesh::BoundaryMesh::uniform(2.0, 3), mesh_b({0.0, 0.5, 1.7, 2.0});
  const space::MultiplierSpace a(mesh_a, std::vector<int>{2, 0, 3}), b(mesh_b, 1);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Eigen::VectorXd ca(a.n_dofs()), cb(b.n_dofs());
  for (auto& c : ca) c = value(random);
  for (auto& c : cb) c = value(random);
  DistanceIntegrand data{&a, &b, &ca, &cb, [](double) { return 1.0; }};
  const std::vector<double> points{0.0, 0.5, 2.0 / 3.0, 4.0 / 3.0, 1.7, 2.0};
  EXPECT_NEAR(contact::multiplier_l2_distance(a, ca, b, cb),
              std::sqrt(hpcontact::testing::adaptive_integral(squared_difference, &data, points)), 1e-12);
  EXPECT_NEAR(contact::multiplier_l2_distance(a, ca, a, ca), 0.0, 1e-15);
  // With the weight w(s) = (2 - s)², as s = (1 - x)² on the §7 Γ_C: ∫ w² (μ_a − μ_b)².
  data.weight = [](double s) { return (2.0 - s) * (2.0 - s); };
  const double result = hpcontact::testing::adaptive_integral(squared_difference, &data, points);
  EXPECT_NEAR(contact::multiplier_l2_distance(a, ca, b, cb, data.weight), std::sqrt(result), 1e-12);
  const auto shorter = mesh::BoundaryMesh::uniform(1.0, 2);
  EXPECT_THROW(contact::multiplier_l2_distance(a, ca, space::MultiplierSpace(shorter, 1), Eigen::VectorXd::Zero(4)),
               std::invalid_argument);
}
