// The standard and dual multiplier families: dimension, continuity, the Lagrange property,
// biorthogonality, constants reproduced, the end modification, closed zones and the refusals.
#include "space/multiplier_family.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>

#include <cmath>

#include "basis/lobatto.hpp"
#include "basis/quadrature.hpp"
#include "core/error.hpp"

using namespace hpcontact;
using space::MultiplierFamily, space::MultiplierFamilyKind;

namespace {

// Two zones: an open one of two segments and a closed one of two.
mesh::BoundaryMesh two_zone_mesh() {
  mesh::BoundaryMesh mesh({0.0, 0.3, 0.5, 0.9, 1.2});
  mesh.set_zones({{0.0, 0.5, false}, {0.5, 1.2, true}}, "test");
  return mesh;
}

// Value of function i at s, from the segment `k` (so both sides of a breakpoint can be read).
double value_on(const space::MultiplierSpace& multipliers, const space::FamilyBasis& basis, int i, int k, double s) {
  const Eigen::VectorXd coefficients = basis.legendre * Eigen::VectorXd::Unit(basis.n_functions(), i);
  return multipliers.basis_values(k, multipliers.local_coordinate(k, s))
      .dot(coefficients.segment(multipliers.first_dof(k), multipliers.segment_degree(k) + 1));
}

// ∫ f_i g_j over Γ_C for two bases on the same multiplier space.
Eigen::MatrixXd pairing(const space::MultiplierSpace& multipliers, const space::FamilyBasis& f,
                        const space::FamilyBasis& g) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(f.n_functions(), g.n_functions());
  const auto& rule = basis::gauss_legendre(12);
  const auto& mesh = multipliers.boundary_mesh();
  for (int k = 0; k < mesh.n_segments(); ++k)
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const double a = mesh.segment_begin(k), b = mesh.segment_end(k);
      const double s = a + 0.5 * (b - a) * (rule.points[q] + 1.0), w = 0.5 * (b - a) * rule.weights[q];
      for (int i = 0; i < f.n_functions(); ++i)
        for (int j = 0; j < g.n_functions(); ++j)
          out(i, j) += w * value_on(multipliers, f, i, k, s) * value_on(multipliers, g, j, k, s);
    }
  return out;
}

// Σ_i f_i = 1 at points inside every segment.
void expect_constants_reproduced(const space::MultiplierSpace& multipliers, const space::FamilyBasis& basis,
                                 const std::string& where) {
  const auto& mesh = multipliers.boundary_mesh();
  for (int k = 0; k < mesh.n_segments(); ++k)
    for (double t : {-0.9, -0.2, 0.35, 0.8}) {
      const double s = mesh.segment_begin(k) + 0.5 * (t + 1.0) * (mesh.segment_end(k) - mesh.segment_begin(k));
      double sum = 0.0;
      for (int i = 0; i < basis.n_functions(); ++i) sum += value_on(multipliers, basis, i, k, s);
      EXPECT_NEAR(sum, 1.0, 1e-12) << where << ": segment " << k << ", s = " << s;
    }
}

}  // namespace

TEST(MultiplierFamily, GaussLobattoPointsAreTheRootsOfTheLegendreDerivative) {
  const auto four = basis::gauss_lobatto_points(4);
  const std::vector<double> expected{-1.0, -std::sqrt(3.0 / 7.0), 0.0, std::sqrt(3.0 / 7.0), 1.0};
  ASSERT_EQ(four.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(four[i], expected[i], 1e-14);
  // P_p'(x) = p (x P_p − P_{p−1}) / (x² − 1) vanishes at the interior points.
  for (int p = 2; p <= 12; ++p)
    for (double x : basis::gauss_lobatto_points(p))
      if (std::abs(x) < 1.0) {
        const Eigen::VectorXd legendre = basis::legendre_values(p, x);
        EXPECT_NEAR(x * legendre(p) - legendre(p - 1), 0.0, 1e-13) << "p = " << p << ", x = " << x;
      }
}

TEST(MultiplierFamily, StandardIsContinuousNodalAndOfTheRightDimension) {
  const auto mesh = two_zone_mesh();
  const std::vector<int> degrees{1, 3, 2, 2};
  const space::MultiplierSpace multipliers(mesh, degrees);
  for (bool modified : {false, true}) {
    const auto basis = space::family_basis(multipliers, {MultiplierFamilyKind::standard, modified});
    const std::string where = modified ? "modified" : "unmodified";
    // Open zone: 1 + 3 + 1 nodes (less its two ends when modified); closed zone: 2 + 2.
    EXPECT_EQ(basis.n_functions(), (modified ? 3 : 5) + 4) << where;
    // Each function is 1 at its node and 0 at the others (read from every segment it lives on).
    for (int i = 0; i < basis.n_functions(); ++i)
      for (int j = 0; j < basis.n_functions(); ++j)
        for (int k : basis.segments[static_cast<std::size_t>(j)]) {
          double s = basis.node_s[static_cast<std::size_t>(j)];
          // the closed zone's first node, read from its last segment, sits at the zone's end
          if (s < mesh.segment_begin(k) - 1e-12) s = mesh.zones()[1].end;
          EXPECT_NEAR(value_on(multipliers, basis, i, k, s), i == j ? 1.0 : 0.0, 1e-12)
              << where << ": function " << i << " at node " << j << " from segment " << k;
        }
    expect_constants_reproduced(multipliers, basis, where);
    if (modified) {  // p_C = 1 at the open zone's start: constant on that end segment
      for (double s : {0.0, 0.1, 0.3}) EXPECT_NEAR(value_on(multipliers, basis, 0, 0, s), 1.0, 1e-12);
    }
  }
}

TEST(MultiplierFamily, DualIsBiorthogonalToTheStandardBasis) {
  const auto mesh = two_zone_mesh();
  for (const std::vector<int>& degrees :
       {std::vector<int>{1, 1, 1, 1}, std::vector<int>{2, 2, 2, 2}, std::vector<int>{1, 3, 2, 4}}) {
    const space::MultiplierSpace multipliers(mesh, degrees);
    const auto standard = space::family_basis(multipliers, {MultiplierFamilyKind::standard, false});
    for (bool modified : {false, true}) {
      const std::string where = fmt::format("p_C {}{}", fmt::join(degrees, ","), modified ? ", modified" : "");
      const auto dual = space::family_basis(multipliers, {MultiplierFamilyKind::dual, modified});
      const auto modified_standard = space::family_basis(multipliers, {MultiplierFamilyKind::standard, modified});
      ASSERT_EQ(dual.n_functions(), modified_standard.n_functions()) << where;
      // ∫ ψ_i φ_j = δ_ij ∫ φ_j against the unmodified φ of the nodes the dual basis keeps.
      const Eigen::MatrixXd products = pairing(multipliers, dual, standard);
      const Eigen::VectorXd integrals = pairing(multipliers, standard, standard).rowwise().sum();
      for (int i = 0; i < dual.n_functions(); ++i) {
        int node = -1;  // the standard function at the same node
        for (int j = 0; j < standard.n_functions(); ++j)
          if (std::abs(standard.node_s[j] - dual.node_s[i]) < 1e-12 &&
              standard.segments[j].front() == dual.segments[i].front())
            node = j;
        ASSERT_GE(node, 0) << where;
        for (int j = 0; j < standard.n_functions(); ++j) {
          // the open zone's two end nodes, at s = 0 and at s = 0.5 on segment 1
          const bool dropped_end =
              modified && (standard.node_s[j] == 0.0 ||
                           (std::abs(standard.node_s[j] - 0.5) < 1e-12 && standard.segments[j].front() == 1));
          if (dropped_end) continue;
          EXPECT_NEAR(products(i, j), j == node ? integrals(j) : 0.0, 1e-12) << where << ": ψ_" << i << ", φ_" << j;
        }
      }
      expect_constants_reproduced(multipliers, dual, where);
    }
  }
}

TEST(MultiplierFamily, RefusesDegreeZeroAndAnEmptyModifiedZone) {
  const mesh::BoundaryMesh two(std::vector<double>{0.0, 0.5, 1.0});
  EXPECT_THROW(
      space::family_basis(space::MultiplierSpace(two, std::vector<int>{1, 0}), {MultiplierFamilyKind::standard, false}),
      InputError);
  const mesh::BoundaryMesh one(std::vector<double>{0.0, 1.0});
  EXPECT_THROW(space::family_basis(space::MultiplierSpace(one, 1), {MultiplierFamilyKind::dual, true}), InputError);
  // p_C = 2 keeps the midpoint: a constant.
  const auto basis = space::family_basis(space::MultiplierSpace(one, 2), {MultiplierFamilyKind::dual, true});
  EXPECT_EQ(basis.n_functions(), 1);
  EXPECT_EQ(space::parse_multiplier_family("dual-modified", "test"),
            (MultiplierFamily{MultiplierFamilyKind::dual, true}));
  EXPECT_THROW(space::parse_multiplier_family("mortar", "test"), InputError);
}
