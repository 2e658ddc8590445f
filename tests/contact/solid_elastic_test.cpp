// Frictionless contact of an elastic box (hexahedra and tetrahedra): a column on a rigid floor, held by rollers on its
// sides and clamped on top, sagging under its weight onto the floor below it. u = u_z(z) e_z is then a quadratic in z,
// in the space for p ≥ 2, so the discrete pressure and energy are exact:
//   (λ + 2μ) u'' = ρ,  u(1) = 0,  u(0) = −δ (in contact),  P = ρ/2 − (λ + 2μ) δ.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "basis/quadrature.hpp"
#include "contact/solid_elastic_contact.hpp"
#include "core/error.hpp"
#include "mesh/contact_surface.hpp"
#include "postprocess/solid_field.hpp"
#include "support/slepc_test_environment.hpp"
#include "support/solid_meshes.hpp"

namespace hpcontact::contact {
namespace {

struct Column {
  double rho = 1.0, delta = 0.1;
  assembly::Material material = assembly::lame_parameters(1.0, 0.3, assembly::PlaneModel::strain);
  double stiffness() const { return material.lambda + 2.0 * material.mu; }
  double c() const { return rho / stiffness(); }
  /// u_z(z) in contact.
  double u(double z) const { return 0.5 * c() * z * z + (delta - 0.5 * c()) * z - delta; }
  double pressure() const { return 0.5 * rho - stiffness() * delta; }
  /// ∫_0^1 ½ (λ + 2μ) u'² + ρ u dz over the unit cross-section.
  double energy() const {
    double sum = 0.0;
    const auto& rule = basis::gauss_legendre(4);
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const double z = 0.5 * (rule.points[q] + 1.0), slope = c() * z + delta - 0.5 * c();
      sum += 0.5 * rule.weights[q] * (0.5 * stiffness() * slope * slope + rho * u(z));
    }
    return sum;
  }
};

/// The column on an n³ mesh of degree p (hexahedra, or renumbered Kuhn tetrahedra), T_{C,H} m × m
/// of degree p_C, solved; `check` reads the solution while the spaces live.
void solve_column(const Column& column, int p, int pc, int n, int m,
                  const std::function<void(const space::SolidVectorSpace&, const SolidElasticSolution&)>& check,
                  bool tetrahedra = false, const std::function<void(SolidElasticSetup&)>& adjust = {}) {
  std::vector<double> nodes;
  for (int i = 0; i <= n; ++i) nodes.push_back(static_cast<double>(i) / n);
  const mesh::SolidMesh mesh =
      tetrahedra ? testing::shuffled(mesh::make_tetrahedral_box_mesh({nodes, nodes, nodes}, "column"), 3)
                 : mesh::make_box_mesh(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), {n, n, n});
  const space::SolidH1Space scalar(mesh, std::vector<int>(mesh.n_cells(), p), space::faces_labelled(mesh, {"z_max"}));
  const space::SolidVectorSpace space(
      scalar, {space::faces_labelled(mesh, {"x_min", "x_max"}), space::faces_labelled(mesh, {"y_min", "y_max"}), {}});
  const mesh::FlatContactSurface floor(mesh, {"z_min"}, "test");
  const mesh::SurfaceMultiplierMesh multiplier_mesh(floor, {m, m}, "test");
  const space::SurfaceMultiplierSpace multipliers(multiplier_mesh, pc);
  SolidElasticSetup setup;
  setup.space = &space;
  setup.multipliers = &multipliers;
  setup.materials.assign(mesh.n_cells(), column.material);
  setup.body_force[2] = [&](const mesh::SolidPoint&) { return -column.rho; };
  setup.gap = [&](const mesh::SolidPoint&) { return column.delta; };
  if (adjust) adjust(setup);
  check(space, solve_solid_elastic_contact(setup));
}

TEST(SolidElasticContact, ColumnOnAFloorIsExactForPAtLeastTwo) {
  const Column column;
  ASSERT_GT(column.pressure(), 0.0);
  // On tetrahedra the trace triangles are clipped against T_{C,H} (m = 2 does not align with
  // the diagonals of Kuhn's cubes), and the quadratic u_z is in P_2.
  for (bool tetrahedra : {false, true})
    for (const auto& [p, pc, n, m] : {std::tuple{2, 0, 2, 1}, std::tuple{2, 1, 2, 2}, std::tuple{3, 1, 3, 2}}) {
      const std::string label =
          "p " + std::to_string(p) + " pC " + std::to_string(pc) + (tetrahedra ? " tetrahedra" : " hexahedra");
      solve_column(
          column, p, pc, n, m,
          [&](const space::SolidVectorSpace& space, const SolidElasticSolution& solution) {
            for (Eigen::Index i = 0; i < solution.pressure.size(); ++i)
              EXPECT_NEAR(solution.pressure(i), column.pressure(), 1e-10) << label;
            EXPECT_NEAR(solution.energy, column.energy(), 1e-12) << label;
            EXPECT_LT(solution.gap.lpNorm<Eigen::Infinity>(), 1e-12) << label;
            // u at a point inside: the column's u_z, no lateral motion.
            const Eigen::Vector3d xi = tetrahedra ? Eigen::Vector3d(-0.6, -0.5, -0.4) : Eigen::Vector3d(0.3, -0.2, 0.1);
            const Eigen::Vector3d u = postprocess::solid_displacement(space, solution.u, 0, xi);
            EXPECT_NEAR(u(2), column.u(space.scalar().mesh().map(0, xi)(2)), 1e-12) << label;
            EXPECT_NEAR(u.head<2>().norm(), 0.0, 1e-12) << label;
          },
          tetrahedra);
    }
}

TEST(SolidElasticContact, AColumnAboveTheFloorDoesNotTouchIt) {
  // δ beyond the free sag c/2: no contact, P = 0 and the gap positive everywhere.
  Column column;
  column.delta = 0.5;
  solve_column(column, 2, 1, 2, 2, [](const space::SolidVectorSpace&, const SolidElasticSolution& solution) {
    EXPECT_LT(solution.pressure.lpNorm<Eigen::Infinity>(), 1e-14);
    EXPECT_GT(solution.gap.minCoeff(), 0.0);
  });
}

// solve.trace_operator = "saddle_point": the active set on K's projected CG (GAMG) gives the exact
// column too, in contact and above the floor, on hexahedra and tetrahedra; a direct K is refused.
TEST(SolidElasticContact, SaddlePointWithGamgIsExactOnTheColumn) {
  auto on_the_saddle_point = [](SolidElasticSetup& setup) {
    setup.trace_solve = SchurPath::saddle_point;
    setup.distribution = {linalg::DistributedSolver::gamg, MPI_COMM_WORLD};
  };
  const Column column;
  for (bool tetrahedra : {false, true}) {
    const std::string label = tetrahedra ? "tetrahedra" : "hexahedra";
    solve_column(
        column, 2, 1, 2, 2,
        [&](const space::SolidVectorSpace&, const SolidElasticSolution& solution) {
          EXPECT_EQ(solution.qp.trace_operator, "saddle_point") << label;
          EXPECT_TRUE(solution.qp.converged) << label;
          EXPECT_GT(solution.qp.products, 0) << label;
          for (Eigen::Index i = 0; i < solution.pressure.size(); ++i)
            EXPECT_NEAR(solution.pressure(i), column.pressure(), 1e-8) << label;
          EXPECT_NEAR(solution.energy, column.energy(), 1e-11) << label;
          EXPECT_LT(solution.gap.lpNorm<Eigen::Infinity>(), 1e-12) << label;
        },
        tetrahedra, on_the_saddle_point);
  }
  Column above = column;
  above.delta = 0.5;
  solve_column(
      above, 2, 1, 2, 2,
      [](const space::SolidVectorSpace&, const SolidElasticSolution& solution) {
        EXPECT_EQ(solution.pressure.lpNorm<Eigen::Infinity>(), 0.0);
        EXPECT_GT(solution.gap.minCoeff(), 0.0);
      },
      false, on_the_saddle_point);
  EXPECT_THROW(solve_column(
                   column, 2, 1, 2, 2, [](const space::SolidVectorSpace&, const SolidElasticSolution&) {}, false,
                   [](SolidElasticSetup& setup) { setup.trace_solve = SchurPath::saddle_point; }),
               InputError);
}

}  // namespace
}  // namespace hpcontact::contact
