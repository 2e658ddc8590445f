// Inf-sup constant: the paper's §7 pairings (stable / decaying), SLEPc against the
// dense path on stable, unstable and singular configurations, convergence of both H^{-1/2}
// reference realizations, the friction variant (22) with supp s ≠ Γ_C, mode sampling, and
// stability sweeps over the levels of a base scene.
#include <gtest/gtest.h>
#include <slepcsys.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

#include "core/error.hpp"
#include "infsup/infsup_analysis.hpp"
#include "mesh/contact_boundary.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "norms/h_minus_half_gram.hpp"
#include "postprocess/mode_samples.hpp"
#include "space/multiplier_space.hpp"
#include "studies/stability_sweep.hpp"
#include "support/csv_file.hpp"
#include "support/paper_scene.hpp"
#include "support/scratch.hpp"
#include "support/slepc_test_environment.hpp"

using namespace hpcontact;

namespace {

struct Configuration {
  int p, pc, n, m;
  infsup::GramNorm norm = infsup::GramNorm::interpolation;
  infsup::PairingProblem problem = infsup::PairingProblem::signorini;
  assembly::BoundaryFunction s = [](const mesh::Point& x) { return (1 - x.x()) * (1 - x.x()); };
};

infsup::InfSupResult alpha(const Configuration& c, infsup::EigenBackend backend = infsup::EigenBackend::dense) {
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
  return infsup::analyse_infsup(setup, backend);
}

}  // namespace

// Figure 2 of the paper: p ≡ 1, p_C ≡ 0 oscillates for h/H = 1 and is stable for h/H = 1/2.
// Halving h halves α when the pairing is unstable (rate 1), and leaves α nearly unchanged when
// it is stable. The same for p = 3 with p_C = 2 (h/H = 1 unstable, 1/2 stable) and p_C = 1.
TEST(InfSup, PaperPairingsDecayOrStayBounded) {
  struct Case {
    int p, pc;
    double ratio;
    bool stable;
  };
  for (const auto& c : {Case{1, 0, 1.0, false}, Case{1, 0, 0.5, true}, Case{3, 2, 1.0, false}, Case{3, 2, 0.5, true},
                        Case{3, 1, 1.0, true}, Case{2, 1, 1.0, false}}) {
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
  for (const Configuration& c :
       {Configuration{1, 0, 8, 8}, Configuration{1, 0, 8, 4}, Configuration{3, 2, 8, 8}, Configuration{4, 3, 6, 12}}) {
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
  const auto table = postprocess::sample_mode(mesh::ContactBoundary(mesh), multipliers, mode);
  EXPECT_EQ(table.n_rows(), 60u);
  EXPECT_EQ(table.columns().front(), "x");
  EXPECT_EQ(table.columns()[1], "mu");
}

// Sweeps read a base scene: on the §7 square with n × n levels, every row of alpha.csv equals α
// computed point by point on the built-in geometry (make_paper_square_mesh, uniform T_{C,H}, no
// shared factors or Gram matrices), and rerunning the sweep into the same folder computes nothing
// (the file is unchanged).
namespace {

std::filesystem::path sweep_folder(const std::string& name) { return hpcontact::testing::scratch("sweep_" + name); }

// The §7 scene on 4 × 4 cells with p = 2, p_C = 1 (a sweep's base scene), with `changes`.
std::string square_scene(const std::vector<hpcontact::testing::SceneKeyText>& changes = {}) {
  std::vector<hpcontact::testing::SceneKeyText> keys{
      {"domain.n_x", "4"}, {"domain.n_y", "4"}, {"discretization.p", "2"}, {"discretization.pC", "1"}};
  keys.insert(keys.end(), changes.begin(), changes.end());
  return hpcontact::testing::paper_scene_with(keys);
}

std::string text_of(const std::filesystem::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), {}};
}

std::string sweep_error(const std::filesystem::path& dir, const std::string& sweep_text) {
  std::ofstream(dir / "sweep.toml") << sweep_text;
  try {
    studies::read_stability_sweep((dir / "sweep.toml").string());
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no error)";
}

}  // namespace

TEST(Sweep, SceneLevelsGiveTheAlphaOfTheBuiltInGeometryAndResume) {
  const auto dir = sweep_folder("levels");
  std::ofstream(dir / "square.toml") << square_scene();
  std::ofstream(dir / "sweep.toml") << R"toml([sweep]
scene = "square.toml"
levels = { "domain.n_x" = [4, 8], "domain.n_y" = [4, 8] }
p = [1, 3]
pC = "0..2"
ratio = [1, "1/2"]
norm = ["interp", "extension"]
problem = ["signorini", "friction"]
eigensolver = "dense"
)toml";
  const auto sweep = studies::read_stability_sweep((dir / "sweep.toml").string());
  ASSERT_EQ(sweep.levels.size(), 2u);
  studies::run_stability_sweep(sweep, dir / "alpha.csv");
  const auto rows = hpcontact::testing::read_csv(dir / "alpha.csv").records();
  // Pairs with p_C < p: (1, 0), (3, 0), (3, 1), (3, 2); × 2 levels × 2 ratios × 2 norms × 2 problems.
  ASSERT_EQ(rows.size(), 4u * 2 * 2 * 2 * 2);
  for (const auto& row : rows) {
    Configuration c{std::stoi(row.at("p")), std::stoi(row.at("pC")), std::stoi(row.at("n")), std::stoi(row.at("m"))};
    c.norm = infsup::parse_gram_norm(row.at("norm"), "test");
    c.problem = infsup::parse_pairing_problem(row.at("problem"), "test");
    // The sweep's extension-norm references are those of the largest p (3) for every point of a
    // level, so α agrees within the two error estimates there; the interpolation norm is exact.
    EXPECT_EQ(std::stoi(row.at("level")), c.n == 4 ? 1 : 2);
    const auto own = alpha(c);
    EXPECT_NEAR(std::stod(row.at("alpha")), own.alpha, 1e-9 + std::stod(row.at("alpha_error")) + own.alpha_error)
        << row.at("problem") << " " << row.at("norm") << " p " << c.p << " pC " << c.pc << " n " << c.n;
  }
  const std::string first = text_of(dir / "alpha.csv");
  int calls = 0;
  studies::run_stability_sweep(sweep, dir / "alpha.csv", [&](int, int, double, const std::string&) { ++calls; });
  EXPECT_EQ(calls, 0);
  EXPECT_EQ(text_of(dir / "alpha.csv"), first);
}

// Without p, pC and ratio the sweep uses the scene's own: here a degree rule and a contact mesh
// of m segments, over levels given by uniform refinements (m follows: 2, 4, 8).
TEST(Sweep, SceneDegreeRulesAndContactMeshWhenTheSweepGivesNone) {
  const auto dir = sweep_folder("rules");
  std::ofstream(dir / "square.toml") << square_scene(
      {{"contact_mesh.ratio", std::nullopt}, {"contact_mesh.m", "2"}, {"discretization.p", "\"x < 0 ? 2 : 3\""}});
  std::ofstream(dir / "sweep.toml") << R"toml([sweep]
scene = "square.toml"
levels = { "domain.refinements" = "0..2" }
)toml";
  const auto sweep = studies::read_stability_sweep((dir / "sweep.toml").string());
  studies::run_stability_sweep(sweep, dir / "alpha.csv");
  const auto rows = hpcontact::testing::read_csv(dir / "alpha.csv").records();
  ASSERT_EQ(rows.size(), 3u);
  for (int level = 0; level < 3; ++level) {
    const auto& row = rows[level];
    EXPECT_EQ(row.at("p"), "2");  // the smallest p_T of the rule
    EXPECT_EQ(row.at("pC"), "1");
    EXPECT_EQ(std::stoi(row.at("n")), 4 << level);
    EXPECT_EQ(std::stoi(row.at("m")), 2 << level);
    EXPECT_EQ(row.at("problem"), "signorini");
    EXPECT_GT(std::stod(row.at("alpha")), 0.1);  // h/H = 1/2 with p_C < p: stable
  }
}

TEST(Sweep, BadInputNamesTheKeyAndTheLevel) {
  const auto dir = sweep_folder("bad");
  std::ofstream(dir / "square.toml") << square_scene();
  std::ofstream(dir / "no_s.toml") << square_scene({{"data.s", std::nullopt}});
  auto contains = [](const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; };
  std::string error = sweep_error(dir, "[sweep]\nscene = \"missing.toml\"\n");
  EXPECT_TRUE(contains(error, "sweep.scene")) << error;
  error = sweep_error(dir,
                      "[sweep]\nscene = \"square.toml\"\nlevels = { \"domain.n_x\" = [4, 6], \"domain.n_y\" = [4, 6] "
                      "}\nratio = \"1/4\"\n");
  EXPECT_TRUE(contains(error, "level 2")) << error;
  EXPECT_TRUE(contains(error, "contact_mesh.ratio")) << error;
  error = sweep_error(dir, "[sweep]\nscene = \"no_s.toml\"\nproblem = \"friction\"\n");
  EXPECT_TRUE(contains(error, "data.s")) << error;
  error = sweep_error(dir, "[sweep]\nscene = \"square.toml\"\np = 0\n");
  EXPECT_TRUE(contains(error, "sweep.p")) << error;
  error = sweep_error(dir, "[sweep]\nscene = \"square.toml\"\nlevel = { \"domain.n_x\" = [4] }\n");
  EXPECT_TRUE(contains(error, "levels")) << error;  // unknown key, nearest suggested
}
