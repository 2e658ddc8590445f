// Products by the surface interpolation-norm Gram matrix equal the dense G (direct and exponential
// sums, P_0 to Q_2, unequal sides), and T ≈ G⁻¹ clusters the spectrum of T G.
#include "norms/surface_gram_products.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "mesh/contact_surface.hpp"
#include "space/solid_space.hpp"
#include "support/solid_meshes.hpp"

using namespace hpcontact;

namespace {

struct Multipliers {
  Multipliers(int n, int n_y, int m, int m_y, int pc)
      : mesh(hpcontact::testing::extruded_paper_mesh(n, n_y, 0.5)),
        surface(mesh, {"contact"}, "test"),
        multiplier_mesh(surface, {m, m_y}, "test"),
        space(multiplier_mesh, pc) {}
  mesh::SolidMesh mesh;
  mesh::FlatContactSurface surface;
  mesh::SurfaceMultiplierMesh multiplier_mesh;
  space::SurfaceMultiplierSpace space;
};

/// The operator applied to every unit vector: its matrix.
template <class Operator>
Eigen::MatrixXd matrix_of(const Operator& op, Eigen::Index n) {
  Eigen::MatrixXd out(n, n);
  for (Eigen::Index j = 0; j < n; ++j) out.col(j) = op(Eigen::VectorXd::Unit(n, j));
  return out;
}

}  // namespace

TEST(SurfaceGramProducts, EqualTheDenseGramByBothSummations) {
  for (const int pc : {0, 1, 2}) {
    const Multipliers built(8, 4, 4, 2, pc);
    const int n = built.space.n_dofs();
    for (const auto summation : {norms::GramSummation::direct, norms::GramSummation::exponential_sum}) {
      const std::array<int, 2> modes{40 * (pc + 1), 24 * (pc + 1)};
      const Eigen::MatrixXd dense = norms::surface_interpolation_gram(built.space, modes);
      const norms::SurfaceGramProducts products(built.space, modes, summation);
      EXPECT_EQ(products.by_exponential_sum(), summation == norms::GramSummation::exponential_sum);
      const Eigen::MatrixXd by_products = matrix_of(products, n);
      EXPECT_LT((by_products - dense).norm(), 1e-12 * dense.norm()) << "p_C = " << pc;
    }
  }
}

TEST(SurfaceGramProducts, PreconditionerClustersTheSpectrumOfG) {
  for (const int pc : {0, 1}) {
    const Multipliers built(12, 12, 12, 12, pc);
    const int n = built.space.n_dofs();
    const Eigen::MatrixXd gram =
        norms::surface_interpolation_gram(built.space, norms::surface_gram_modes(built.space, 2));
    const Eigen::MatrixXd t = matrix_of(norms::SurfaceGramPreconditioner(built.space), n);
    EXPECT_LT((t - t.transpose()).norm(), 1e-12 * t.norm());
    const Eigen::VectorXd g_values = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(gram).eigenvalues();
    // T G is similar to T^{1/2} G T^{1/2}: the spectrum of the pencil (G, T⁻¹).
    const Eigen::VectorXd tg_values =
        Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>(gram, t.inverse()).eigenvalues();
    const double condition_g = g_values(n - 1) / g_values(0);
    const double condition_tg = tg_values(n - 1) / tg_values(0);
    EXPECT_GT(tg_values(0), 0.0);
    // (measured: κ(G) = 96 and 2.1e3, κ(TG) = 1.4 and 1.5)
    EXPECT_LT(condition_tg, 2.0) << "p_C = " << pc << ": κ(G) = " << condition_g;
    EXPECT_GT(condition_g, 50.0);
  }
}
