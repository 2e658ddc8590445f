// α of 3-D pairings: the surface interpolation norm (exact on constants, increasing and converging
// by a factor 4 per level of its ladder), the §7 pairing extruded in y against the planar α, the
// 3-D analogue of Figure 2 (ratio 1 decays, 1/2 stays bounded), SLEPc against the dense path, and
// the friction pairing (22) restricted to supp s.
#include "infsup/solid_infsup.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "basis/quadrature.hpp"
#include "core/error.hpp"
#include "norms/surface_interpolation_gram.hpp"
#include "space/solid_vector_space.hpp"
#include "support/paper_alpha.hpp"
#include "support/slepc_test_environment.hpp"
#include "support/solid_meshes.hpp"

using namespace hpcontact;

namespace {

/// The §7 pairing extruded over y ∈ (0, width): n × n_y × n cells of degree p, T_{C,H} an m × m_y
/// grid of degree p_C.
struct Extruded {
  int n, n_y, p, pc, m, m_y;
  double width = 0.5;
  infsup::PairingProblem problem = infsup::PairingProblem::signorini;
};

struct Built {
  explicit Built(const Extruded& c)
      : mesh(hpcontact::testing::extruded_paper_mesh(c.n, c.n_y, c.width)),
        space(mesh, std::vector<int>(mesh.n_cells(), c.p), space::faces_labelled(mesh, {"dirichlet"})),
        surface(mesh, {"contact"}, "test"),
        multiplier_mesh(surface, {c.m, c.m_y}, "test"),
        multipliers(multiplier_mesh, c.pc) {}
  mesh::SolidMesh mesh;
  space::SolidH1Space space;
  mesh::FlatContactSurface surface;
  mesh::SurfaceMultiplierMesh multiplier_mesh;
  space::SurfaceMultiplierSpace multipliers;
};

infsup::InfSupResult alpha(const Extruded& c, infsup::EigenBackend backend = infsup::EigenBackend::dense,
                           double tolerance = 1e-4, contact::SchurPath path = contact::SchurPath::dense) {
  const Built built(c);
  infsup::SolidInfSupSetup setup;
  setup.space = &built.space;
  setup.multipliers = &built.multipliers;
  setup.problem = c.problem;
  setup.friction_bound = [](const mesh::SolidPoint& x) { return std::max(0.0, -x(0)); };
  setup.alpha_tolerance = tolerance;
  setup.path = path;
  return infsup::analyse_solid_infsup(setup, backend);
}

}  // namespace

// One constant multiplier on the whole rectangle: only the mode φ_00 = 1/√(L₁L₂) meets it, so
// G = (∫ 1 · φ_00)² = L₁ L₂ exactly, with any number of modes.
TEST(SolidInfSup, GramOfAConstantIsTheArea) {
  const Built built({2, 1, 1, 0, 1, 1, 0.5});
  for (int modes : {1, 7, 64}) {
    const Eigen::MatrixXd gram = norms::surface_interpolation_gram(built.multipliers, {modes, modes + 3});
    ASSERT_EQ(gram.rows(), 1);
    EXPECT_NEAR(gram(0, 0), 2.0 * 0.5, 1e-12) << modes;
  }
}

// G against its definition summed by brute force: the moments (ℓ_i, c_j c_k) by composite Gauss
// quadrature on each cell of T_{C,H} from the multiplier space's own values, on a non-square Γ_C with a
// 3 × 2 grid at p_C = 2 and modes reaching κ = ωH/2 ≈ 21 (the moments' summation by parts).
TEST(SolidInfSup, GramEqualsItsDefinitionByQuadrature) {
  const Built built({6, 4, 2, 2, 3, 2, 0.7});
  const std::array<int, 2> modes{40, 30};
  // (named, not bound: a lambda below uses the lower corner)
  const Eigen::Vector2d lo = built.surface.bounds()[0], length = built.surface.bounds()[1] - lo;
  // (composite: 4 × 4 pieces of 20 × 20 Gauss points per cell, at most 11 radians of the last
  // cosine over a piece; GSL's rules of many points are accurate to about 1e-10 only)
  const auto& rule = basis::gauss_legendre(20);
  constexpr int kPieces = 4;
  const int n = built.multipliers.n_dofs();
  Eigen::MatrixXd moments = Eigen::MatrixXd::Zero(modes[0] * modes[1], n);  // row j + modes[0] k
  const auto mode = [&](int i, int axis, double x) {
    return i == 0 ? 1.0 / std::sqrt(length(axis))
                  : std::sqrt(2.0 / length(axis)) * std::cos(i * M_PI * (x - lo(axis)) / length(axis));
  };
  for (int c = 0; c < built.multiplier_mesh.n_cells(); ++c) {
    const auto [cell_lo, cell_hi] = built.multiplier_mesh.cell_bounds(c);
    const Eigen::Vector2d piece = (cell_hi - cell_lo) / kPieces;
    for (int pi = 0; pi < kPieces * kPieces; ++pi)
      for (std::size_t q = 0; q < rule.points.size(); ++q)
        for (std::size_t r = 0; r < rule.points.size(); ++r) {
          const Eigen::Vector2d t(rule.points[q], rule.points[r]);
          const Eigen::Vector2d corner = cell_lo + Eigen::Vector2d(pi % kPieces, pi / kPieces).cwiseProduct(piece);
          const Eigen::Vector2d a = corner + (0.5 * (t.array() + 1.0) * piece.array()).matrix();
          const double weight = 0.25 * piece.prod() * rule.weights[q] * rule.weights[r];
          const Eigen::VectorXd values = built.multipliers.values(c, a);
          for (int k = 0; k < modes[1]; ++k)
            for (int j = 0; j < modes[0]; ++j)
              moments.row(j + modes[0] * k).segment(built.multipliers.first_dof(c), values.size()) +=
                  (weight * mode(j, 0, a(0)) * mode(k, 1, a(1))) * values.transpose();
        }
  }
  Eigen::VectorXd weights(modes[0] * modes[1]);
  for (int k = 0; k < modes[1]; ++k)
    for (int j = 0; j < modes[0]; ++j)
      weights(j + modes[0] * k) =
          1.0 / std::sqrt(1.0 + std::pow(j * M_PI / length(0), 2) + std::pow(k * M_PI / length(1), 2));
  const Eigen::MatrixXd expected = moments.transpose() * weights.asDiagonal() * moments;
  for (const auto summation : {norms::GramSummation::direct, norms::GramSummation::exponential_sum}) {
    const Eigen::MatrixXd gram = norms::surface_interpolation_gram(built.multipliers, modes, summation);
    EXPECT_LT((gram - expected).norm(), 1e-12 * expected.norm()) << static_cast<int>(summation);
  }
}

// The two summations of the double sum over the modes agree to the exponential sum's accuracy.
TEST(SolidInfSup, ExponentialSumEqualsTheDirectSum) {
  const Built built({4, 2, 2, 2, 3, 2, 0.7});
  for (const std::array<int, 2> modes :
       {std::array<int, 2>{9, 6}, std::array<int, 2>{96, 48}, std::array<int, 2>{1536, 768}}) {
    const Eigen::MatrixXd direct =
        norms::surface_interpolation_gram(built.multipliers, modes, norms::GramSummation::direct);
    const Eigen::MatrixXd sum =
        norms::surface_interpolation_gram(built.multipliers, modes, norms::GramSummation::exponential_sum);
    EXPECT_LT((sum - direct).norm(), 1e-12 * direct.norm()) << modes[0];
  }
}

// The truncations grow towards G (each adds positive terms) and the dropped part decays like 1/N²:
// α on the ladder's levels decreases, by a factor about 4 less per level.
TEST(SolidInfSup, LadderIncreasesAndConvergesByAFactorFourPerLevel) {
  const Built built({4, 2, 2, 1, 4, 2});
  const assembly::CondensedFactor factor = infsup::solid_gram_factor(built.space, built.surface);
  const norms::GramLadder ladder = norms::surface_interpolation_gram_ladder(built.multipliers);
  std::vector<double> alphas;
  for (int level = 0; level <= 4; ++level) {
    infsup::SolidInfSupSetup setup;
    setup.space = &built.space;
    setup.multipliers = &built.multipliers;
    setup.gram_factor = &factor;
    // (a ladder of this level alone: its top is `level`)
    const norms::GramLadder up_to([&ladder, level](int l, bool*) { return ladder.at(std::min(l, level)); },
                                  std::max(level, 1));
    setup.grams = &up_to;
    setup.alpha_tolerance = 1e-12;  // (never met: α on the top level)
    alphas.push_back(infsup::analyse_solid_infsup(setup, infsup::EigenBackend::dense).alpha);
  }
  for (int level = 0; level < 4; ++level) {
    const Eigen::MatrixXd difference = ladder.at(level + 1) - ladder.at(level);
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(difference).eigenvalues().minCoeff(),
              -1e-12 * ladder.at(level).norm())
        << level;
    EXPECT_LE(alphas[level + 1], alphas[level] * (1 + 1e-12)) << level;
  }
  for (int level = 1; level < 4; ++level)
    EXPECT_GT((alphas[level - 1] - alphas[level]) / (alphas[level] - alphas[level + 1]), 3.0) << level;
}

// One cell of T_h and of T_{C,H} along y with p_C = 0: the multipliers are μ(x) ⊗ 1, A_G⁻¹Bᵀμ is
// constant in y, and the cosine modes along y other than the constant do not meet μ, so S_G and G
// are the planar ones times the width and α is the planar α (the planar interpolation norm is
// realized by its kernel: an independent path).
TEST(SolidInfSup, ExtrudedPairingHasThePlanarAlpha) {
  struct Case {
    int n, p, m;
  };
  for (const Case& c : {Case{8, 1, 8}, Case{8, 1, 4}, Case{4, 2, 4}, Case{4, 3, 8}}) {
    const double planar = hpcontact::testing::paper_alpha(c.n, c.p, 0, c.m).alpha;
    const infsup::InfSupResult solid = alpha({c.n, 1, c.p, 0, c.m, 1, 0.7}, infsup::EigenBackend::dense, 1e-6);
    EXPECT_TRUE(solid.alpha_converged || solid.alpha_error < 1e-5 * solid.alpha) << c.n << " " << c.p << " " << c.m;
    EXPECT_NEAR(solid.alpha, planar, 1e-5 * planar) << c.n << " " << c.p << " " << c.m;
  }
}

// Figure 2 in 3-D, on the extruded square with n_y = n: p = 1, p_C = 0 with H = h decays at least
// like h (faster than in 2-D: the surface checkerboard meets Bᵀ only at the corners of Γ_C), and
// p = 2, p_C = 0 with H = 2h stays bounded.
TEST(SolidInfSup, RatioOneDecaysRatioOneHalfStaysBounded) {
  const auto at = [](int n, int p, int m) { return alpha({n, n, p, 0, m, m, 2.0}).alpha; };
  const double unstable[3] = {at(2, 1, 2), at(4, 1, 4), at(8, 1, 8)};
  EXPECT_LT(unstable[1] / unstable[0], 0.55);
  EXPECT_LT(unstable[2] / unstable[1], 0.55);
  const double stable[2] = {at(4, 2, 2), at(8, 2, 4)};
  EXPECT_NEAR(stable[1] / stable[0], 1.0, 0.01);
  EXPECT_GT(stable[1], 0.9);
}

TEST(SolidInfSup, SlepcAgreesWithDensePath) {
  for (const Extruded& c : {Extruded{4, 2, 2, 1, 4, 2}, Extruded{4, 4, 1, 0, 4, 4}, Extruded{2, 2, 3, 2, 2, 2}}) {
    const auto dense = alpha(c, infsup::EigenBackend::dense), slepc = alpha(c, infsup::EigenBackend::slepc);
    EXPECT_NEAR(slepc.alpha, dense.alpha, 1e-8 * std::max(1.0, dense.alpha)) << c.n << " " << c.p << " " << c.pc;
    EXPECT_EQ(slepc.reference_level, dense.reference_level);
  }
}

// Products only (Generalized Davidson on S_G by solves, G by moments) against the dense path: the same ladder
// level, α to 1e-8 and an eigenvector, for stable and unstable pairings, (11) and (22) with supp s
// half of Γ_C, P_0 to Q_2.
TEST(SolidInfSup, ProductsAgreeWithTheDensePath) {
  Extruded friction{4, 2, 2, 1, 4, 2};
  friction.problem = infsup::PairingProblem::friction;
  for (const Extruded& c : {Extruded{4, 2, 2, 1, 4, 2}, Extruded{4, 4, 1, 0, 4, 4}, Extruded{2, 2, 3, 2, 2, 2},
                            Extruded{8, 4, 1, 0, 8, 4}, friction}) {
    const auto dense = alpha(c);
    const auto products = alpha(c, infsup::EigenBackend::dense, 1e-4, contact::SchurPath::products);
    EXPECT_NEAR(products.alpha, dense.alpha, 1e-8 * std::max(1.0, dense.alpha)) << c.n << " " << c.p << " " << c.pc;
    EXPECT_EQ(products.reference_level, dense.reference_level);
    EXPECT_NEAR(products.alpha_error, dense.alpha_error, 1e-6 * dense.alpha);
    // (λ_min is multiple on some of these symmetric grids, so the modes may differ: the mode is
    // checked by its residual, ‖S x − λ G x‖ / (λ_max ‖G x‖), computed outside SLEPc)
    // (λ_max is a scale: a Ritz value from below on the first level's G, a few digits)
    EXPECT_NEAR(products.lambda_max, dense.lambda_max, 0.02 * dense.lambda_max);
    EXPECT_LT(products.residual, 1e-6);
    EXPECT_EQ(products.mode.size(), dense.mode.size());
    EXPECT_NE(products.method.find("products only"), std::string::npos);
  }
}

// `automatic` takes the products from 64 multipliers with SLEPc, never with the dense backend.
TEST(SolidInfSup, AutomaticPathTakesProductsFromSixtyFourMultipliers) {
  using contact::SchurPath;
  EXPECT_FALSE(infsup::uses_alpha_products(SchurPath::automatic, 63, infsup::EigenBackend::slepc));
  EXPECT_TRUE(infsup::uses_alpha_products(SchurPath::automatic, 64, infsup::EigenBackend::slepc));
  EXPECT_FALSE(infsup::uses_alpha_products(SchurPath::automatic, 1 << 20, infsup::EigenBackend::dense));
  EXPECT_TRUE(infsup::uses_alpha_products(SchurPath::products, 1, infsup::EigenBackend::dense));
  EXPECT_FALSE(infsup::uses_alpha_products(SchurPath::dense, 1 << 20, infsup::EigenBackend::slepc));
  const Extruded c{8, 4, 1, 0, 8, 4};  // 32 multipliers at p_C = 0, 128 at p_C = 1
  Extruded many = c;
  many.pc = 1;
  const auto below = alpha(c, infsup::EigenBackend::slepc, 1e-4, SchurPath::automatic);
  const auto above = alpha(many, infsup::EigenBackend::slepc, 1e-4, SchurPath::automatic);
  EXPECT_EQ(below.method.find("products only"), std::string::npos) << below.method;
  EXPECT_NE(above.method.find("products only"), std::string::npos) << above.method;
  EXPECT_NEAR(above.alpha, alpha(many).alpha, 1e-8);
}

// (22): with s ≡ 1 it is the Signorini pairing (11); with s = max(0, −x) the multipliers of the
// T_{C,H} cells in x > 0 are dropped (the mode is 0 there); with s ≡ 0 it is refused.
TEST(SolidInfSup, FrictionPairingKeepsTheCellsOfSuppS) {
  const Extruded c{4, 2, 2, 1, 4, 2};
  const Built built(c);
  const auto friction = [&](assembly::SolidFunction s) {
    infsup::SolidInfSupSetup setup;
    setup.space = &built.space;
    setup.multipliers = &built.multipliers;
    setup.problem = infsup::PairingProblem::friction;
    setup.friction_bound = std::move(s);
    return infsup::analyse_solid_infsup(setup, infsup::EigenBackend::dense);
  };
  EXPECT_NEAR(friction([](const mesh::SolidPoint&) { return 1.0; }).alpha, alpha(c).alpha, 1e-10);
  const infsup::InfSupResult half = friction([](const mesh::SolidPoint& x) { return std::max(0.0, -x(0)); });
  ASSERT_EQ(half.mode.size(), built.multipliers.n_dofs());
  int dropped = 0;
  for (int dof = 0; dof < built.multipliers.n_dofs(); ++dof) {
    const auto [lo, hi] = built.multiplier_mesh.cell_bounds(dof / built.multipliers.per_cell());
    if (built.surface.from_plane(0.5 * (lo + hi))(0) > 0.0) {
      EXPECT_EQ(half.mode(dof), 0.0) << dof;
      ++dropped;
    }
  }
  EXPECT_EQ(dropped, built.multipliers.n_dofs() / 2);
  EXPECT_GT(half.alpha, 0.0);
  EXPECT_THROW(friction([](const mesh::SolidPoint&) { return 0.0; }), InputError);
}

// The elastic pairings in the vector H¹ norm: A_G is K + M on each component, so the normal
// multiplier meets v·n = −v_z alone and α is the scalar α of the z component's space; the
// friction pairing (normal, e_1 = x, e_2 = −y) is the smallest of the three components' α. Each
// component's space holds it where Γ_D clamps the body and where its rollers hold it (x on x = −1,
// y on y = 0): three scalar runs against the vector one.
TEST(SolidInfSup, ElasticPairingIsTheScalarPairingOfEachComponent) {
  const Built built({4, 2, 2, 1, 2, 1, 0.5});
  const std::array<const char*, 3> roller{"x_min", "y_min", ""};
  std::array<std::vector<char>, 3> held;
  for (int c = 0; c < 2; ++c) held[c] = space::faces_labelled(built.mesh, {roller[c]});
  const space::SolidVectorSpace vector_space(built.space, held);
  const auto vector_alpha = [&](infsup::PairingProblem problem, contact::SchurPath path = contact::SchurPath::dense) {
    infsup::SolidInfSupSetup setup;
    setup.space = &built.space;
    setup.vector_space = &vector_space;
    setup.multipliers = &built.multipliers;
    setup.problem = problem;
    setup.alpha_tolerance = 1e-7;
    setup.path = path;
    return infsup::analyse_solid_infsup(setup, infsup::EigenBackend::dense).alpha;
  };
  std::array<double, 3> component{};
  for (int c = 0; c < 3; ++c) {
    const space::SolidH1Space held_space(built.mesh, std::vector<int>(built.mesh.n_cells(), 2),
                                         space::faces_labelled(built.mesh, {"dirichlet", roller[c]}));
    infsup::SolidInfSupSetup setup;
    setup.space = &held_space;
    setup.multipliers = &built.multipliers;
    setup.alpha_tolerance = 1e-7;
    component[c] = infsup::analyse_solid_infsup(setup, infsup::EigenBackend::dense).alpha;
  }
  EXPECT_NEAR(vector_alpha(infsup::PairingProblem::signorini), component[2], 1e-6 * component[2]);
  const double smallest = *std::min_element(component.begin(), component.end());
  EXPECT_NEAR(vector_alpha(infsup::PairingProblem::friction), smallest, 1e-6 * smallest);
  // the three copies of G by products
  EXPECT_NEAR(vector_alpha(infsup::PairingProblem::friction, contact::SchurPath::products), smallest, 1e-6 * smallest);
  // (the rollers make the components differ: the test would not see a swapped direction otherwise)
  EXPECT_GT(std::abs(component[0] - component[2]), 1e-3 * component[2]);
}
