// What a newcomer types and what it gets: numbers where expressions are expected, misspelt keys
// and options with the name meant, a mesh without named groups, an unreadable mesh file with the
// reason, and any scene key set from the command line (--set, lists of pairs too) checked like the
// file's value.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/cli_runner.hpp"

namespace {

using hpcontact::testing::run;
using hpcontact::testing::Run;
using hpcontact::testing::scratch;

// An elastic block on an obstacle; each test changes one thing in it.
const std::string kScene = R"toml([domain]
n_x = 2
n_y = 2
[boundary]
contact = "abs(y + 1) < 1e-9"
dirichlet = "abs(y - 1) < 1e-9"
[contact_mesh]
ratio = 1
[discretization]
p = 2
pC = 1
[material]
E = "1"
nu = 0.3
[data]
f_y = "-1"
g = 0.05
[run]
effects = ["frictionless"]
)toml";

std::string replaced(const std::string& from, const std::string& to) {
  std::string text = kScene;
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("test scene has no '" + from + "'");
  return text.replace(at, from.size(), to);
}

// Runs `command` (solve, infsup, advise) on `text` written as a scene, with `extra` options.
Run run_on(const std::string& name, const std::string& text, const std::string& command, const std::string& extra) {
  const auto dir = scratch("newcomer_" + name);
  std::ofstream(dir / "scene.toml") << text;
  const std::string out = command == "solve" ? " --out " + (dir / "out").string() : "";  // (infsup writes no folder)
  return run(command + " " + (dir / "scene.toml").string() + out + " " + extra);
}

void expect_mentions(const Run& result, int exit_code, const std::vector<std::string>& words) {
  EXPECT_EQ(result.exit_code, exit_code) << result.output;
  for (const auto& word : words)
    EXPECT_NE(result.output.find(word), std::string::npos) << "missing '" << word << "' in\n" << result.output;
}

TEST(NewcomerMessages, ExpressionKeysTakeNumbers) {
  // nu = 0.3 and g = 0.05 above are numbers; E = 210e9 too (the load scales with it).
  const auto result = run_on("numbers", replaced("E = \"1\"", "E = 210e9"), "solve", "");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  const auto same = run_on("strings", replaced("E = \"1\"", "E = \"210e9\""), "solve", "");
  // The energy line is the same whether E was a number or a string.
  auto energy = [](const std::string& output) { return output.substr(output.find("energy"), 40); };
  ASSERT_NE(result.output.find("energy"), std::string::npos) << result.output;
  EXPECT_EQ(energy(result.output), energy(same.output));
  expect_mentions(run_on("bool", replaced("E = \"1\"", "E = true"), "solve", ""), 2,
                  {"material.E", "an expression (a string in quotes) or a number"});
}

TEST(NewcomerMessages, AMisspeltRequiredKeyIsNamed) {
  expect_mentions(run_on("pc", replaced("pC = 1", "pc = 1"), "solve", ""), 2,
                  {"scene.toml", "unknown key 'discretization.pc'", "did you mean 'pC'"});
}

TEST(NewcomerMessages, AMisspeltOptionSuggestsTheOption) {
  expect_mentions(run_on("option", kScene, "solve", "--pC 2"), 2,
                  {"unknown option '--pC'", "did you mean '--pc'", "--set KEY=VALUE"});
  expect_mentions(run_on("option_infsup", kScene, "infsup --scene", "--ration 2"), 2,
                  {"unknown option '--ration'", "did you mean '--ratio'"});
}

TEST(NewcomerMessages, SetReachesAnySceneKeyAndIsCheckedLikeTheFile) {
  const auto result = run_on("set", kScene, "solve", "--set domain.n_x=3 --set material.E=2 --n 4");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  expect_mentions(run_on("set_range", kScene, "solve", "--set domain.n_x=0"), 2,
                  {"hpcontact solve --set domain.n_x", "domain.n_x", "0", "[1, 100000]"});
  expect_mentions(run_on("set_typo", kScene, "solve", "--set discretization.pc=2"), 2,
                  {"unknown scene key 'discretization.pc'", "did you mean 'discretization.pC'"});
  expect_mentions(run_on("set_form", kScene, "solve", "--set p"), 2, {"--set", "KEY=VALUE"});
  expect_mentions(run_on("set_infsup", kScene, "infsup --scene", "--set contact_mesh.ratio=0"), 2,
                  {"hpcontact infsup --set contact_mesh.ratio", "contact_mesh.ratio"});
}

// A list of pairs set from the command line is the file's list: the same mesh, the same solve.
TEST(NewcomerMessages, SetTakesAListOfPairs) {
  const std::string points = "grading_points = [[-1.0, -1.0], [1.0, -1.0]]\ngrading_layers = 2\n";
  const auto in_file = run_on("pairs_file", replaced("n_y = 2\n", "n_y = 2\n" + points), "solve", "");
  const auto by_set = run_on("pairs_set", replaced("n_y = 2\n", "n_y = 2\ngrading_layers = 2\n"), "solve",
                             "--set 'domain.grading_points=[[-1.0, -1.0], [1.0, -1.0]]'");
  const auto ungraded = run_on("pairs_none", kScene, "solve", "");
  ASSERT_EQ(in_file.exit_code, 0) << in_file.output;
  ASSERT_EQ(by_set.exit_code, 0) << by_set.output;
  auto energy = [](const std::string& output) { return output.substr(output.find("energy"), 40); };
  ASSERT_NE(by_set.output.find("energy"), std::string::npos) << by_set.output;
  EXPECT_EQ(energy(by_set.output), energy(in_file.output));
  EXPECT_NE(energy(by_set.output), energy(ungraded.output));  // (the points did grade the mesh)
  expect_mentions(run_on("pairs_bad", kScene, "solve", "--set 'domain.grading_points=[[0.5], [1, 2]]'"), 2,
                  {"domain.grading_points", "list of pairs"});
}

TEST(NewcomerMessages, SolveTakesTheCellCount) {
  expect_mentions(run_on("n", kScene, "solve", "--n 0"), 2, {"hpcontact solve --n", "domain.n_x", "[1, 100000]"});
}

TEST(NewcomerMessages, AMissingMeshFileSaysWhy) {
  expect_mentions(run_on("no_mesh", replaced("n_x = 2\nn_y = 2", "mesh = \"no_such.msh\""), "solve", ""), 2,
                  {"no_such.msh", "No such file or directory"});
}

TEST(NewcomerMessages, AMeshWithoutNamedGroupsSaysSo) {
  const auto dir = scratch("newcomer_groups");
  std::ofstream(dir / "square.geo") << "Point(1) = {0, 0, 0, 0.5};\nPoint(2) = {1, 0, 0, 0.5};\n"
                                       "Point(3) = {1, 1, 0, 0.5};\nPoint(4) = {0, 1, 0, 0.5};\n"
                                       "Line(1) = {1, 2};\nLine(2) = {2, 3};\nLine(3) = {3, 4};\nLine(4) = {4, 1};\n"
                                       "Curve Loop(1) = {1, 2, 3, 4};\nPlane Surface(1) = {1};\n";
  std::string text = replaced("n_x = 2\nn_y = 2", "mesh = \"square.geo\"");
  text = text.replace(text.find("contact = \"abs(y + 1) < 1e-9\""), 29, "contact_groups = [\"contact\"]");
  std::ofstream(dir / "scene.toml") << text;
  const auto result = run("solve " + (dir / "scene.toml").string() + " --out " + (dir / "out").string());
  expect_mentions(result, 2, {"boundary.contact_groups", "no named physical group"});
  EXPECT_EQ(result.output.find("the mesh has: \n"), std::string::npos) << result.output;
}

}  // namespace

namespace {

TEST(NewcomerMessages, TheOutputFolderIsCheckedBeforeSolvingWhateverItsSpelling) {
  // A folder that cannot be made: refused before the solve starts ("# solving" is never printed).
  const auto scene = scratch("newcomer_out_proc") / "scene.toml";
  std::ofstream(scene) << kScene;
  const auto refused = run("solve " + scene.string() + " --out /proc/hpcontact_no_such_folder");
  expect_mentions(refused, 2, {"/proc/hpcontact_no_such_folder", "cannot be written"});
  EXPECT_EQ(refused.output.find("# solving"), std::string::npos) << refused.output;
  const auto empty = scratch("newcomer_empty_out");
  std::ofstream(empty / "scene.toml") << kScene;
  expect_mentions(run("solve " + (empty / "scene.toml").string() + " --out \"\""), 2, {"output folder"});
  // "DIR/" is DIR: the run lands there, staged beside it, and a second run replaces it.
  const auto dir = scratch("newcomer_slash");
  std::ofstream(dir / "scene.toml") << kScene;
  for (int pass = 0; pass < 2; ++pass) {
    const auto result = run("solve " + (dir / "scene.toml").string() + " --out " + (dir / "out").string() + "/");
    EXPECT_EQ(result.exit_code, 0) << result.output;
  }
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "summary.json"));
  for (const auto& entry : std::filesystem::directory_iterator(dir / "out"))
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
}

}  // namespace

namespace {

// Data that overflow double precision give a numerical failure (exit 3) naming the problem, not
// an energy of NaN with exit 0 and nothing written.
TEST(NewcomerMessages, OverflowingDataAreANumericalFailure) {
  const auto dir = scratch("newcomer_overflow");
  std::ofstream(dir / "scene.toml") << kScene;
  const auto result =
      run("solve " + (dir / "scene.toml").string() + " --set data.f_y=-1e300 --out " + (dir / "out").string());
  expect_mentions(result, 3, {"frictionless solve gave non-finite numbers", "overflow"});
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

// A staging folder left by a killed run (its process gone) is removed by the next run into the
// same folder; one of a live process is not.
TEST(NewcomerMessages, StagingFoldersOfDeadRunsAreRemoved) {
  const auto dir = scratch("newcomer_stale");
  std::ofstream(dir / "scene.toml") << kScene;
  const auto stale = dir / "out.tmp-999999999", live = dir / ("out.tmp-" + std::to_string(getppid()));
  for (const auto& folder : {stale, live}) {
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "half_written.csv") << "x,u\n0,";
  }
  const auto result = run("solve " + (dir / "scene.toml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_FALSE(std::filesystem::exists(stale));
  EXPECT_TRUE(std::filesystem::exists(live / "half_written.csv"));
}

}  // namespace
