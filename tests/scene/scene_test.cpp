// Scenes: the §7 geometry read from a scene equals the built-in one, a Gmsh scene with
// physical groups, and one error per class of bad scene input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/error.hpp"
#include "io/toml_reader.hpp"
#include "mesh/contact_boundary.hpp"
#include "scene/scene_keys.hpp"
#include "scene/scene_mesh.hpp"
#include "scene/scene_reader.hpp"
#include "scene/scene_variants.hpp"
#include "support/scratch.hpp"

using namespace hpcontact;

namespace {

// In the process's scratch folder: ctest runs the tests of this file in parallel processes, which
// must not write each other's scenes.
std::string write_scene(const std::string& name, const std::string& text) {
  const auto path = hpcontact::testing::scratch_root() / ("scene_" + name + ".toml");
  std::ofstream(path) << text;
  return path.string();
}

std::string error_of(const std::string& text) {
  try {
    const auto scene = scene::read_scene(write_scene("bad", text));
    const auto mesh = scene::build_scene_mesh(scene);
    const mesh::ContactBoundary contact(mesh);
    scene::build_scene_boundary_mesh(scene, contact);
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no error)";
}

const std::string kGood = R"toml(
[domain]
n_x = 4
n_y = 4
[boundary]
contact = "y < -0.999"
dirichlet = "y > 0.999"
[contact_mesh]
m = 2
[discretization]
p = 2
pC = 1
)toml";

std::string with(const std::string& from, const std::string& to) {
  std::string text = kGood;
  text.replace(text.find(from), from.size(), to);
  return text;
}

/// kGood with these [domain] keys added and T_{C,H} following T_h with h/H = 1/2.
scene::Scene graded_scene(const std::string& name, const std::string& domain_keys) {
  std::string text = with("n_y = 4", "n_y = 4\n" + domain_keys);
  text.replace(text.find("m = 2"), 5, "ratio = \"1/2\"");
  return scene::read_scene(write_scene(name, text));
}

}  // namespace

TEST(Scene, PaperSceneMatchesBuiltInGeometry) {
  const auto scene = scene::read_scene(std::string(HPCONTACT_TEST_DATA) + "/scene_paper.toml");
  const auto mesh = scene::build_scene_mesh(scene);
  const auto paper = mesh::make_paper_square_mesh(8);
  ASSERT_EQ(mesh.n_edges(), paper.n_edges());
  for (int e = 0; e < mesh.n_edges(); ++e) EXPECT_EQ(mesh.edge_part(e), paper.edge_part(e)) << e;
  const mesh::ContactBoundary contact(mesh);
  const auto boundary = scene::build_scene_boundary_mesh(scene, contact);
  EXPECT_EQ(boundary.n_segments(), 4);
  EXPECT_EQ(scene.p.value, 3);
  EXPECT_EQ(scene.pc.value, 2);
}

TEST(Scene, GmshSceneUsesPhysicalGroups) {
  const std::string text = "[domain]\nmesh = \"" + std::string(HPCONTACT_TEST_DATA) +
                           "/square_2x2.msh\"\n[boundary]\ncontact_groups = [\"contact\"]\n"
                           "dirichlet_groups = [\"dirichlet\"]\n[contact_mesh]\nratio = 1\n"
                           "[discretization]\np = 2\npC = 0\n";
  const auto scene = scene::read_scene(write_scene("gmsh", text));
  const auto mesh = scene::build_scene_mesh(scene);
  const mesh::ContactBoundary contact(mesh);
  EXPECT_NEAR(contact.length(), 2.0, 1e-14);
  EXPECT_EQ(scene::build_scene_boundary_mesh(scene, contact).n_segments(), 2);
}

TEST(Scene, EachClassOfBadInputNamesTheKey) {
  EXPECT_EQ(error_of(kGood), "(no error)");
  EXPECT_NE(error_of(with("p = 2", "p = 0")).find("discretization.p"), std::string::npos);
  EXPECT_NE(error_of(with("pC = 1", "pC = -1")).find("discretization.pC"), std::string::npos);
  EXPECT_NE(error_of(with("n_x = 4", "n_x = 0")).find("domain.n_x"), std::string::npos);
  EXPECT_NE(error_of(with("m = 2", "m = 2\nratio = 1")).find("exactly one of m, ratio"), std::string::npos);
  EXPECT_NE(error_of(with("m = 2", "ratio = \"1/3\"")).find("whole number"), std::string::npos);
  EXPECT_NE(error_of(with("m = 2", "ratio = 0")).find("contact_mesh.ratio"), std::string::npos);
  EXPECT_NE(error_of(with("y < -0.999", "y < -0.999 +")).find("boundary.contact"), std::string::npos);
  EXPECT_NE(error_of(with("y < -0.999", "y < -5")).find("Γ_C is empty"), std::string::npos);
  EXPECT_NE(error_of(with("y > 0.999", "y < 0")).find("overlap"), std::string::npos);
  EXPECT_NE(error_of(with("[discretization]", "[discretisation]")).find("did you mean 'discretization'"),
            std::string::npos);
  EXPECT_NE(error_of("[domain\n").find("malformed TOML"), std::string::npos);
}

TEST(Scene, DegreeRulesGiveDistributions) {
  const auto scene =
      scene::read_scene(write_scene("rules", with("p = 2\npC = 1", "p = \"x < 0 ? 2 : 4\"\npC = \"x < 0 ? 0 : 1\"")));
  const auto mesh = scene::build_scene_mesh(scene);
  const auto degrees = scene::scene_cell_degrees(scene, mesh);
  int twos = 0, fours = 0;
  for (int p : degrees) (p == 2 ? twos : fours) += 1;
  EXPECT_EQ(twos, 8);
  EXPECT_EQ(fours, 8);
  const mesh::ContactBoundary contact(mesh);
  const auto boundary = scene::build_scene_boundary_mesh(scene, contact);
  EXPECT_EQ(scene::scene_segment_degrees(scene, contact, boundary), (std::vector<int>{0, 1}));
  const auto bad = scene::read_scene(write_scene("bad_rule", with("p = 2", "p = \"x + 2\"")));
  try {
    scene::scene_cell_degrees(bad, scene::build_scene_mesh(bad));
    ADD_FAILURE() << "a rule giving 1.25 must be rejected";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("discretization.p"), std::string::npos) << error.what();
  }
}

// A graded rectangle: the grading points become vertices, and ratio = h/H follows T_h|Γ_C (1/k
// merges k edges), refinements split T_h and T_{C,H} alike.
TEST(Scene, GradedRectangleAndRefinementsKeepTheRatio) {
  const auto scene = graded_scene("graded", "grading_x = [0.3]\ngrading = 0.25\ngrading_layers = 2\nrefinements = 1");
  const auto mesh = scene::build_scene_mesh(scene);
  const mesh::ContactBoundary contact(mesh);
  // 4 cells + 2 · 2 layers around x = 0.3, refined once: 16 edges on Γ_C.
  ASSERT_EQ(contact.edges().size(), 16u);
  const auto arcs = contact.breakpoints();
  EXPECT_NE(std::find_if(arcs.begin(), arcs.end(), [](double s) { return std::abs(s - 1.3) < 1e-14; }), arcs.end());
  const auto boundary = scene::build_scene_boundary_mesh(scene, contact);
  ASSERT_EQ(boundary.n_segments(), 8);
  for (int k = 0; k < 8; ++k) EXPECT_NEAR(boundary.segment_end(k), arcs[2 * k + 2], 1e-14) << k;
  // m is split by the refinements too.
  const auto refined = scene::read_scene(write_scene("refined_m", with("n_y = 4", "n_y = 4\nrefinements = 2")));
  const auto refined_mesh = scene::build_scene_mesh(refined);
  EXPECT_EQ(scene::build_scene_boundary_mesh(refined, mesh::ContactBoundary(refined_mesh)).n_segments(), 8);
  EXPECT_NE(error_of(with("n_y = 4", "n_y = 4\ngrading_x = [3.0]\ngrading_layers = 1")).find("grading"),
            std::string::npos);
}

// Grading points: local geometric layers around a point of Γ_C, which stays a breakpoint of
// T_{C,H} when ratio 1/k merges edges (k = 2 and an odd number of edges before the point, where
// merging from the end of Γ_C would straddle it); bad points name the key.
TEST(Scene, GradingPointsStayBreakpointsOfTheContactMesh) {
  const auto scene = graded_scene("graded_point", "grading_points = [[0.3, -1]]\ngrading = 0.2\ngrading_layers = 2");
  const auto mesh = scene::build_scene_mesh(scene);
  const mesh::ContactBoundary contact(mesh);
  const auto arcs = contact.breakpoints();
  const auto at_point = std::find_if(arcs.begin(), arcs.end(), [](double s) { return std::abs(s - 1.3) < 1e-14; });
  ASSERT_NE(at_point, arcs.end());
  ASSERT_EQ((at_point - arcs.begin()) % 2, 1) << "the test needs an odd number of edges before the point";
  const auto boundary = scene::build_scene_boundary_mesh(scene, contact);
  bool breakpoint = false;
  for (int k = 0; k < boundary.n_segments(); ++k)
    breakpoint = breakpoint || std::abs(boundary.segment_end(k) - 1.3) < 1e-14;
  EXPECT_TRUE(breakpoint);
  EXPECT_NE(error_of(with("n_y = 4", "n_y = 4\ngrading_points = [[1]]")).find("domain.grading_points"),
            std::string::npos);
  for (const char* outside : {"[[3, -1]]", "[[-0.99, -1]]"})  // outside; snapping leaves a thin cell
    EXPECT_NE(
        error_of(with("n_y = 4", std::string("n_y = 4\ngrading_points = ") + outside)).find("domain.grading_points"),
        std::string::npos)
        << outside;
  EXPECT_NE(error_of(with("n_y = 4", "n_y = 4\ngrading_points = [[0.0, -1], [0.5, -1]]\ngrading_layers = 1"))
                .find("share a cell"),
            std::string::npos);
}

// Study files extend a base scene: `set` replaces keys in every variant, `vary` moves dotted keys
// jointly; each variant is a checked scene, and errors name the variant.
TEST(Scene, VariantsSetAndVaryKeysOfABaseScene) {
  const auto base = write_scene("variants_base", kGood);
  const auto study = io::parse_toml_string(
      "set = { discretization = { pC = 0 } }\nvary = { \"domain.n_x\" = [4, 8], \"discretization.p\" = \"1..2\" }\n",
      "study.toml");
  const auto variants = scene::scene_variants(base, study.table("set"), study.table("vary"), "study.toml");
  ASSERT_EQ(variants.size(), 2u);
  EXPECT_EQ(variants[0].scene.n_x, 4);
  EXPECT_EQ(variants[1].scene.n_x, 8);
  EXPECT_EQ(variants[1].scene.p.value, 2);
  EXPECT_EQ(variants[1].scene.pc.value, 0);
  EXPECT_EQ(variants[1].scene.n_y, 4);
  EXPECT_EQ(variants[1].label, "discretization.p=2 domain.n_x=8");
  auto error_of_study = [&](const std::string& text) {
    try {
      const auto table = io::parse_toml_string(text, "study.toml");
      scene::scene_variants(base, table.table("set"), table.table("vary"), "study.toml");
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(error_of_study("vary = { \"domain.n_x\" = [4, 8], \"discretization.p\" = [1] }\n").find("move together"),
            std::string::npos);
  const auto bad_variant = error_of_study("vary = { \"discretization.p\" = [2, 0] }\n");
  EXPECT_NE(bad_variant.find("variant 2"), std::string::npos) << bad_variant;
  EXPECT_NE(bad_variant.find("discretization.p"), std::string::npos) << bad_variant;
  EXPECT_NE(error_of_study("vary = { \"p\" = [2] }\n").find("section.key"), std::string::npos);
}

namespace {

std::string override_error(const scene::SceneOverride& override) {
  try {
    scene::parse_scene(scene::paper_scene_text(), scene::paper_scene_name, {override});
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

}  // namespace

// docs/scene_keys.md is generated from the declarations the reader parses with; it must be current.
TEST(SceneKeys, ReferenceInDocsIsCurrent) {
  std::ifstream file(std::string(HPCONTACT_TEST_DATA) + "/../../docs/scene_keys.md");
  ASSERT_TRUE(file.good());
  std::stringstream committed;
  committed << file.rdbuf();
  EXPECT_EQ(committed.str(), scene::scene_key_reference())
      << "regenerate with: hpcontact scene-keys > docs/scene_keys.md";
}

// Every declared numeric range is the one the reader checks: a value beyond it, given as an
// override, is refused with a message naming the override's origin and the key.
TEST(SceneKeys, DeclaredRangesAreCheckedAndNameTheOrigin) {
  int checked = 0;
  for (const auto& key : scene::scene_keys()) {
    double low = 0, high = 0;
    if ((key.type != "integer" && key.type != "number") ||
        std::sscanf(key.allowed.c_str(), "[%lf, %lf]", &low, &high) != 2)
      continue;
    scene::SceneOverride beyond{key.dotted(), 2 * high + 1, "test override"};
    if (key.type == "integer") beyond.value = static_cast<long long>(2 * high + 1);
    const std::string message = override_error(beyond);
    EXPECT_NE(message.find("test override: key '" + key.dotted() + "'"), std::string::npos)
        << key.dotted() << ": " << message;
    ++checked;
  }
  EXPECT_GE(checked, 10);
}

// Overrides replace single keys: one of the contact mesh's exclusive keys replaces the others,
// a rule is replaced by an integer, unknown keys and keys that do not apply are refused.
TEST(SceneKeys, OverridesReplaceKeysAndAreChecked) {
  const std::string base = R"toml([domain]
n_x = 8
n_y = 8
[boundary]
contact = "abs(y + 1) < 1e-9"
dirichlet = "abs(y - 1) < 1e-9"
[contact_mesh]
m = 3
[discretization]
p = "1 + (x > 0)"
pC = 0
)toml";
  const auto scene = scene::parse_scene(
      base, "base.toml", {{"contact_mesh.ratio", std::string("1/2"), "--ratio"}, {"discretization.p", 4LL, "--p"}});
  ASSERT_EQ(scene.ratio.size(), 1u);
  EXPECT_EQ(scene.ratio.front().text, "1/2");
  EXPECT_EQ(scene.p.value, 4);
  EXPECT_TRUE(scene.p.rule.empty());
  EXPECT_EQ(scene.where("contact_mesh.ratio"), "--ratio");
  EXPECT_EQ(scene.where("discretization.pC"), "base.toml");
  EXPECT_NE(override_error({"discretization.q", 1LL, "--q"}).find("--q: unknown scene key 'discretization.q'"),
            std::string::npos);
  EXPECT_NE(
      override_error({"contact_mesh.ratio", std::string("0"), "--ratio"}).find("--ratio: key 'contact_mesh.ratio'"),
      std::string::npos);
  EXPECT_NE(override_error({"infsup.norm", std::string("h1"), "--norm"}).find("--norm: key 'infsup.norm'"),
            std::string::npos);
  const std::string gmsh = std::string(R"([domain]
mesh = ")") + HPCONTACT_TEST_DATA +
                           R"(/square_2x2.msh"
[boundary]
contact_groups = ["contact"]
[contact_mesh]
ratio = 1
[discretization]
p = 1
pC = 0
)";
  try {
    scene::parse_scene(gmsh, "gmsh.toml", {{"domain.n_x", 4LL, "--n"}});
    ADD_FAILURE() << "n_x on a Gmsh scene was accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("--n: key 'domain.n_x'"), std::string::npos) << error.what();
  }
}
