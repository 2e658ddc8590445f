// The tetrahedron basis and rule: the collapsed rule's exactness, exact gradients, edge traces
// equal to the Lobatto functions of hexahedra and triangles, face traces equal to the triangle
// basis in the face's vertex order (so neighbouring tetrahedra and the triangles of Γ_C share
// them), modes vanishing where they must, and a basis of P_p whose mass matrix stays regular.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <random>

#include "basis/lobatto.hpp"
#include "basis/quadrature.hpp"
#include "basis/tetrahedron_basis.hpp"
#include "basis/triangle_basis.hpp"

namespace hpcontact::basis {
namespace {

double factorial(int n) { return std::tgamma(n + 1.0); }

/// Every shape of degree ≤ p at one point, in the order vertices, edges, faces, interior.
std::vector<SolidShapeValue> all_shapes(int p, const Eigen::Vector3d& xi) {
  const TetrahedronShapes shapes(p, xi(0), xi(1), xi(2));
  std::vector<SolidShapeValue> out;
  for (int v = 0; v < 4; ++v) out.push_back(shapes.vertex(v));
  for (int e = 0; e < 6; ++e)
    for (int k = 2; k <= p; ++k) out.push_back(shapes.edge(e, k));
  for (int f = 0; f < 4; ++f)
    for (int n1 = 0; n1 <= p - 3; ++n1)
      for (int n2 = 0; n1 + n2 <= p - 3; ++n2) out.push_back(shapes.face(f, n1, n2));
  for (int n1 = 0; n1 <= p - 4; ++n1)
    for (int n2 = 0; n1 + n2 <= p - 4; ++n2)
      for (int n3 = 0; n1 + n2 + n3 <= p - 4; ++n3) out.push_back(shapes.interior(n1, n2, n3));
  return out;
}

/// The reference point with barycentric coordinates λ (λ0 = 1 − λ1 − λ2 − λ3).
Eigen::Vector3d from_barycentric(const std::array<double, 4>& lambda) {
  return {2.0 * lambda[1] - 1.0, 2.0 * lambda[2] - 1.0, 2.0 * lambda[3] - 1.0};
}

TEST(Tetrahedra, CollapsedRuleIsExactToDegreeTwoNMinusThree) {
  // ∫ λ0^a λ1^b λ2^c λ3^d = 6 |T| a! b! c! d! / (a + b + c + d + 3)!, |T| = 4/3.
  for (int n = 2; n <= 6; ++n) {
    const QuadratureRule3D& rule = collapsed_tetrahedron_rule(n);
    const int degree = 2 * n - 3;
    for (int a = 0; a <= degree; ++a)
      for (int b = 0; a + b <= degree; ++b)
        for (int c = 0; a + b + c <= degree; ++c) {
          const int d = degree - a - b - c;
          double sum = 0.0;
          for (std::size_t q = 0; q < rule.weights.size(); ++q) {
            const double l1 = 0.5 * (1.0 + rule.xi[q]), l2 = 0.5 * (1.0 + rule.eta[q]), l3 = 0.5 * (1.0 + rule.zeta[q]);
            sum +=
                rule.weights[q] * std::pow(1.0 - l1 - l2 - l3, a) * std::pow(l1, b) * std::pow(l2, c) * std::pow(l3, d);
          }
          const double exact = 8.0 * factorial(a) * factorial(b) * factorial(c) * factorial(d) / factorial(degree + 3);
          EXPECT_NEAR(sum, exact, 1e-13 * exact + 1e-16) << "n = " << n << ", powers " << a << b << c << d;
        }
  }
}

TEST(Tetrahedra, GradientsAreExact) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(0.05, 0.3);
  const int p = 6;
  const double h = 1e-6;
  for (int trial = 0; trial < 5; ++trial) {
    const Eigen::Vector3d xi = from_barycentric({0.0, unit(random), unit(random), unit(random)});
    const auto at = all_shapes(p, xi);
    for (int d = 0; d < 3; ++d) {
      const auto up = all_shapes(p, xi + h * Eigen::Vector3d::Unit(d));
      const auto down = all_shapes(p, xi - h * Eigen::Vector3d::Unit(d));
      for (std::size_t s = 0; s < at.size(); ++s)
        EXPECT_NEAR(at[s].d[d], (up[s].v - down[s].v) / (2.0 * h), 1e-7) << "shape " << s << ", axis " << d;
    }
  }
}

TEST(Tetrahedra, EdgeModesAreTheLobattoFunctionsAndOthersVanishOnEdges) {
  const int p = 6;
  Eigen::VectorXd lobatto(p + 1), slopes(p + 1);
  for (int e = 0; e < 6; ++e) {
    const auto [a, b] = kTetEdgeVertices[e];
    for (double t : {-0.8, -0.3, 0.1, 0.65}) {
      std::array<double, 4> lambda{};
      lambda[a] = 0.5 * (1.0 - t);
      lambda[b] = 0.5 * (1.0 + t);
      const TetrahedronShapes shapes(p, from_barycentric(lambda)(0), from_barycentric(lambda)(1),
                                     from_barycentric(lambda)(2));
      lobatto_values(p, t, lobatto, slopes);
      for (int other = 0; other < 6; ++other)
        for (int k = 2; k <= p; ++k)
          EXPECT_NEAR(shapes.edge(other, k).v, other == e ? lobatto(k) : 0.0, 1e-13) << "edge " << e << ", mode " << k;
      for (int f = 0; f < 4; ++f)
        for (int n1 = 0; n1 <= p - 3; ++n1)
          for (int n2 = 0; n1 + n2 <= p - 3; ++n2) EXPECT_NEAR(shapes.face(f, n1, n2).v, 0.0, 1e-14);
    }
  }
}

TEST(Tetrahedra, FaceTracesAreTheTriangleBasisInTheFaceOrder) {
  const int p = 7;
  std::mt19937 random(8);
  std::uniform_real_distribution<double> unit(0.05, 0.45);
  for (int f = 0; f < 4; ++f) {
    const auto& corners = kTetFaceVertices[f];
    for (int trial = 0; trial < 4; ++trial) {
      const double m1 = unit(random), m2 = unit(random), m0 = 1.0 - m1 - m2;
      std::array<double, 4> lambda{};
      lambda[corners[0]] = m0;
      lambda[corners[1]] = m1;
      lambda[corners[2]] = m2;
      const Eigen::Vector3d xi = from_barycentric(lambda);
      const TetrahedronShapes tet(p, xi(0), xi(1), xi(2));
      const TriangleShapes triangle(p, 2.0 * m1 - 1.0, 2.0 * m2 - 1.0);
      for (int n1 = 0; n1 <= p - 3; ++n1)
        for (int n2 = 0; n1 + n2 <= p - 3; ++n2) {
          EXPECT_NEAR(tet.face(f, n1, n2).v, triangle.bubble(n1, n2).value, 1e-13) << "face " << f;
          for (int other = 0; other < 4; ++other)
            if (other != f) {
              EXPECT_NEAR(tet.face(other, n1, n2).v, 0.0, 1e-14);
            }
        }
      // The triangle's edges 0: v0→v1, 1: v1→v2, 2: v0→v2 are the tetrahedron's (a,b), (b,c), (a,c).
      const std::array<std::array<int, 2>, 3> triangle_edges{
          {{corners[0], corners[1]}, {corners[1], corners[2]}, {corners[0], corners[2]}}};
      for (int te = 0; te < 3; ++te) {
        int e = 0;
        while (kTetEdgeVertices[e] != triangle_edges[te]) ++e;
        for (int k = 2; k <= p; ++k) EXPECT_NEAR(tet.edge(e, k).v, triangle.edge(te, k).value, 1e-13);
      }
      for (int n1 = 0; n1 <= p - 4; ++n1)
        for (int n2 = 0; n1 + n2 <= p - 4; ++n2)
          for (int n3 = 0; n1 + n2 + n3 <= p - 4; ++n3) EXPECT_NEAR(tet.interior(n1, n2, n3).v, 0.0, 1e-14);
    }
  }
}

TEST(Tetrahedra, ShapesAreABasisOfPpWithARegularMassMatrix) {
  for (int p = 1; p <= 7; ++p) {
    const QuadratureRule3D& rule = collapsed_tetrahedron_rule(p + 2);
    const int n = tetrahedron_shape_count(p);
    Eigen::MatrixXd mass = Eigen::MatrixXd::Zero(n, n);
    for (std::size_t q = 0; q < rule.weights.size(); ++q) {
      const auto shapes = all_shapes(p, {rule.xi[q], rule.eta[q], rule.zeta[q]});
      ASSERT_EQ(static_cast<int>(shapes.size()), n) << "p = " << p;
      Eigen::VectorXd values(n);
      for (int s = 0; s < n; ++s) values(s) = shapes[s].v;
      mass += rule.weights[q] * values * values.transpose();
    }
    // Exact for degree 2p, so that a dependent set of shapes would give a zero eigenvalue. Scaled
    // to a unit diagonal: the shapes' sizes (λ0 λ1 λ2 λ3 is at most 1/256) are no defect.
    const Eigen::VectorXd scale = mass.diagonal().cwiseSqrt().cwiseInverse();
    const Eigen::MatrixXd scaled = scale.asDiagonal() * mass * scale.asDiagonal();
    const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(scaled).eigenvalues();
    const double condition = eigenvalues(n - 1) / eigenvalues(0);
    std::printf("p = %d: %d shapes, condition number of the scaled mass matrix %.3g\n", p, n, condition);
    EXPECT_GT(eigenvalues(0), 0.0) << "p = " << p;
    // (6.5e4 at p = 7: the Jacobi weights of the collapsed construction keep it polynomial in p)
    EXPECT_LT(condition, 1e6) << "p = " << p;
  }
}

}  // namespace
}  // namespace hpcontact::basis
