// Contact between two elastic bodies on non-matching meshes (contact/two_body_contact.hpp): the
// contact patch test (uniform compression of two blocks of different materials reproduced to
// round-off, quadrilaterals and triangles, p = 1…4, pressure uniform, for every multiplier family),
// KKT at the constraint points with friction, the rigid limit (a stiff master reproduces the
// one-body solver), and α of the pair (a mirrored master, SLEPc against LAPACK, the families).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "assembly/cell_field.hpp"
#include "contact/two_body_contact.hpp"
#include "infsup/infsup_analysis.hpp"
#include "infsup/infsup_operators.hpp"
#include "mesh/boundary_mesh.hpp"
#include "mesh/contact_pair_geometry.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "mesh/refine.hpp"
#include "norms/gram_ladder.hpp"
#include "postprocess/boundary_samples.hpp"
#include "postprocess/point_locator.hpp"
#include "support/elastic_kkt.hpp"
#include "support/slepc_test_environment.hpp"

using namespace hpcontact;
using mesh::Point;

namespace {

constexpr double kEps = 1e-12;

// A block (x_min, x_max) × (y_min, y_max) with Γ_C on one side, u_x = 0 on its left side and
// u_y fixed on the side `fixed_y_at` (a y coordinate).
struct Block {
  mesh::Rectangle rectangle;
  mesh::Mesh mesh;
  std::unique_ptr<operators::ElasticOperators> operators;

  Block(const mesh::Rectangle& r, int n_x, int n_y, bool triangles, int p, double young, double poisson,
        double contact_y, double fixed_y_at)
      : rectangle(r), mesh(mesh::make_rectangle_mesh(r, n_x, n_y)) {
    if (triangles) mesh = mesh::split_into_triangles(mesh);
    mesh::assign_boundary_part(mesh, mesh::BoundaryPart::contact,
                               [&](const Point& x) { return std::abs(x.y() - contact_y) < kEps; });
    std::array<std::vector<char>, space::kComponents> fixed;
    for (auto& mask : fixed) mask.assign(mesh.n_edges(), 0);
    for (int e : mesh.boundary_edges()) {
      const Point x = mesh.edge_midpoint(e);
      fixed[0][e] = std::abs(x.x() - r.x_min) < kEps;
      fixed[1][e] = std::abs(x.y() - fixed_y_at) < kEps;
    }
    operators = std::make_unique<operators::ElasticOperators>(
        mesh, std::vector<int>(mesh.n_cells(), p),
        std::vector<assembly::Material>(mesh.n_cells(),
                                        assembly::lame_parameters(young, poisson, assembly::PlaneModel::strain)),
        nullptr, fixed);
  }
};

// The slave on top: (−1, 1) × (g₀, 1 + g₀), its top pushed down by δ, its bottom Γ_C; the master
// below: (−1, 1) × (−1, 0), its bottom on rollers, its top Γ_C. Plane strain, sides free.
// The softer block (E = 1, ν = 0.3) is the slave, or with `stiff_slave` the master (the other
// block E = 3, ν = 0.2).
struct CompressedBlocks {
  double gap0 = 0.01, delta = 0.05;
  double e_slave, nu_slave, e_master, nu_master;
  Block slave, master;
  std::unique_ptr<mesh::BoundaryMesh> boundary_mesh;

  CompressedBlocks(int p, bool slave_triangles, int m_segments, bool stiff_slave = false)
      : e_slave(stiff_slave ? 3.0 : 1.0),
        nu_slave(stiff_slave ? 0.2 : 0.3),
        e_master(stiff_slave ? 1.0 : 3.0),
        nu_master(stiff_slave ? 0.3 : 0.2),
        slave({-1.0, 1.0, 0.01, 1.01}, 3, 3, slave_triangles, p, e_slave, nu_slave, 0.01, 1.01),
        master({-1.0, 1.0, -1.0, 0.0}, 5, 5, false, p, e_master, nu_master, 0.0, -1.0),
        boundary_mesh(std::make_unique<mesh::BoundaryMesh>(
            mesh::BoundaryMesh::uniform(slave.operators->contact().length(), m_segments))) {}

  // 1/E' = (1 − ν²)/E of plane strain under uniaxial stress σ_yy with σ_xx = 0.
  double compliance(double young, double poisson) const { return (1.0 - poisson * poisson) / young; }
  double pressure() const { return (delta - gap0) / (compliance(e_slave, nu_slave) + compliance(e_master, nu_master)); }
  // u = (ν(1 + ν) p/E (x + 1), −(1 − ν²) p/E (y − y_fixed)) in each block.
  Eigen::Vector2d exact(const Point& x) const {
    const bool upper = x.y() > 0.005;
    const double young = upper ? e_slave : e_master, poisson = upper ? nu_slave : nu_master;
    const double y_fixed = upper ? 1.01 : -1.0, shift = upper ? -delta : 0.0;
    return {poisson * (1.0 + poisson) * pressure() / young * (x.x() + 1.0),
            shift - compliance(young, poisson) * pressure() * (x.y() - y_fixed)};
  }

  contact::TwoBodyContactSetup setup(contact::ElasticContactProblem problem, int pc, double threshold = 0.05,
                                     double coefficient = 0.3) const {
    contact::TwoBodyContactSetup s;
    s.slave.operators = slave.operators.get();
    s.slave.boundary_mesh = boundary_mesh.get();
    s.slave.segment_degrees.assign(boundary_mesh->n_segments(), pc);
    s.slave.problem = problem;
    const double shift = -delta;
    s.slave.dirichlet[1] = [shift](const Point&) { return shift; };
    s.slave.threshold = [threshold](const Point&) { return threshold; };
    s.slave.friction_coefficient = coefficient;
    s.master.operators = master.operators.get();
    return s;
  }
};

// max |u_h − u| over a grid of points of one block, relative to max |u|.
double relative_error(const CompressedBlocks& blocks, const Block& block, const contact::BodyDisplacement& u) {
  const postprocess::PointLocator locator(block.mesh);
  std::vector<postprocess::CellPoint> points;
  std::vector<Point> xs;
  for (double x = -1.0; x <= 1.0 + kEps; x += 0.125)
    for (int j = 0; j <= 8; ++j) {
      const double y_min = block.rectangle.y_min, y_max = block.rectangle.y_max;
      xs.emplace_back(x, y_min + (y_max - y_min) * j / 8.0);
      points.push_back(*locator.locate(xs.back()));
    }
  const Eigen::MatrixXd values = postprocess::values_at(
      assembly::vector_field(block.operators->vector_space(), u.u, u.u_rows, u.lift), points, {});
  double error = 0.0, scale = 0.0;
  for (std::size_t k = 0; k < xs.size(); ++k) {
    const Eigen::Vector2d exact = blocks.exact(xs[k]);
    error = std::max(error, (values.row(static_cast<Eigen::Index>(k)).transpose() - exact).lpNorm<Eigen::Infinity>());
    scale = std::max(scale, exact.lpNorm<Eigen::Infinity>());
  }
  return error / scale;
}

// Both bodies' displacements equal the patch test's linear field to 1e-10 (relative).
void expect_exact_displacements(const CompressedBlocks& blocks, const contact::TwoBodyContactSolution& solution,
                                const std::string& where) {
  const contact::BodyDisplacement slave{solution.contact.u, solution.contact.u_rows, solution.contact.n_dofs,
                                        solution.contact.lift};
  EXPECT_LT(relative_error(blocks, blocks.slave, slave), 1e-10) << "slave, " << where;
  EXPECT_LT(relative_error(blocks, blocks.master, solution.master), 1e-10) << "master, " << where;
}

// (s, (u_s − u_m)·t) along the interface of the compressed blocks, t = (1, 0) (s = x + 1).
std::vector<std::pair<double, double>> interface_slip(const CompressedBlocks& blocks,
                                                      const contact::TwoBodyContactSolution& solution) {
  const auto at = [](const Block& block, const contact::BodyDisplacement& u, double y, int samples) {
    const postprocess::PointLocator locator(block.mesh);
    std::vector<postprocess::CellPoint> points;
    for (int k = 0; k < samples; ++k) points.push_back(*locator.locate(Point(-0.95 + 1.9 * k / (samples - 1), y)));
    return postprocess::values_at(assembly::vector_field(block.operators->vector_space(), u.u, u.u_rows, u.lift),
                                  points, {});
  };
  const contact::BodyDisplacement slave{solution.contact.u, solution.contact.u_rows, solution.contact.n_dofs,
                                        solution.contact.lift};
  const int samples = 39;
  const Eigen::MatrixXd u_s = at(blocks.slave, slave, 0.01, samples),
                        u_m = at(blocks.master, solution.master, 0.0, samples);
  std::vector<std::pair<double, double>> slip;
  for (int k = 0; k < samples; ++k) slip.emplace_back(0.05 + 1.9 * k / (samples - 1), u_s(k, 0) - u_m(k, 0));
  return slip;
}

}  // namespace

TEST(TwoBodyContact, PatchTestOfUniformCompressionIsExactOnNonMatchingMeshes) {
  for (const bool triangles : {false, true})
    for (int p = 1; p <= 4; ++p)
      for (const int pc : {0, 1}) {
        const CompressedBlocks blocks(p, triangles, 4);
        const auto solution =
            contact::solve_two_body_contact(blocks.setup(contact::ElasticContactProblem::frictionless, pc));
        const std::string where = (triangles ? "triangles" : "quadrilaterals") + std::string(", p ") +
                                  std::to_string(p) + ", p_C " + std::to_string(pc);
        expect_exact_displacements(blocks, solution, where);
        // The pressure is the constant p in every segment's Legendre expansion.
        const space::MultiplierSpace multipliers(*blocks.boundary_mesh, std::vector<int>(4, pc));
        for (int k = 0; k < multipliers.n_segments(); ++k) {
          const int first = multipliers.first_dof(k);
          EXPECT_NEAR(solution.contact.pressure(first), blocks.pressure(), 1e-10 * blocks.pressure()) << where;
          for (int j = 1; j <= pc; ++j) EXPECT_NEAR(solution.contact.pressure(first + j), 0.0, 1e-10) << where;
        }
      }
}

// Every standard and dual family (with and without the end modification) reproduces constants, so
// each passes the patch test: T_{C,H} the slave's trace mesh, p_C = p − 1 and p.
TEST(TwoBodyContact, EveryMultiplierFamilyPassesThePatchTest) {
  using space::MultiplierFamilyKind;
  for (const auto kind : {MultiplierFamilyKind::standard, MultiplierFamilyKind::dual})
    for (const bool modified : {false, true})
      for (const bool triangles : {false, true})
        for (int p = 1; p <= 3; ++p)
          for (const int pc : {p - 1, p}) {
            if (pc < 1) continue;
            const CompressedBlocks blocks(p, triangles, 3);
            auto setup = blocks.setup(contact::ElasticContactProblem::frictionless, pc);
            setup.slave.family = {kind, modified};
            const auto solution = contact::solve_two_body_contact(setup);
            const std::string where = space::to_string(setup.slave.family) + (triangles ? ", triangles" : "") + ", p " +
                                      std::to_string(p) + ", p_C " + std::to_string(pc);
            expect_exact_displacements(blocks, solution, where);
            const space::MultiplierSpace multipliers(*blocks.boundary_mesh, std::vector<int>(3, pc));
            for (double s : {0.0, 0.3, 0.99, 1.5, 2.0})
              EXPECT_NEAR(multipliers.evaluate(solution.contact.pressure, s), blocks.pressure(),
                          1e-10 * blocks.pressure())
                  << where << ", s = " << s;
          }
}

TEST(TwoBodyContact, FrictionSatisfiesKktAndOpposesTheSlip) {
  // The blocks' Poisson ratios differ: the softer one (ν = 0.3, E = 1) widens more, so the slave
  // slides towards +x against the master when it is the softer one, towards −x when the master
  // is (the master's own motion then decides the sign: a wrong sign of its tangential trace
  // would show). Holding the interface would take |σ_nt| up to about 6e-3; with friction 1e-3
  // (Tresca s; Coulomb F p with F = 0.03) it slides where the traction is at its bound, and
  // there friction opposes the slip (u_s − u_m∘Φ)·t: σ_nt (u_s − u_m)·t ≤ 0.
  for (const bool stiff_slave : {false, true})
    for (const auto problem : {contact::ElasticContactProblem::tresca, contact::ElasticContactProblem::coulomb}) {
      const CompressedBlocks blocks(3, false, 4, stiff_slave);
      const auto frictionless =
          contact::solve_two_body_contact(blocks.setup(contact::ElasticContactProblem::frictionless, 1));
      const std::string where = contact::to_string(problem) + (stiff_slave ? ", stiff slave" : ", soft slave");
      const auto solution = contact::solve_two_body_contact(blocks.setup(problem, 1, 1e-3, 0.03));
      hpcontact::testing::expect_kkt(solution.contact, 1e-9);
      EXPECT_GT((solution.contact.u - frictionless.contact.u).norm(), 1e-6 * frictionless.contact.u.norm()) << where;
      const Eigen::Index n = solution.contact.n_normal;
      const double scale = solution.contact.lambda.lpNorm<Eigen::Infinity>();
      for (Eigen::Index j = 0; j < n; ++j) {
        const double pressure = -solution.contact.lambda(j), shear = std::abs(solution.contact.lambda(n + j));
        const double bound = problem == contact::ElasticContactProblem::tresca ? 1e-3 : 0.03 * std::max(pressure, 0.0);
        EXPECT_LE(shear, bound + 1e-10 * scale) << where << ", point " << j;
      }
      const auto slip = interface_slip(blocks, solution);
      const space::MultiplierSpace multipliers(*blocks.boundary_mesh, std::vector<int>(4, 1));
      double largest_slip = 0.0;
      for (const auto& [s, du] : slip) largest_slip = std::max(largest_slip, std::abs(du));
      EXPECT_GT(largest_slip, 1e-3) << where << ": the interface slides";
      for (const auto& [s, du] : slip)
        if (std::abs(du) > 1e-2 * largest_slip) {
          EXPECT_LE(multipliers.evaluate(solution.contact.shear, s) * du, 0.0) << where << ", s = " << s;
        }
    }
}

TEST(TwoBodyContact, AStiffClampedMasterReproducesTheRigidObstacle) {
  // The paper's square hanging from Γ_D, pulled down by f = (0, −1) onto a master block clamped at
  // its bottom, 1e10 times stiffer, whose top is tilted so that the contact set is partial.
  const double ratio = 1e10;
  auto slave_mesh = mesh::make_paper_square_mesh(8);
  auto master_mesh = mesh::make_rectangle_mesh({-1.5, 1.5, -4.0, -1.0}, 6, 3);
  std::vector<Point> moved = master_mesh.vertices();
  for (auto& x : moved) x.y() -= (x.y() + 4.0) / 3.0 * (0.1 + 0.5 * (1.0 + x.x()));
  master_mesh.move_vertices(moved, "tilted master");
  mesh::assign_boundary_part(master_mesh, mesh::BoundaryPart::contact, [](const Point& x) { return x.y() > -3.9; });
  mesh::assign_boundary_part(master_mesh, mesh::BoundaryPart::dirichlet,
                             [](const Point& x) { return x.y() < -4.0 + kEps; });
  // Sides of the master are free; only its top is Γ_C.
  mesh::assign_boundary_part(master_mesh, mesh::BoundaryPart::neumann,
                             [](const Point& x) { return std::abs(std::abs(x.x()) - 1.5) < kEps; });
  const auto material = [](double young) {
    return assembly::lame_parameters(young, 0.3, assembly::PlaneModel::strain);
  };
  const operators::ElasticOperators slave(slave_mesh, std::vector<int>(slave_mesh.n_cells(), 3),
                                          std::vector<assembly::Material>(slave_mesh.n_cells(), material(1.0)));
  const operators::ElasticOperators master(master_mesh, std::vector<int>(master_mesh.n_cells(), 3),
                                           std::vector<assembly::Material>(master_mesh.n_cells(), material(ratio)));
  const auto boundary_mesh = mesh::BoundaryMesh::uniform(slave.contact().length(), 8);
  contact::TwoBodyContactSetup pair;
  pair.slave.operators = &slave;
  pair.slave.boundary_mesh = &boundary_mesh;
  pair.slave.segment_degrees.assign(8, 1);
  pair.slave.body_force = [](const Point&) { return Eigen::Vector2d(0.0, -1.0); };
  pair.master.operators = &master;
  const auto two_bodies = contact::solve_two_body_contact(pair);

  // The one-body solver with the same gap to the master's top, along the slave's normal (0, −1).
  const mesh::MasterProjection projection(master.contact());
  contact::ElasticContactSetup one_body = pair.slave;
  one_body.gap = [&](const Point& x) { return x.y() - projection.project(x).point.y(); };
  const auto rigid = contact::solve_elastic_contact(one_body);

  hpcontact::testing::expect_kkt(two_bodies.contact, 1e-9);
  const Eigen::Index n = rigid.lambda.size();
  int in_contact = 0;
  for (Eigen::Index j = 0; j < n; ++j) in_contact += rigid.lambda(j) < -1e-8 * rigid.lambda.lpNorm<Eigen::Infinity>();
  EXPECT_GT(in_contact, 0);
  EXPECT_LT(in_contact, n) << "a partial contact set";
  EXPECT_LT((two_bodies.contact.u - rigid.u).norm(), 1e-8 * rigid.u.norm());
  EXPECT_LT((two_bodies.contact.pressure - rigid.pressure).norm(), 1e-8 * rigid.pressure.norm());
  EXPECT_LT(two_bodies.master.u.lpNorm<Eigen::Infinity>(), 1e-8 * rigid.u.lpNorm<Eigen::Infinity>());
}

namespace {

// A block (−1, 1) × (0, 1) (above) or its mirror image (−1, 1) × (−1, 0) (below), n × n cells,
// Γ_C on the shared line y = 0, clamped on the far side; p = 3.
struct MirroredBlock {
  mesh::Mesh mesh;
  std::unique_ptr<operators::ElasticOperators> operators;

  MirroredBlock(bool above, int n, double young)
      : mesh(mesh::make_rectangle_mesh({-1.0, 1.0, above ? 0.0 : -1.0, above ? 1.0 : 0.0}, n, n)) {
    mesh::assign_boundary_part(mesh, mesh::BoundaryPart::contact,
                               [](const Point& x) { return std::abs(x.y()) < kEps; });
    mesh::assign_boundary_part(mesh, mesh::BoundaryPart::dirichlet,
                               [](const Point& x) { return std::abs(std::abs(x.y()) - 1.0) < kEps; });
    operators = std::make_unique<operators::ElasticOperators>(
        mesh, std::vector<int>(mesh.n_cells(), 3),
        std::vector<assembly::Material>(mesh.n_cells(),
                                        assembly::lame_parameters(young, 0.3, assembly::PlaneModel::strain)));
  }
};

infsup::InfSupSetup pair_setup(const MirroredBlock& slave, const mesh::BoundaryMesh& boundary, int pc,
                               infsup::PairingProblem problem, operators::PrimalNorm norm) {
  infsup::InfSupSetup setup;
  setup.mesh = &slave.mesh;
  setup.cell_degrees.assign(slave.mesh.n_cells(), 3);
  setup.boundary_mesh = &boundary;
  setup.segment_degrees.assign(boundary.n_segments(), pc);
  setup.problem = problem;
  setup.elastic = slave.operators.get();
  setup.primal_norm = norm;
  return setup;
}

}  // namespace

TEST(TwoBodyInfSup, AMirroredMasterAddsTheSlavesShareReflected) {
  // The master is the slave's mirror image (x, y) ↦ (x, −y) with the same mesh; a displacement
  // reflected with it has the same norm (H¹ and energy), the opposite normal trace along n_s and
  // the same tangential one. So the master's share of S_G is D S_s D with D = diag(−I, I) on
  // (normal; tangential) multipliers: S_G = 2 S_s for the normal pairing, whose α grows by √2.
  const MirroredBlock slave(true, 4, 1.0), master(false, 4, 1.0);
  const mesh::MasterProjection projection(master.operators->contact());
  const auto boundary = mesh::BoundaryMesh::uniform(2.0, 4);
  for (const auto problem : {infsup::PairingProblem::signorini, infsup::PairingProblem::friction})
    for (const auto norm : {operators::PrimalNorm::h1, operators::PrimalNorm::energy}) {
      const std::string where = infsup::to_string(problem) + ", " + operators::to_string(norm);
      auto setup = pair_setup(slave, boundary, 2, problem, norm);
      const Eigen::MatrixXd alone = infsup::assemble_infsup_operators(setup).s_g;
      const double alpha_alone = infsup::analyse_infsup(setup, infsup::EigenBackend::dense).alpha;
      setup.master = master.operators.get();
      setup.projection = &projection;
      const auto pair = infsup::assemble_infsup_operators(setup);
      Eigen::VectorXd d = Eigen::VectorXd::Ones(alone.rows());
      d.head(alone.rows() / pair.gram_copies).setConstant(-1.0);
      const Eigen::MatrixXd expected = alone + d.asDiagonal() * alone * d.asDiagonal();
      EXPECT_LT((pair.s_g - expected).lpNorm<Eigen::Infinity>(), 1e-12 * alone.lpNorm<Eigen::Infinity>()) << where;
      EXPECT_EQ(pair.n_primal_dofs, slave.operators->n_dofs() + master.operators->n_dofs()) << where;
      if (problem == infsup::PairingProblem::signorini) {
        EXPECT_NEAR(infsup::analyse_infsup(setup, infsup::EigenBackend::dense).alpha, std::sqrt(2.0) * alpha_alone,
                    1e-10 * alpha_alone)
            << where;
      }
    }
}

TEST(TwoBodyInfSup, ANonMatchingMasterRaisesAlphaAndBothEigensolversAgree) {
  // α² of a pair is λ_min of (S_s + S_m) against G: at least the slave's own α² (S_m ≥ 0).
  const MirroredBlock slave(true, 3, 1.0), master(false, 5, 2.0);
  const mesh::MasterProjection projection(master.operators->contact());
  const auto boundary = mesh::BoundaryMesh::uniform(2.0, 3);
  auto setup = pair_setup(slave, boundary, 1, infsup::PairingProblem::signorini, operators::PrimalNorm::h1);
  const double slave_alone = infsup::analyse_infsup(setup, infsup::EigenBackend::dense).alpha;
  setup.master = master.operators.get();
  setup.projection = &projection;
  const double pair = infsup::analyse_infsup(setup, infsup::EigenBackend::slepc).alpha;
  EXPECT_GT(pair, slave_alone * (1.0 + 1e-3));
  EXPECT_NEAR(pair, infsup::analyse_infsup(setup, infsup::EigenBackend::dense).alpha, 1e-8 * pair)
      << "SLEPc and dense LAPACK agree";
}

// α of a family is λ_min of the pencil restricted to its functions T: (Tᵀ S_G T, Tᵀ G T), here
// rebuilt from the discontinuous pencil and the family's Legendre coefficients; SLEPc and dense
// LAPACK agree on it.
TEST(TwoBodyInfSup, AFamilysAlphaIsThatOfTheRestrictedPencil) {
  const MirroredBlock slave(true, 3, 1.0), master(false, 5, 2.0);
  const mesh::MasterProjection projection(master.operators->contact());
  const auto boundary = mesh::BoundaryMesh::uniform(2.0, 3);
  auto setup = pair_setup(slave, boundary, 3, infsup::PairingProblem::signorini, operators::PrimalNorm::h1);
  setup.master = master.operators.get();
  setup.projection = &projection;
  const Eigen::MatrixXd s_g = infsup::assemble_infsup_operators(setup).s_g;  // discontinuous: every mode
  const space::MultiplierSpace multipliers(boundary, std::vector<int>(3, 3));
  const auto ladder = norms::interpolation_gram_ladder(multipliers);
  for (const auto kind : {space::MultiplierFamilyKind::standard, space::MultiplierFamilyKind::dual})
    for (const bool modified : {false, true}) {
      setup.family = {kind, modified};
      const auto result = infsup::analyse_infsup(setup, infsup::EigenBackend::dense);
      const Eigen::MatrixXd t = space::family_basis(multipliers, setup.family).legendre;
      const Eigen::MatrixXd gram = ladder.at(result.reference_level);
      const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> pencil(t.transpose() * s_g * t,
                                                                             t.transpose() * gram * t);
      const double expected = std::sqrt(pencil.eigenvalues().minCoeff());
      const std::string where = space::to_string(setup.family);
      EXPECT_NEAR(result.alpha, expected, 1e-10 * expected) << where;
      EXPECT_EQ(result.n_multiplier_dofs, t.cols()) << where;
      EXPECT_NEAR(infsup::analyse_infsup(setup, infsup::EigenBackend::slepc).alpha, expected, 1e-8 * expected) << where;
    }
}
