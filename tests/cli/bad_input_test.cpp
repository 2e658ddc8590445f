// Bad input through the command line: one test per class. Each must exit with code 2,
// name the file (or option), the key and the offending value, say what is allowed, and leave no
// output behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/cli_runner.hpp"

namespace {

using hpcontact::testing::run;
using hpcontact::testing::scratch;

// A valid Signorini scene; each test breaks one thing in it.
const std::string kScene = R"toml([domain]
n_x = 4
n_y = 4
[boundary]
contact = "abs(y + 1) < 1e-9"
dirichlet = "abs(y - 1) < 1e-9"
[contact_mesh]
ratio = "1/2"
[discretization]
p = 2
pC = 1
[data]
f = "-1"
g = "-x^2"
s = "(1 - x)^2"
[run]
effects = ["signorini"]
)toml";

std::string replaced(const std::string& from, const std::string& to) {
  std::string text = kScene;
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("test scene has no '" + from + "'");
  return text.replace(at, from.size(), to);
}

// Writes `text` as a scene, runs `solve` on it with `extra` options, and checks the contract.
void expect_bad_input(const std::string& name, const std::string& text, const std::vector<std::string>& mentions,
                      const std::string& extra = "") {
  const auto dir = scratch("bad_" + name);
  const auto scene = dir / "scene.toml";
  std::ofstream(scene) << text;
  const auto out = dir / "out";
  const auto result = run("solve " + scene.string() + " --out " + out.string() + " " + extra);
  EXPECT_EQ(result.exit_code, 2) << name << ": " << result.output;
  for (const auto& word : mentions)
    EXPECT_NE(result.output.find(word), std::string::npos) << name << ": missing '" << word << "' in\n"
                                                           << result.output;
  EXPECT_FALSE(std::filesystem::exists(out)) << name << ": output left behind";
}

}  // namespace

TEST(BadInput, TheValidSceneRuns) {
  const auto dir = scratch("bad_valid");
  std::ofstream(dir / "scene.toml") << kScene;
  const auto result = run("solve " + (dir / "scene.toml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(result.exit_code, 0) << result.output;
}

TEST(BadInput, MalformedToml) {
  expect_bad_input("malformed", replaced("[data]", "[data"), {"scene.toml", "malformed TOML"});
}

TEST(BadInput, UnknownKeySuggestsTheNearest) {
  expect_bad_input("unknown", replaced("effects = ", "efects = "), {"scene.toml", "efects", "did you mean 'effects'"});
}

TEST(BadInput, MissingRequiredKey) {
  expect_bad_input("missing", replaced("p = 2\n", ""), {"scene.toml", "discretization.p"});
}

TEST(BadInput, DegreesOutOfRange) {
  expect_bad_input("p_zero", replaced("p = 2", "p = 0"), {"scene.toml", "discretization.p", "0"});
  expect_bad_input("pc_negative", replaced("pC = 1", "pC = -1"), {"scene.toml", "discretization.pC", "-1"});
}

TEST(BadInput, CellCountOutOfRange) {
  expect_bad_input("n_zero", replaced("n_x = 4", "n_x = 0"), {"scene.toml", "domain.n_x", "0"});
}

TEST(BadInput, RatioOutOfRange) {
  expect_bad_input("ratio_zero", replaced("ratio = \"1/2\"", "ratio = \"0\""),
                   {"scene.toml", "contact_mesh.ratio", "0"});
  expect_bad_input("ratio_negative", replaced("ratio = \"1/2\"", "ratio = \"-1/2\""),
                   {"scene.toml", "contact_mesh.ratio", "-1/2"});
  // (It once ran for seconds and 1.8 GB before an allocation failed.)
  expect_bad_input("ratio_huge", replaced("ratio = \"1/2\"", "ratio = 1000000"),
                   {"scene.toml", "contact_mesh.ratio", "1000000", "at most 64"});
}

// A contact problem on a body held nowhere, and a friction bound that vanishes on all of Γ_C,
// name the scene file and the key.
TEST(BadInput, BodyHeldNowhereOrFrictionBoundZero) {
  expect_bad_input("no_dirichlet", replaced("dirichlet = \"abs(y - 1) < 1e-9\"", "dirichlet = \"y > 5\""),
                   {"scene.toml", "boundary.dirichlet", "y > 5", "no boundary edge is in Γ_D"});
  expect_bad_input("s_zero", replaced("s = \"(1 - x)^2\"", "s = \"0\"\n[infsup]\nproblem = \"friction\""),
                   {"scene.toml", "data.s", "vanishes on all of Γ_C"}, "--effects infsup");
}

TEST(BadInput, FewerConstraintPointsThanPcPlusOne) {
  expect_bad_input("points_scene", replaced("pC = 1", "pC = 3") + "[solve]\nconstraint_points = 3\n",
                   {"scene.toml", "solve.constraint_points", "3", "p_C + 1 = 4"});
  expect_bad_input("points_option", replaced("pC = 1", "pC = 3"), {"--constraint-points", "2", "p_C + 1 = 4"},
                   "--constraint-points 2");
}

// A multiplier family: its name checked, p_C ≥ 1, and no constraint points (its coefficients are
// constrained).
TEST(BadInput, MultiplierFamilyAndWhatItRefuses) {
  expect_bad_input("family_name", replaced("[contact_mesh]\n", "[contact_mesh]\nfamily = \"mortar\"\n"),
                   {"scene.toml", "contact_mesh.family", "mortar", "standard-modified"});
  expect_bad_input("family_pc", replaced("[contact_mesh]\n", "[contact_mesh]\nfamily = \"dual\"\n"),
                   {"discretization.pC", "at least 1", "dual"}, "--pc 0");
  expect_bad_input(
      "family_points",
      replaced("[contact_mesh]\n", "[contact_mesh]\nfamily = \"standard\"\n") + "[solve]\nconstraint_points = 3\n",
      {"scene.toml", "solve.constraint_points", "standard", "absent"});
  expect_bad_input("family_end",
                   replaced("[contact_mesh]\nratio = \"1/2\"\n", "[contact_mesh]\nm = 1\nfamily = \"dual-modified\"\n"),
                   {"scene.toml", "contact_mesh.family", "dual-modified", "one segment"});
}

TEST(BadInput, ExpressionThatDoesNotParse) {
  expect_bad_input("parse", replaced("g = \"-x^2\"", "g = \"-x^^2\""), {"scene.toml", "data.g", "-x^^2"});
}

TEST(BadInput, ExpressionThatIsNotFinite) {
  expect_bad_input("nan", replaced("f = \"-1\"", "f = \"sqrt(x - 5)\""),
                   {"scene.toml", "data.f", "sqrt(x - 5)", "finite"});
  expect_bad_input("inf", replaced("g = \"-x^2\"", "g = \"1/(x - x)\""), {"scene.toml", "data.g", "finite"});
}

TEST(BadInput, NegativeFrictionBound) {
  std::string text = replaced("s = \"(1 - x)^2\"", "s = \"x\"");
  const std::string signorini = "effects = [\"signorini\"]";
  text.replace(text.find(signorini), signorini.size(), "effects = [\"friction_s\"]");
  expect_bad_input("s_negative", text, {"scene.toml", "data.s", ">= 0"});
}

TEST(BadInput, EffectsAndOutputsThatDoNotApply) {
  const std::string effects = "effects = [\"signorini\"]";
  expect_bad_input("effect_unknown", replaced(effects, "effects = [\"signorini\", \"plasticity\"]"),
                   {"scene.toml", "run.effects", "plasticity", "friction_s"});
  expect_bad_input("effect_twice", replaced(effects, "effects = [\"signorini\", \"signorini\"]"),
                   {"scene.toml", "run.effects", "at most once"});
  expect_bad_input("convergence_alone", replaced(effects, "effects = [\"infsup\", \"convergence\"]"),
                   {"scene.toml", "run.effects", "convergence", "contact problems"});
  expect_bad_input("mode_without_infsup", replaced(effects, effects + "\noutputs = [\"mode\"]"),
                   {"scene.toml", "run.outputs", "mode", "infsup"});
  expect_bad_input("vtu_without_contact", replaced(effects, "effects = [\"infsup\"]\noutputs = [\"vtu\"]"),
                   {"scene.toml", "run.outputs", "vtu"});
  expect_bad_input("signorini_without_g", replaced("g = \"-x^2\"\n", ""), {"scene.toml", "data.g", "obstacle"});
  expect_bad_input("effects_option", kScene, {"--effects", "elasticity"}, "--effects elasticity");
  expect_bad_input("effects_missing", replaced("[run]\neffects = [\"signorini\"]\n", ""),
                   {"scene.toml", "run.effects", "--effects"});
}

TEST(BadInput, ContactBoundaryEmptyOrOverlappingDirichlet) {
  expect_bad_input("gc_empty", replaced("abs(y + 1) < 1e-9", "y < -5"), {"scene.toml", "Γ_C is empty"});
  expect_bad_input("gc_overlap", replaced("abs(y - 1) < 1e-9", "y < 0"),
                   {"scene.toml", "overlap", "boundary.dirichlet"});
}

TEST(BadInput, DirichletDataWithoutDirichletBoundaryOrNotAnExpression) {
  expect_bad_input("u_d_without_gamma_d",
                   replaced("dirichlet = \"abs(y - 1) < 1e-9\"", "dirichlet = \"y > 5\"\nu_D = \"x\""),
                   {"scene.toml", "boundary.u_D", "no Γ_D"});
  expect_bad_input("u_d_parse",
                   replaced("dirichlet = \"abs(y - 1) < 1e-9\"", "dirichlet = \"abs(y - 1) < 1e-9\"\nu_D = \"x +\""),
                   {"scene.toml", "boundary.u_D", "x +"});
  expect_bad_input("u_d_x_in_scalar_scene",
                   replaced("dirichlet = \"abs(y - 1) < 1e-9\"", "dirichlet = \"abs(y - 1) < 1e-9\"\nu_D_x = \"1\""),
                   {"scene.toml", "boundary.u_D_x", "elastic"});
}

TEST(BadInput, BrokenOrNonQuadrilateralMeshFile) {
  for (const std::string file : {"truncated.msh", "triangles.msh"}) {
    const std::string text =
        replaced("n_x = 4\nn_y = 4", "mesh = \"" + std::string(HPCONTACT_SOURCE_DIR) + "/tests/data/" + file + "\"");
    expect_bad_input("mesh_" + file, text, {file});
  }
}

TEST(BadInput, OutputFolderThatCannotBeWritten) {
  const auto dir = scratch("bad_output");
  std::ofstream(dir / "scene.toml") << kScene;
  std::ofstream(dir / "a_file") << "not a folder\n";
  const auto result = run("solve " + (dir / "scene.toml").string() + " --out " + (dir / "a_file" / "out").string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("output folder (--out) '"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("a_file"), std::string::npos) << result.output;
}

// Ranges and values in the shortest text that reads back as the number, not 17 digits; a value
// that is not a number reads "nan", not "inf".
TEST(BadInput, NumbersInMessagesAreShortAndTrue) {
  const auto dir = scratch("bad_numbers");
  const std::string graded = replaced("n_x = 4\nn_y = 4", "n_x = 4\nn_y = 4\ngrading = 0.995");
  std::ofstream(dir / "scene.toml") << graded;
  const auto range = run("solve " + (dir / "scene.toml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(range.exit_code, 2) << range.output;
  EXPECT_NE(range.output.find("'domain.grading' = 0.995: must be in [0.01, 0.99]"), std::string::npos) << range.output;
  std::ofstream(dir / "scene.toml") << replaced("n_x = 4\nn_y = 4", "n_x = 4\nn_y = 4\nx_max = nan");
  const auto not_a_number = run("solve " + (dir / "scene.toml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(not_a_number.exit_code, 2) << not_a_number.output;
  EXPECT_NE(not_a_number.output.find("'domain.x_max' = nan: a finite number"), std::string::npos)
      << not_a_number.output;
}
