// Linear elasticity on [S^p(T_h)]²: the element matrices (two paths, rigid motions in
// the kernel), convergence against a manufactured displacement (rates p in the energy norm,
// exponential in p, robust for ν → ½ at p ≥ 4), and the contact problems (KKT at the constraint
// points; Tresca and Coulomb tend to frictionless as the friction vanishes).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "assembly/condensed_factor.hpp"
#include "assembly/elastic_load.hpp"
#include "assembly/elastic_system.hpp"
#include "contact/elastic_contact.hpp"
#include "driver/elastic_scene.hpp"
#include "infsup/infsup_analysis.hpp"
#include "mesh/boundary_mesh.hpp"
#include "mesh/contact_boundary.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "mesh/refine.hpp"
#include "operators/elastic_operators.hpp"
#include "postprocess/elastic_errors.hpp"
#include "postprocess/hertz_comparison.hpp"
#include "scene/scene_reader.hpp"
#include "space/vector_space.hpp"
#include "support/cli_runner.hpp"
#include "support/csv_file.hpp"
#include "support/elastic_kkt.hpp"
#include "support/elastic_manufactured.hpp"
#include "support/slepc_test_environment.hpp"

using namespace hpcontact;

namespace {

assembly::Material material(double poisson) {
  return assembly::lame_parameters(1.0, poisson, assembly::PlaneModel::strain);
}

// The manufactured problem on the paper's square (traction data on Γ_N and Γ_C), its energy error.
// Perturbed: the 2 × 2 mesh perturbed, then refined uniformly (so the levels are nested).
double energy_error(int n, int p, double poisson, double perturbation = 0.0) {
  auto m = mesh::make_paper_square_mesh(perturbation > 0 ? 2 : n);
  if (perturbation > 0) {
    mesh::perturb_interior_vertices(m, perturbation, 7);
    for (int size = 2; size < n; size *= 2) m = mesh::refine_uniformly(m);
  }
  const space::H1Space scalar_space(m, p);
  const space::VectorSpace space(scalar_space);
  const std::vector<assembly::Material> materials(m.n_cells(), material(poisson));
  const assembly::CondensedFactor factor(std::make_unique<assembly::ElasticCellSystem>(space, materials));
  const auto load = assembly::assemble_elastic_load(
      space, [&](const mesh::Point& x) { return hpcontact::testing::elastic_body_force(x, materials[0]); },
      {mesh::BoundaryPart::neumann, mesh::BoundaryPart::contact},
      [&](const mesh::Point& x, const mesh::Point& normal) {
        return hpcontact::testing::elastic_traction(x, normal, materials[0]);
      });
  const Eigen::VectorXd u = factor.solve(load);
  return postprocess::compute_elastic_errors(space, materials, u,
                                             {hpcontact::testing::elastic_u, hpcontact::testing::elastic_gradient})
      .energy;
}

}  // namespace

TEST(Elasticity, ManufacturedDataAreConsistent) {
  // Central differences of the gradient and of the stress against the closed forms.
  const assembly::Material m = material(0.3);
  const double h = 1e-5;
  for (const mesh::Point& x : {mesh::Point(0.3, -0.4), mesh::Point(-0.7, 0.2)}) {
    for (int j = 0; j < 2; ++j) {
      const mesh::Point e = h * mesh::Point::Unit(j);
      const Eigen::Vector2d du =
          (hpcontact::testing::elastic_u(x + e) - hpcontact::testing::elastic_u(x - e)) / (2 * h);
      EXPECT_NEAR((du - hpcontact::testing::elastic_gradient(x).col(j)).norm(), 0.0, 1e-8);
    }
    Eigen::Vector2d div_stress = Eigen::Vector2d::Zero();
    for (int j = 0; j < 2; ++j) {
      const mesh::Point e = h * mesh::Point::Unit(j);
      div_stress += (hpcontact::testing::elastic_traction(x + e, mesh::Point::Unit(j), m) -
                     hpcontact::testing::elastic_traction(x - e, mesh::Point::Unit(j), m)) /
                    (2 * h);
    }
    EXPECT_NEAR((div_stress + hpcontact::testing::elastic_body_force(x, m)).norm(), 0.0, 1e-7);
  }
}

TEST(Elasticity, KroneckerAndQuadratureElementMatricesAgreeAndRigidMotionsHaveNoEnergy) {
  // A sheared parallelogram mesh: the Kronecker path applies; quadrature is the independent path.
  auto m = mesh::make_rectangle_mesh({0.0, 2.0, 0.0, 1.0}, 2, 1);
  std::vector<mesh::Point> moved = m.vertices();
  for (auto& v : moved) v.x() += 0.4 * v.y();
  m.move_vertices(moved, "sheared");
  for (int p : {1, 3, 6}) {
    const space::H1Space space(m, p);
    assembly::ElementMatrices kronecker(space, true), quadrature(space, false);
    const auto a = kronecker.directional(0), b = quadrature.directional(0);
    const double scale = a.xx.norm();
    EXPECT_LT((a.xx - b.xx).norm(), 1e-12 * scale) << "p = " << p;
    EXPECT_LT((a.xy - b.xy).norm(), 1e-12 * scale) << "p = " << p;
    EXPECT_LT((a.yx - b.yx).norm(), 1e-12 * scale) << "p = " << p;
    EXPECT_LT((a.yy - b.yy).norm(), 1e-12 * scale) << "p = " << p;
    // Vertex shapes reproduce linear fields: the rigid motions (1,0), (0,1), (−y, x) interpolate
    // exactly with vertex coefficients alone, and must have zero energy.
    const space::VectorSpace vector_space(space);
    const assembly::ElasticCellSystem system(vector_space, {2, material(0.3)});
    const Eigen::MatrixXd k = system.element_matrix(0);
    const auto& shapes = space.cell_shapes(0);
    for (int motion = 0; motion < 3; ++motion) {
      Eigen::VectorXd coefficients = Eigen::VectorXd::Zero(k.rows());
      for (std::size_t s = 0; s < shapes.size(); ++s) {
        if (shapes[s].role != space::ShapeRole::vertex) continue;  // other modes vanish at vertices
        const mesh::Point v = m.vertex(m.cell(0)[shapes[s].entity]);
        const Eigen::Vector2d value = motion == 0   ? Eigen::Vector2d(1, 0)
                                      : motion == 1 ? Eigen::Vector2d(0, 1)
                                                    : Eigen::Vector2d(-v.y(), v.x());
        coefficients.segment<2>(2 * s) = shapes[s].sign * value;
      }
      EXPECT_LT((k * coefficients).norm(), 1e-12 * k.norm()) << "p = " << p << ", motion " << motion;
    }
    // And a stretch has energy.
    Eigen::VectorXd stretch = Eigen::VectorXd::Zero(k.rows());
    stretch(0) = 1.0;
    EXPECT_GT(stretch.dot(k * stretch), 0.0);
  }
}

TEST(Elasticity, EnergyErrorRateIsPUnderUniformRefinement) {
  const int coarse[] = {0, 8, 4, 4, 2, 2, 2};
  for (const double perturbation : {0.0, 0.2}) {
    for (int p = 1; p <= 6; ++p) {
      const int n = 2 * coarse[p];
      const double coarse_error = energy_error(n, p, 0.3, perturbation);
      const double fine_error = energy_error(2 * n, p, 0.3, perturbation);
      const double rate = std::log2(coarse_error / fine_error);
      EXPECT_NEAR(rate, p, 0.25) << "p = " << p << ", perturbation " << perturbation << ", errors " << coarse_error
                                 << " → " << fine_error;
    }
  }
}

TEST(Elasticity, EnergyErrorDecaysExponentiallyInP) {
  // log(error) falls at least linearly in p: each degree gains a factor > 3 on a 2 × 2 mesh.
  for (const double perturbation : {0.0, 0.2}) {
    double previous = energy_error(2, 2, 0.3, perturbation);
    for (int p = 3; p <= 10; ++p) {
      const double error = energy_error(2, p, 0.3, perturbation);
      EXPECT_LT(error, previous / 3.0) << "p = " << p << ", perturbation " << perturbation;
      previous = error;
    }
    EXPECT_LT(previous, 1e-8) << "perturbation " << perturbation;
  }
}

TEST(Elasticity, RatesSurviveNearIncompressibilityAtHighDegree) {
  // Locking shows as a pre-asymptotic range whose length grows with λ/μ; at p ≥ 4 the rate p holds
  // for ν = 0.49 and 0.499, and the error is within a small factor of the compressible one.
  for (const double poisson : {0.49, 0.499}) {
    for (int p : {4, 5}) {
      const double coarse_error = energy_error(2, p, poisson), fine_error = energy_error(4, p, poisson);
      EXPECT_NEAR(std::log2(coarse_error / fine_error), p, 0.5) << "ν = " << poisson << ", p = " << p;
      EXPECT_LT(fine_error, 5.0 * energy_error(4, p, 0.3)) << "ν = " << poisson << ", p = " << p;
    }
  }
}

namespace {

// The paper's square hanging from Γ_D, pulled down by f = (0, −1) onto an obstacle below Γ_C
// (the bottom edge, n = (0, −1)) at the gap g = 0.05 + 0.3 x²: contact in the middle, a gap
// towards the corners.
struct ElasticContactFixture {
  mesh::Mesh mesh = mesh::make_paper_square_mesh(8);
  std::unique_ptr<operators::ElasticOperators> operators;
  std::unique_ptr<mesh::BoundaryMesh> boundary_mesh;

  explicit ElasticContactFixture(int p = 3, int m = 8) {
    operators = std::make_unique<operators::ElasticOperators>(
        mesh, std::vector<int>(mesh.n_cells(), p), std::vector<assembly::Material>(mesh.n_cells(), material(0.3)));
    std::vector<double> nodes;
    for (int k = 0; k <= m; ++k) nodes.push_back(2.0 * k / m);
    boundary_mesh = std::make_unique<mesh::BoundaryMesh>(nodes, "T_{C,H}");
  }

  contact::ElasticContactSolution solve(contact::ElasticContactProblem problem, int pc = 1, double friction = 0.0) {
    contact::ElasticContactSetup setup;
    setup.operators = operators.get();
    setup.boundary_mesh = boundary_mesh.get();
    setup.segment_degrees.assign(boundary_mesh->n_segments(), pc);
    setup.problem = problem;
    setup.body_force = [](const mesh::Point&) { return Eigen::Vector2d(0.0, -1.0); };
    setup.gap = [](const mesh::Point& x) { return 0.1 + 2.0 * x.x() * x.x(); };
    setup.threshold = [friction](const mesh::Point&) { return friction; };
    setup.friction_coefficient = friction;
    return contact::solve_elastic_contact(setup);
  }
};

}  // namespace

TEST(ElasticContact, FrictionlessSatisfiesKktWithAPartialContactSet) {
  ElasticContactFixture fixture;
  for (int pc : {0, 1}) {
    const auto solution = fixture.solve(contact::ElasticContactProblem::frictionless, pc);
    hpcontact::testing::expect_kkt(solution, 1e-10);
    const Eigen::Index n = solution.lambda.size();
    int in_contact = 0;
    for (Eigen::Index j = 0; j < n; ++j)
      in_contact += solution.lambda(j) < -1e-10 * solution.lambda.lpNorm<Eigen::Infinity>();
    EXPECT_GT(in_contact, 0) << "p_C = " << pc;
    EXPECT_LT(in_contact, n) << "p_C = " << pc;
    EXPECT_GE(solution.pressure.maxCoeff(), 0.0);
    EXPECT_EQ(solution.shear.norm(), 0.0);
  }
}

TEST(ElasticContact, TrescaAndCoulombSatisfyKktAndTendToFrictionless) {
  ElasticContactFixture fixture;
  const auto frictionless = fixture.solve(contact::ElasticContactProblem::frictionless);
  const double scale = frictionless.u.norm();
  double previous_tresca = 0.0, previous_coulomb = 0.0;
  for (const double friction : {0.3, 3e-2, 3e-3}) {
    const auto tresca = fixture.solve(contact::ElasticContactProblem::tresca, 1, 0.1 * friction);
    const auto coulomb = fixture.solve(contact::ElasticContactProblem::coulomb, 1, friction);
    hpcontact::testing::expect_kkt(tresca, 1e-10);
    hpcontact::testing::expect_kkt(coulomb, 1e-9);
    EXPECT_GT(coulomb.fixed_point_changes.size(), 1u) << "F = " << friction;
    EXPECT_LE(coulomb.fixed_point_changes.back(), 1e-10);
    const double tresca_distance = (tresca.u - frictionless.u).norm() / scale;
    const double coulomb_distance = (coulomb.u - frictionless.u).norm() / scale;
    EXPECT_GT(coulomb.shear.norm(), 0.0) << "friction acts";
    // Each tenfold smaller friction brings u at least fourfold closer to frictionless (the distance
    // is O(friction) once the stick zone has vanished).
    if (previous_tresca > 0) {
      EXPECT_LT(tresca_distance, previous_tresca / 4.0) << "s = " << 0.1 * friction;
      EXPECT_LT(coulomb_distance, previous_coulomb / 4.0) << "F = " << friction;
    }
    previous_tresca = tresca_distance;
    previous_coulomb = coulomb_distance;
  }
}

TEST(ElasticContact, CoulombTractionStaysInsideTheFrictionCone) {
  ElasticContactFixture fixture;
  const double coefficient = 0.5;
  const auto solution = fixture.solve(contact::ElasticContactProblem::coulomb, 1, coefficient);
  // Nodal constraints: the normal part of λ is σ_nn, the tangential part −σ_nt at the same points.
  const Eigen::Index n = solution.n_normal;
  const double scale = solution.lambda.lpNorm<Eigen::Infinity>();
  bool some_slip = false;
  for (Eigen::Index j = 0; j < n; ++j) {
    const double pressure = -solution.lambda(j), shear = std::abs(solution.lambda(n + j));
    EXPECT_LE(shear, coefficient * std::max(pressure, 0.0) + 1e-10 * scale) << "point " << j;
    some_slip = some_slip || (pressure > 1e-8 * scale && shear > coefficient * pressure - 1e-10 * scale);
  }
  EXPECT_TRUE(some_slip) << "somewhere the body slides";
}

namespace {

const std::string kHertzScene = std::string(HPCONTACT_SOURCE_DIR) + "/studies/elasticity/hertz.toml";

postprocess::HertzComparison hertz_run(const std::vector<scene::SceneOverride>& overrides = {}) {
  const auto scene = scene::read_scene(kHertzScene, overrides);
  const auto d = driver::discretize_scene(scene);
  const auto owned = driver::scene_elastic_operators(scene, d->mesh.get(), d->cell_degrees);
  const operators::ElasticOperators& operators = *owned;
  const auto setup = driver::elastic_setup_of(scene, *d, contact::ElasticContactProblem::frictionless, operators);
  const auto solution = contact::solve_elastic_contact(setup);
  return postprocess::compare_with_hertz(setup, solution, 1.0, 1.0 / (1.0 - 0.3 * 0.3));
}

// The block (−L, L) × (−L, 0) with the cells of hertz.toml near the contact and the indentation
// that keeps a ≈ 0.3, at p = 5, p_C = 4 (so that the discretization error is well below the block's).
std::vector<scene::SceneOverride> block(int size, const std::string& indentation) {
  const std::string origin = "test";
  return {{"discretization.p", 5LL, origin},
          {"discretization.pC", 4LL, origin},
          {"domain.x_min", static_cast<long long>(-size), origin},
          {"domain.x_max", static_cast<long long>(size), origin},
          {"domain.y_min", static_cast<long long>(-size), origin},
          {"domain.n_x", static_cast<long long>(8 * size), origin},
          {"domain.n_y", static_cast<long long>(4 * size), origin},
          {"boundary.dirichlet", "abs(y + " + std::to_string(size) + ") < 1e-9", origin},
          {"data.g", "x^2 / 2 - " + indentation, origin}};
}

}  // namespace

TEST(Hertz, ContactHalfWidthAndPressureProfileMatchHertzToOnePercent) {
  const auto hertz = hertz_run();
  EXPECT_NEAR(hertz.hertz_half_width, 0.3, 0.01) << "the scene is posed for a ≈ 0.3";
  EXPECT_LT(std::abs(hertz.half_width - hertz.hertz_half_width), 0.01 * hertz.hertz_half_width)
      << "a = " << hertz.half_width << ", Hertz " << hertz.hertz_half_width;
  EXPECT_LT(hertz.profile_error, 0.01);
}

TEST(Hertz, TheRemainingDeviationIsTheFiniteBlocks) {
  // Doubling the block (at the same resolution near the contact) must shrink the profile error:
  // the discretization is not what limits it.
  const auto small = hertz_run(block(4, "0.1484")), large = hertz_run(block(8, "0.1796"));
  EXPECT_LT(large.profile_error, 0.5 * small.profile_error)
      << "profile errors " << small.profile_error << " → " << large.profile_error;
  EXPECT_LT(std::abs(large.half_width - large.hertz_half_width),
            0.5 * std::abs(small.half_width - small.hertz_half_width));
}

TEST(Hertz, SolveWritesTheBoundaryColumnsWithPressureAndGapComplementary) {
  const auto dir = hpcontact::testing::scratch("hertz_solve");
  const auto result = hpcontact::testing::run("solve " + kHertzScene + " --out " + dir.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto csv = hpcontact::testing::read_csv(dir / "boundary_frictionless.csv");
  EXPECT_EQ(csv.header_line(), "x,y,s_arc,u_n,u_t,gap,pressure,traction_t,sigma_xx,sigma_yy,sigma_zz,sigma_xy,zone");
  double max_pressure = 0.0, min_pressure = 0.0, min_gap = 0.0, max_product = 0.0;
  const auto rows = csv.numbers();
  for (const auto& v : rows) {
    ASSERT_EQ(v.size(), 13u);
    max_pressure = std::max(max_pressure, v[6]);
    min_pressure = std::min(min_pressure, v[6]);
    min_gap = std::min(min_gap, v[5]);
    max_product = std::max(max_product, std::abs(v[5] * v[6]));
    EXPECT_EQ(v[7], 0.0) << "frictionless: no tangential traction";
  }
  EXPECT_GT(rows.size(), 100u);
  EXPECT_GT(max_pressure, 0.1);
  EXPECT_GE(min_pressure, -1e-3 * max_pressure);
  // The constraints hold at the constraint points; between them the gap may dip by the
  // discretization error, far below the indentation d = 0.1484.
  EXPECT_GT(min_gap, -1e-3 * 0.1484);
  EXPECT_LT(max_product, 1e-4 * 0.1484 * max_pressure);
  EXPECT_TRUE(std::filesystem::exists(dir / "solution_frictionless.vtu"));
  std::ifstream summary(dir / "summary.json");
  const std::string text((std::istreambuf_iterator<char>(summary)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\"total_force\""), std::string::npos);
}

TEST(Hertz, StudyCommandWritesOneRowPerLevel) {
  const auto dir = hpcontact::testing::scratch("hertz_study");
  {
    std::ofstream study(dir / "study.toml");
    study << "[hertz]\nscene = \"" << kHertzScene << "\"\nradius = 1.0\n"
          << "[[hertz.sequence]]\nname = \"p\"\nvary = { \"discretization.p\" = \"2..3\", "
             "\"discretization.pC\" = \"1..2\" }\n";
  }
  const auto result = hpcontact::testing::run("hertz " + (dir / "study.toml").string() + " --out " + dir.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto csv = hpcontact::testing::read_csv(dir / "hertz.csv");
  EXPECT_EQ(csv.header_line(), "sequence,level,label,p,pC,ndofs,nmult,P,a_hertz,a,a_error,profile_error,seconds");
  EXPECT_EQ(csv.rows.size(), 2u);
  EXPECT_TRUE(std::filesystem::exists(dir / "hertz_profiles.csv"));
}

// studies/elasticity/compression.toml: the bottom lifted by u_y = 0.01 on a roller against a flat
// plate on top; uniaxial stress, so the pressure is E/(1 − ν²) · 0.01/4 everywhere and the energy
// ½ p · 0.0025 · |Ω|, for any discretization (the solution is affine).
TEST(ElasticScenes, PrescribedDisplacementGivesTheExactUniformPressure) {
  const auto dir = hpcontact::testing::scratch("compression");
  const auto result = hpcontact::testing::run("solve " + std::string(HPCONTACT_SOURCE_DIR) +
                                              "/studies/elasticity/compression.toml --out " + dir.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const double pressure = 0.0025 / (1 - 0.3 * 0.3);
  const auto rows = hpcontact::testing::read_csv(dir / "boundary_frictionless.csv").numbers();
  for (const auto& v : rows) {
    ASSERT_EQ(v.size(), 13u);
    EXPECT_NEAR(v[6], pressure, 1e-12) << "x = " << v[0];
    // The discrete stress beside Γ_C is the uniform state too: σ_yy = −p, no shear.
    EXPECT_NEAR(v[9], -pressure, 1e-10) << "x = " << v[0];
    EXPECT_NEAR(v[11], 0.0, 1e-10) << "x = " << v[0];
    EXPECT_NEAR(v[3], 0.0, 1e-14) << "u_n: the top stays on the plate";
  }
  EXPECT_GT(rows.size(), 100u);
  std::ifstream summary(dir / "summary.json");
  const auto json = nlohmann::json::parse(summary);
  EXPECT_NEAR(json["frictionless"]["energy"].get<double>(), 0.5 * pressure * 0.0025 * 32.0, 1e-15);
}

TEST(ElasticScenes, BadInputNamesTheKeyAndTheRule) {
  std::ifstream in(kHertzScene);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string effects = "effects = [\"frictionless\"]", material = "[material]\nE = \"1\"\nnu = \"0.3\"\n";
  struct Case {
    std::vector<std::pair<std::string, std::string>> changes;
    std::string expected;
  };
  const std::vector<Case> cases{
      {{{effects, "effects = [\"frictionless\", \"signorini\"]"}}, "one body per scene"},
      {{{effects, "effects = [\"signorini\"]"}}, "one body per scene"},
      {{{"nu = \"0.3\"", "nu = \"0.5\""}}, "material.nu"},
      {{{effects, "effects = [\"coulomb\"]"}}, "friction coefficient"},
      {{{effects, "effects = [\"infsup\", \"convergence\"]"}}, "'convergence' refines the contact problems"},
      {{{"contact = \"abs(y) < 1e-9\"\n", "contact = \"abs(y) < 1e-9\"\nfixed_y = \"abs(y) < 1e-9\"\n"}},
       "edges outside Γ_C and Γ_D"},
      // A scalar scene with an elastic key: it would do nothing.
      {{{effects, "effects = [\"signorini\"]"},
        {material, ""},
        {"model = \"plane_strain\"\n", ""},
        {"[data]\n", "[data]\nf_x = \"1\"\n"}},
       "only with an elastic effect"},
      // Dirichlet data: the scalar key, or a component that nothing fixes.
      {{{"[boundary]\n", "[boundary]\nu_D = \"1\"\n"}}, "boundary.u_D_x, boundary.u_D_y"},
      {{{"dirichlet = \"abs(y + 4) < 1e-9\"\n", "fixed_y = \"abs(y + 4) < 1e-9\"\nu_D_x = \"0.1\"\n"}},
       "no edge fixes u_x"},
  };
  for (const auto& c : cases) {
    const auto dir = hpcontact::testing::scratch("elastic_bad");
    std::string changed = text;
    for (const auto& [from, to] : c.changes) {
      const auto at = changed.find(from);
      ASSERT_NE(at, std::string::npos) << from;
      changed.replace(at, from.size(), to);
    }
    std::ofstream(dir / "scene.toml") << changed;
    const auto result =
        hpcontact::testing::run("solve " + (dir / "scene.toml").string() + " --out " + (dir / "out").string());
    EXPECT_NE(result.exit_code, 0) << c.expected;
    EXPECT_NE(result.output.find(c.expected), std::string::npos) << c.expected << ": " << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out" / "summary.json")) << c.expected;
  }
}

namespace {

// α of the elastic pairing on the §7 square (Γ_C the bottom edge, straight) or, with `corner`, on
// Γ_C around the lower right corner; p = 3, p_C = 1 (stable), n = 8, h/H = 1.
infsup::InfSupResult elastic_alpha(infsup::PairingProblem problem, operators::PrimalNorm norm, double poisson,
                                   bool corner = false, infsup::EigenBackend backend = infsup::EigenBackend::slepc) {
  auto mesh = mesh::make_rectangle_mesh({-1.0, 1.0, -1.0, 1.0}, 8, 8);
  mesh::assign_boundary_part(mesh, mesh::BoundaryPart::dirichlet,
                             [](const mesh::Point& x) { return x.y() > 1 - 1e-9; });
  mesh::assign_boundary_part(mesh, mesh::BoundaryPart::contact, [corner](const mesh::Point& x) {
    return x.y() < -1 + 1e-9 || (corner && x.x() > 1 - 1e-9 && x.y() < 0);
  });
  const mesh::ContactBoundary contact(mesh);
  const auto boundary = mesh::BoundaryMesh(contact.breakpoints(), "T_{C,H}");
  const std::vector<int> degrees(mesh.n_cells(), 3);
  const operators::ElasticOperators elastic(
      mesh, degrees,
      std::vector<assembly::Material>(mesh.n_cells(),
                                      assembly::lame_parameters(1.0, poisson, assembly::PlaneModel::strain)));
  infsup::InfSupSetup setup;
  setup.mesh = &mesh;
  setup.cell_degrees = degrees;
  setup.boundary_mesh = &boundary;
  setup.segment_degrees.assign(boundary.n_segments(), 1);
  setup.problem = problem;
  setup.elastic = &elastic;
  setup.primal_norm = norm;
  return infsup::analyse_infsup(setup, backend);
}

}  // namespace

TEST(ElasticInfSup, H1NormOnAStraightContactEdgeGivesTheScalarAlpha) {
  // On a straight Γ_C the normal trace is one displacement component and the tangential one the
  // other; in the componentwise H¹ norm both pairings are then the scalar pairing (11): an
  // independent path (directional couplings, the vector Gram factor) to the same α.
  auto mesh = mesh::make_rectangle_mesh({-1.0, 1.0, -1.0, 1.0}, 8, 8);
  mesh::assign_boundary_part(mesh, mesh::BoundaryPart::dirichlet,
                             [](const mesh::Point& x) { return x.y() > 1 - 1e-9; });
  mesh::assign_boundary_part(mesh, mesh::BoundaryPart::contact, [](const mesh::Point& x) { return x.y() < -1 + 1e-9; });
  const auto boundary = mesh::BoundaryMesh::uniform(2.0, 8);
  infsup::InfSupSetup scalar;
  scalar.mesh = &mesh;
  scalar.cell_degrees.assign(mesh.n_cells(), 3);
  scalar.boundary_mesh = &boundary;
  scalar.segment_degrees.assign(8, 1);
  const double scalar_alpha = infsup::analyse_infsup(scalar, infsup::EigenBackend::slepc).alpha;
  for (const auto problem : {infsup::PairingProblem::signorini, infsup::PairingProblem::friction}) {
    const auto elastic = elastic_alpha(problem, operators::PrimalNorm::h1, 0.3);
    EXPECT_NEAR(elastic.alpha, scalar_alpha, 1e-10 * scalar_alpha) << infsup::to_string(problem);
    EXPECT_EQ(elastic.n_multiplier_dofs, (problem == infsup::PairingProblem::friction ? 2 : 1) * 8 * 2);
  }
  EXPECT_GT(scalar_alpha, 0.5);
}

TEST(ElasticInfSup, EnergyNormAlphaFallsAsNuTendsToOneHalfAndFrictionIsBelowSignorini) {
  double previous = INFINITY;
  for (const double poisson : {0.3, 0.49, 0.499}) {
    const double signorini =
        elastic_alpha(infsup::PairingProblem::signorini, operators::PrimalNorm::energy, poisson).alpha;
    const double friction =
        elastic_alpha(infsup::PairingProblem::friction, operators::PrimalNorm::energy, poisson).alpha;
    EXPECT_LT(signorini, previous) << "ν = " << poisson;
    // Multipliers (μ_n, 0) are among the friction pairing's: its infimum is over more.
    EXPECT_LE(friction, signorini * (1 + 1e-10)) << "ν = " << poisson;
    previous = signorini;
  }
  EXPECT_GT(previous, 0.1) << "still clearly positive at ν = 0.499";
}

TEST(ElasticInfSup, AroundACornerSlepcAgreesWithTheDensePathAndThePairingsDiffer) {
  const auto slepc = elastic_alpha(infsup::PairingProblem::friction, operators::PrimalNorm::energy, 0.3, true);
  const auto dense = elastic_alpha(infsup::PairingProblem::friction, operators::PrimalNorm::energy, 0.3, true,
                                   infsup::EigenBackend::dense);
  EXPECT_NEAR(slepc.alpha, dense.alpha, 1e-8 * dense.alpha);
  const auto normal = elastic_alpha(infsup::PairingProblem::signorini, operators::PrimalNorm::h1, 0.3, true);
  const auto both = elastic_alpha(infsup::PairingProblem::friction, operators::PrimalNorm::h1, 0.3, true);
  // Where the normal turns, the tangential multiplier on one edge meets the normal one on the
  // other in the same displacement component: the pairings are no longer the scalar one twice.
  EXPECT_LT(both.alpha, normal.alpha * (1 - 1e-3));
}

TEST(ElasticInfSup, SolveAndSweepRunTheElasticPairing) {
  const auto dir = hpcontact::testing::scratch("elastic_infsup");
  const std::string square = std::string(HPCONTACT_SOURCE_DIR) + "/studies/elasticity/square.toml";
  {
    std::ifstream in(square);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    text.replace(text.find("primal_norm"), 0, "problem = \"friction\"\n");
    std::ofstream(dir / "square.toml") << text;
  }
  const auto solved =
      hpcontact::testing::run("solve " + (dir / "square.toml").string() + " --out " + (dir / "out").string());
  ASSERT_EQ(solved.exit_code, 0) << solved.output;
  EXPECT_EQ(hpcontact::testing::read_csv(dir / "out" / "mode.csv").header_line(), "x,mu,y,s,mu_t");
  std::ofstream(dir / "sweep.toml") << "[sweep]\nscene = \"square.toml\"\n"
                                    << "levels = { \"domain.n_x\" = [4, 8], \"domain.n_y\" = [4, 8] }\n"
                                    << "p = \"1..2\"\npC = \"0..1\"\nratio = [1]\nproblem = [\"signorini\", "
                                       "\"friction\"]\nfit_levels = 2\n";
  const auto swept =
      hpcontact::testing::run("sweep " + (dir / "sweep.toml").string() + " --out " + (dir / "sweep").string());
  ASSERT_EQ(swept.exit_code, 0) << swept.output;
  EXPECT_EQ(hpcontact::testing::read_csv(dir / "sweep" / "alpha.csv").rows.size(),
            2u * 2 * 3);  // problems × levels × (p, p_C < p)
}

TEST(ElasticScenes, ConvergenceEffectRefinesTheElasticProblems) {
  // The Hertz block, ungraded, p = 2: the energies of nested uniform refinements decrease towards
  // the finest, each level's error at least halving, as for the scalar problems.
  std::ifstream in(kHertzScene);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"effects = [\"frictionless\"]",
            "effects = [\"frictionless\", \"convergence\"]\n[convergence]\nrefinements = 3"},
           {"grading_layers = 8", "grading_layers = 0"},
           {"n_x = 32", "n_x = 16"},
           {"n_y = 16", "n_y = 8"},
           {"p = 4", "p = 2"},
           {"pC = 2", "pC = 1"}})
    text.replace(text.find(from), from.size(), to);
  const auto dir = hpcontact::testing::scratch("elastic_convergence");
  std::ofstream(dir / "scene.toml") << text;
  const auto result =
      hpcontact::testing::run("solve " + (dir / "scene.toml").string() + " --out " + (dir / "out").string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::vector<double> energies, errors;
  for (const auto& fields : hpcontact::testing::read_csv(dir / "out" / "convergence.csv").rows) {
    ASSERT_EQ(fields.size(), 14u) << hpcontact::testing::line_of(fields);
    energies.push_back(std::stod(fields[8]));
    errors.push_back(std::stod(fields[9]));
  }
  ASSERT_EQ(energies.size(), 4u);
  for (std::size_t k = 1; k < energies.size(); ++k) EXPECT_LT(energies[k], energies[k - 1]) << "level " << k;
  for (std::size_t k = 1; k + 1 < errors.size(); ++k) EXPECT_LT(errors[k], 0.5 * errors[k - 1]) << "level " << k;
  // Each refined level's operators are in summary.json under its own name, its factor of A with
  // them (factorized once per level).
  std::ifstream file(dir / "out" / "summary.json");
  const auto operators = nlohmann::json::parse(file)["operators"];
  for (int level = 1; level <= 3; ++level) {
    const std::string suffix = " (convergence level " + std::to_string(level) + ")";
    int factors = 0;
    for (const auto& record : operators)
      if (record["name"].get<std::string>() == "factor(A)" + suffix) ++factors;
    EXPECT_EQ(factors, 1) << "level " << level << " in " << operators.dump();
  }
}

TEST(ElasticScenes, HalfModelWithASymmetryRollerGivesHalfTheFullModel) {
  // hertz_half.toml is the right half of hertz.toml (the same cells) with u_x = 0 on x = 0.
  double energy[2], force[2];
  int k = 0;
  for (const char* name : {"hertz.toml", "hertz_half.toml"}) {
    const auto scene = scene::read_scene(std::string(HPCONTACT_SOURCE_DIR) + "/studies/elasticity/" + name);
    const auto d = driver::discretize_scene(scene);
    const auto operators = driver::scene_elastic_operators(scene, d->mesh.get(), d->cell_degrees);
    const auto setup = driver::elastic_setup_of(scene, *d, contact::ElasticContactProblem::frictionless, *operators);
    const auto solution = contact::solve_elastic_contact(setup);
    energy[k] = solution.energy;
    force[k++] =
        solution.pressure.sum() > 0 ? postprocess::compare_with_hertz(setup, solution, 1.0, 1.0).total_force : 0.0;
  }
  EXPECT_NEAR(energy[1], 0.5 * energy[0], 1e-9 * energy[0]);
  EXPECT_NEAR(force[1], 0.5 * force[0], 1e-9 * force[0]);
}
