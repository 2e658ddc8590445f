// Stage 10, inf-sup constant: the paper's §7 pairings (stable / decaying), SLEPc against the
// dense path on stable, unstable and singular configurations, convergence of both H^{-1/2}
// reference realizations, the friction variant (22) with supp s ≠ Γ_C, and mode sampling.
#include <gtest/gtest.h>

#include "slepc_test_environment.hpp"
#include <slepcsys.h>

#include <cmath>

#include "core/error.hpp"
#include "mesh/contact_boundary.hpp"
#include "norms/h_minus_half_gram.hpp"
#include "space/multiplier_space.hpp"
#include "infsup/infsup_analysis.hpp"
#include "mesh/rectangle_mesh.hpp"

using namespace hpcontact;

namespace {

struct Configuration {
  int p, pc, n, m;
  infsup::GramNorm norm = infsup::GramNorm::interpolation;
  infsup::PairingProblem problem = infsup::PairingProblem::signorini;
  assembly::BoundaryFunction s = [](const mesh::Point& x) { return (1 - x.x()) * (1 - x.x()); };
  norms::InterpolationReference interpolation{};
  norms::ExtensionReference extension{};
};

infsup::InfSupResult alpha(const Configuration& c,
                           infsup::EigenBackend backend = infsup::EigenBackend::dense) {
  const auto mesh = mesh::make_paper_square_mesh(c.n);
  const auto boundary = mesh::BoundaryMesh::uniform(2.0, c.m);
  infsup::InfSupSetup setup;
  setup.mesh = &mesh;
  setup.cell_degrees.assign(mesh.n_cells(), c.p);
  setup.boundary_mesh = &boundary;
  setup.segment_degrees.assign(c.m, c.pc);
  setup.norm = c.norm;
  setup.problem = c.problem;
  setup.friction_bound = c.s;
  setup.interpolation_reference = c.interpolation;
  setup.extension_reference = c.extension;
  return infsup::analyse_infsup(setup, backend);
}

}  // namespace

// Figure 2 of the paper: p ≡ 1, p_C ≡ 0 oscillates for h/H = 1 and is stable for h/H = 1/2.
// Halving h halves α when the pairing is unstable (rate 1), and leaves α nearly unchanged when
// it is stable. The same for p = 3 with p_C = 2 (h/H = 1 unstable, 1/2 stable) and p_C = 1.
TEST(InfSup, PaperPairingsDecayOrStayBounded) {
  struct Case { int p, pc; double ratio; bool stable; };
  for (const auto& c : {Case{1, 0, 1.0, false}, Case{1, 0, 0.5, true}, Case{3, 2, 1.0, false},
                        Case{3, 2, 0.5, true}, Case{3, 1, 1.0, true}, Case{2, 1, 1.0, false}}) {
    const double coarse = alpha({c.p, c.pc, 8, static_cast<int>(8 * c.ratio)}).alpha;
    const double fine = alpha({c.p, c.pc, 16, static_cast<int>(16 * c.ratio)}).alpha;
    if (c.stable) {
      EXPECT_GT(fine / coarse, 0.95) << "p " << c.p << " pC " << c.pc << " h/H " << c.ratio;
      EXPECT_GT(fine, 0.5);
    } else {
      EXPECT_NEAR(fine / coarse, 0.5, 0.05) << "p " << c.p << " pC " << c.pc << " h/H " << c.ratio;
    }
  }
}

TEST(InfSup, SlepcAgreesWithDensePath) {
  for (const Configuration& c : {Configuration{1, 0, 8, 8}, Configuration{1, 0, 8, 4},
                                 Configuration{3, 2, 8, 8}, Configuration{4, 3, 6, 12}}) {
    const auto dense = alpha(c, infsup::EigenBackend::dense);
    const auto slepc = alpha(c, infsup::EigenBackend::slepc);
    EXPECT_NEAR(slepc.lambda_min, dense.lambda_min, 1e-8 * dense.lambda_min + 1e-12 * dense.lambda_max)
        << "p " << c.p << " pC " << c.pc << " m " << c.m;
    EXPECT_EQ(slepc.singular, dense.singular);
  }
}

// More multipliers than trace dofs: S_G is singular, α is reported as 0 (never NaN or
// negative) by both paths, and the mode is a genuine null vector.
TEST(InfSup, SingularPairingIsReportedAsZero) {
  const Configuration c{1, 0, 4, 8};  // 8 constants against 5 trace values
  for (auto backend : {infsup::EigenBackend::dense, infsup::EigenBackend::slepc}) {
    const auto result = alpha(c, backend);
    EXPECT_TRUE(result.singular);
    EXPECT_TRUE(std::isfinite(result.alpha));
    EXPECT_GE(result.alpha, 0.0);
    EXPECT_LT(result.alpha, 1e-5);
  }
}

// The reference spaces of both realizations are refined until α no longer changes; the changes
// shrink and the last one is small.
TEST(InfSup, ReferenceSpacesAreFineEnough) {
  Configuration c{2, 1, 8, 8};
  std::vector<double> interpolation, extension;
  for (int subdivisions : {1, 2, 4}) {
    c.interpolation = {subdivisions, 0};
    interpolation.push_back(alpha(c).alpha);
  }
  c.norm = infsup::GramNorm::extension;
  for (int refinements : {0, 1, 2}) {
    c.extension = {refinements, 2};
    extension.push_back(alpha(c).alpha);
  }
  EXPECT_LT(std::abs(interpolation[2] - interpolation[1]), std::abs(interpolation[1] - interpolation[0]));
  EXPECT_LT(std::abs(interpolation[2] - interpolation[1]) / interpolation[2], 1e-3);
  EXPECT_LT(std::abs(extension[2] - extension[1]), std::abs(extension[1] - extension[0]));
  EXPECT_LT(std::abs(extension[2] - extension[1]) / extension[2], 1e-2);
  // The checkerboard mode oscillates on the scale h, where both norms behave like
  // sqrt(1 + k²) for frequency k: the two realizations agree closely for it.
  EXPECT_NEAR(extension[2] / interpolation[2], 1.0, 5e-3);
}

TEST(InfSup, FrictionRestrictsMultipliersToSupportOfS) {
  Configuration c{3, 1, 8, 8};
  c.problem = infsup::PairingProblem::friction;
  c.s = [](const mesh::Point& x) { return x.x() < 0 ? x.x() * x.x() : 0.0; };  // supp s = left half
  const auto result = alpha(c, infsup::EigenBackend::slepc);
  EXPECT_GT(result.alpha, 0.0);
  // The mode vanishes on the right half, where no multiplier lives.
  EXPECT_EQ(result.mode.tail(8).norm(), 0.0);
  EXPECT_GT(result.mode.head(8).norm(), 0.0);
  c.s = [](const mesh::Point&) { return 0.0; };
  EXPECT_THROW(alpha(c), InputError);
}

// With s ≡ 1, (22) is (11): an independent path through the weighted coupling B^s, the support
// restriction and the friction bookkeeping must give the Signorini α.
TEST(InfSup, FrictionWithUnitBoundEqualsSignorini) {
  Configuration signorini{3, 2, 8, 8};
  Configuration friction = signorini;
  friction.problem = infsup::PairingProblem::friction;
  friction.s = [](const mesh::Point&) { return 1.0; };
  EXPECT_NEAR(alpha(friction).alpha, alpha(signorini).alpha, 1e-12);
}

// s = (1-x)² vanishes at the end x = 1 of Γ_C: multipliers concentrated there make ‖sμ‖ tiny
// against ‖μ‖, so the constant of (22) decays (like h², measured) even for pairings that are
// stable for (11).
TEST(InfSup, FrictionBoundVanishingAtAnEndMakesAlphaDecay) {
  Configuration c{3, 1, 8, 8};
  c.problem = infsup::PairingProblem::friction;
  const double coarse = alpha(c).alpha;
  c.n = 16;
  c.m = 16;
  const double fine = alpha(c).alpha;
  EXPECT_LT(fine / coarse, 0.35);
}

TEST(InfSup, ModeSamplesTwentyPointsPerSegment) {
  const auto mesh = mesh::make_paper_square_mesh(4);
  const auto boundary = mesh::BoundaryMesh::uniform(2.0, 3);
  const space::MultiplierSpace multipliers(boundary, 1);
  Eigen::VectorXd mode = Eigen::VectorXd::Zero(6);
  mode(2) = 1.0;  // constant 1 on the middle segment
  const auto table = infsup::sample_mode(mesh, multipliers, mode);
  EXPECT_EQ(table.n_rows(), 60u);
  EXPECT_EQ(table.columns().front(), "x");
  EXPECT_EQ(table.columns()[1], "mu");
}

// The two ways of applying Φ Λ^{-1/2} Φᵀ in the interpolation norm: the dense eigendecomposition
// and the sinc quadrature of (2/π) ∫ (K_W + t² M_W)⁻¹ dt with closed-form tails. Same Gram matrix
// to 1e-9 (relative, max norm) for uniform and mixed degrees, non-nested h/H, and the same α.
TEST(InfSup, InterpolationGramQuadratureEqualsDenseEigendecomposition) {
  for (const auto& [n, pc, m] : {std::tuple{8, 0, 8}, {12, 3, 8}, {16, 1, 12}}) {
    const auto mesh = mesh::make_paper_square_mesh(n);
    const mesh::ContactBoundary contact(mesh);
    const auto boundary = mesh::BoundaryMesh::uniform(2.0, m);
    std::vector<int> degrees(m, pc);
    degrees[m / 2] = pc + 2;  // a degree distribution
    const space::MultiplierSpace multipliers(boundary, degrees);
    norms::InterpolationReference dense_reference, quadrature_reference;
    dense_reference.dense_limit = 1 << 30;
    quadrature_reference.dense_limit = 0;
    const Eigen::MatrixXd dense = norms::interpolation_norm_gram(contact, multipliers, dense_reference);
    const Eigen::MatrixXd quadrature = norms::interpolation_norm_gram(contact, multipliers, quadrature_reference);
    EXPECT_LT((dense - quadrature).cwiseAbs().maxCoeff(), 1e-9 * dense.cwiseAbs().maxCoeff())
        << "n " << n << " pC " << pc << " m " << m;
  }
  Configuration c{3, 2, 8, 8};
  const double dense_alpha = alpha(c).alpha;
  c.interpolation.dense_limit = 0;
  EXPECT_NEAR(alpha(c).alpha, dense_alpha, 1e-9);
}
