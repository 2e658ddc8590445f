// The master side of the mortar coupling, B^m_ij = ∫ μ_i φ^m_j∘Φ ds on the slave's Γ_C, against
// adaptive GSL quadrature of μ · u_h^m(Φ(x)) with Φ known in closed form, for non-matching flat
// interfaces (fully and partly covered) and concentric arcs, random degrees on both sides, for a
// scalar field and for a displacement along the slave's normal and tangent; and the
// patch test of tied contact between two blocks with non-matching meshes.
#include "assembly/mortar_coupling.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "assembly/coupling.hpp"
#include "assembly/poisson_assembly.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "postprocess/fe_function.hpp"
#include "support/adaptive_integral.hpp"
#include "support/annulus_sector.hpp"

using namespace hpcontact;
using mesh::Point;

namespace {

// A pair of bodies, the closed form of Φ on the slave's Γ_C (nullopt where the master does not
// cover it) and the slave arc lengths where the integrand may have kinks.
struct PairCase {
  std::string name;
  mesh::Mesh master, slave;
  std::function<std::optional<Point>(const Point&)> phi;
};

mesh::Mesh with_contact(mesh::Mesh mesh, const std::function<bool(const Point&)>& on_contact) {
  mesh::assign_boundary_part(mesh, mesh::BoundaryPart::contact, on_contact);
  return mesh;
}

// The master's top y = −1 on (−w, w) in n cells, the slave's bottom y = −0.99 on (−0.8, 0.8) in 3.
PairCase flat_case(double w, int n) {
  return {"flat, master half-width " + std::to_string(w),
          with_contact(mesh::make_rectangle_mesh({-w, w, -2.0, -1.0}, n, 2),
                       [](const Point& p) { return p.y() > -1.0 - 1e-12; }),
          with_contact(mesh::make_rectangle_mesh({-0.8, 0.8, -0.99, 0.0}, 3, 2),
                       [](const Point& p) { return p.y() < -0.99 + 1e-12; }),
          [w](const Point& x) -> std::optional<Point> {
            if (std::abs(x.x()) > w) return std::nullopt;
            return Point(x.x(), -1.0);
          }};
}

// The master's arc r = 2, θ ∈ (0, π/2) in 5 cells, the slave's r = 2.05, θ ∈ (0.1, 1.4) in 3.
PairCase arc_case() {
  using std::numbers::pi;
  return {"concentric arcs",
          with_contact(hpcontact::testing::annulus_sector_mesh(1.0, 2.0, 0.0, pi / 2, 2, 5),
                       [](const Point& p) { return p.norm() > 1.99; }),
          with_contact(hpcontact::testing::annulus_sector_mesh(2.05, 3.0, 0.1, 1.4, 2, 3),
                       [](const Point& p) { return p.norm() < 2.06; }),
          [](const Point& x) -> std::optional<Point> { return Point(2.0 * x.normalized()); }};
}

struct Integrand {
  const PairCase* pair;
  const mesh::ContactBoundary* slave;
  const space::H1Space* space;
  const Eigen::VectorXd* u;
  const postprocess::PointLocator* locator;
  const space::MultiplierSpace* multipliers;
  const Eigen::VectorXd* mu;
};

double integrand(double s, void* data) {
  const auto& d = *static_cast<Integrand*>(data);
  const auto image = d.pair->phi(d.slave->point_at(s));
  if (!image) return 0.0;
  return postprocess::evaluate_at(*d.space, *d.u, *d.locator, *image).value * d.multipliers->evaluate(*d.mu, s);
}

// μ (u_h, w_h)∘Φ · d_s: the directional pairing, d the slave's normal or tangent.
struct DirectionalIntegrand {
  Integrand scalar;
  const Eigen::VectorXd* w;
  assembly::TraceDirection direction;
};

double directional_integrand(double s, void* data) {
  const auto& d = *static_cast<DirectionalIntegrand*>(data);
  const auto image = d.scalar.pair->phi(d.scalar.slave->point_at(s));
  if (!image) return 0.0;
  const Point direction = assembly::trace_direction(*d.scalar.slave, s, d.direction);
  const double u = postprocess::evaluate_at(*d.scalar.space, *d.scalar.u, *d.scalar.locator, *image).value;
  const double w = postprocess::evaluate_at(*d.scalar.space, *d.w, *d.scalar.locator, *image).value;
  return (u * direction.x() + w * direction.y()) * d.scalar.multipliers->evaluate(*d.scalar.mu, s);
}

}  // namespace

TEST(MortarCoupling, ExactOnTheMortarSegmentsAgainstAdaptiveQuadrature) {
  std::mt19937 generator(11);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (const auto& pair : {flat_case(1.0, 5), flat_case(0.5, 5), arc_case()}) {
    const mesh::ContactBoundary master(pair.master), slave(pair.slave);
    const mesh::MasterProjection projection(master);
    const postprocess::PointLocator locator(pair.master);
    for (int m : {2, 4, 7}) {
      std::vector<int> degrees(pair.master.n_cells());
      for (int& p : degrees) p = std::uniform_int_distribution<int>(1, 5)(generator);
      const space::H1Space space(pair.master, degrees);
      const auto boundary = mesh::BoundaryMesh::uniform(slave.length(), m);
      std::vector<int> pc(m);
      for (int& d : pc) d = std::uniform_int_distribution<int>(0, 4)(generator);
      const space::MultiplierSpace multipliers(boundary, pc);
      Eigen::VectorXd u(space.n_dofs()), mu(multipliers.n_dofs());
      for (auto& v : u) v = uniform(generator);
      for (auto& v : mu) v = uniform(generator);
      const auto b = assembly::assemble_mortar_coupling(space, projection, slave, multipliers);
      ASSERT_EQ(b.rows(), multipliers.n_dofs());
      ASSERT_EQ(b.cols(), space.n_dofs());
      // μᵀ B^m u by adaptive quadrature, the breakpoints of the slave, T_{C,H} and Φ given.
      std::vector<double> breakpoints = slave.breakpoints();
      for (double s : boundary.nodes()) breakpoints.push_back(s);
      for (double s : projection.slave_breakpoints(slave)) breakpoints.push_back(s);
      Integrand data{&pair, &slave, &space, &u, &locator, &multipliers, &mu};
      const double pairing = mu.dot(b * u);
      const double reference = hpcontact::testing::adaptive_integral(integrand, &data, breakpoints);
      EXPECT_NEAR(pairing, reference, 1e-11 * (1.0 + std::abs(reference))) << pair.name << ", m = " << m;
      // The elastic master side: (u, w)∘Φ paired along the slave's normal and tangent.
      const space::VectorSpace vector_space(space);
      Eigen::VectorXd w(space.n_dofs()), uw(vector_space.n_dofs());
      for (auto& v : w) v = uniform(generator);
      for (int dof = 0; dof < space.n_dofs(); ++dof) {
        uw(vector_space.dof(dof, 0)) = u(dof);
        uw(vector_space.dof(dof, 1)) = w(dof);
      }
      for (const auto direction : {assembly::TraceDirection::normal, assembly::TraceDirection::tangent}) {
        const auto bd =
            assembly::assemble_directional_mortar_coupling(vector_space, projection, slave, multipliers, direction);
        DirectionalIntegrand directional{data, &w, direction};
        const double expected = hpcontact::testing::adaptive_integral(directional_integrand, &directional, breakpoints);
        EXPECT_NEAR(mu.dot(bd * uw), expected, 1e-11 * (1.0 + std::abs(expected)))
            << pair.name << ", m = " << m << (direction == assembly::TraceDirection::normal ? ", normal" : ", tangent");
      }
    }
  }
}

// The mortar patch test of tied contact: two blocks meeting along y = −1 with non-matching meshes
// (the master (−1, 1) × (−2, −1) in 5 × 2 cells, clamped at y = −2; the slave (−1, 1) × (−1, 0) in
// 3 × 2 cells, free elsewhere) and u = (y + 2)(c + d x), harmonic and in Q_p for every p ≥ 1. With
// the flux λ = −∂u/∂n_s = c + d x in M^{p_C} (p_C ≥ 1), the saddle point
//   [K_s 0 B_sᵀ; 0 K_m −B_mᵀ; B_s −B_m 0] [u_s; u_m; λ] = [f_s; f_m; 0]
// is solved by u itself: the discrete solution must be u to round-off on both bodies, and λ_h the flux.
TEST(MortarCoupling, TiedNonMatchingBlocksReproduceABilinearSolution) {
  const double c = 0.7, d = -0.4;
  const auto exact = [&](const Point& x) { return (x.y() + 2.0) * (c + d * x.x()); };
  const auto flux = [&](const Point& x, const Point& normal) {
    return Point(d * (x.y() + 2.0), c + d * x.x()).dot(normal);  // ∂u/∂n on the Neumann edges
  };
  auto master_mesh = mesh::make_rectangle_mesh({-1.0, 1.0, -2.0, -1.0}, 5, 2);
  mesh::assign_boundary_part(master_mesh, mesh::BoundaryPart::contact,
                             [](const Point& p) { return p.y() > -1.0 - 1e-12; });
  mesh::assign_boundary_part(master_mesh, mesh::BoundaryPart::dirichlet,
                             [](const Point& p) { return p.y() < -2.0 + 1e-12; });
  auto slave_mesh = mesh::make_rectangle_mesh({-1.0, 1.0, -1.0, 0.0}, 3, 2);
  mesh::assign_boundary_part(slave_mesh, mesh::BoundaryPart::contact,
                             [](const Point& p) { return p.y() < -1.0 + 1e-12; });
  const mesh::ContactBoundary master(master_mesh), slave(slave_mesh);
  const mesh::MasterProjection projection(master);
  const postprocess::PointLocator master_locator(master_mesh), slave_locator(slave_mesh);
  for (const auto& [p, pc, m] : std::vector<std::array<int, 3>>{{1, 1, 1}, {2, 1, 2}, {3, 2, 2}, {4, 1, 1}}) {
    const space::H1Space master_space(master_mesh, p), slave_space(slave_mesh, p);
    const auto boundary = mesh::BoundaryMesh::uniform(slave.length(), m);
    const space::MultiplierSpace multipliers(boundary, pc);
    const int ns = slave_space.n_dofs(), nm = master_space.n_dofs(), nl = multipliers.n_dofs();
    const Eigen::MatrixXd bs = assembly::assemble_coupling(slave_space, slave, multipliers);
    const Eigen::MatrixXd bm = assembly::assemble_mortar_coupling(master_space, projection, slave, multipliers);
    Eigen::MatrixXd system = Eigen::MatrixXd::Zero(ns + nm + nl, ns + nm + nl);
    system.block(0, 0, ns, ns) = assembly::assemble_volume_matrices(slave_space, {}).stiffness;
    system.block(ns, ns, nm, nm) = assembly::assemble_volume_matrices(master_space, {}).stiffness;
    system.block(ns + nm, 0, nl, ns) = bs;
    system.block(ns + nm, ns, nl, nm) = -bm;
    system.block(0, ns + nm, ns, nl) = bs.transpose();
    system.block(ns, ns + nm, nm, nl) = -bm.transpose();
    Eigen::VectorXd load = Eigen::VectorXd::Zero(ns + nm + nl);
    load.head(ns) = assembly::assemble_boundary_load(slave_space, {mesh::BoundaryPart::neumann}, flux);
    load.segment(ns, nm) = assembly::assemble_boundary_load(master_space, {mesh::BoundaryPart::neumann}, flux);
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(system);
    ASSERT_TRUE(lu.isInvertible()) << "p " << p << " pC " << pc << " m " << m;
    const Eigen::VectorXd solution = lu.solve(load);
    const Eigen::VectorXd us = solution.head(ns), um = solution.segment(ns, nm), lambda = solution.tail(nl);
    double error = 0.0;
    for (double x = -1.0; x <= 1.0; x += 0.125)
      for (double y = -1.875; y <= -0.125; y += 0.125) {
        const Point point(x, y);
        const double value = y > -1.0 ? postprocess::evaluate_at(slave_space, us, slave_locator, point).value
                                      : postprocess::evaluate_at(master_space, um, master_locator, point).value;
        error = std::max(error, std::abs(value - exact(point)));
      }
    EXPECT_LT(error, 1e-12) << "p " << p << " pC " << pc << " m " << m;
    for (double s = 0.0; s <= slave.length(); s += 0.1)
      EXPECT_NEAR(multipliers.evaluate(lambda, s), c + d * slave.point_at(s).x(), 1e-11) << "s = " << s;
  }
}
