// 3-D scenes on Gmsh meshes through `hpcontact solve`: the extruded block of extruded_block.geo
// gives the box scenes' energies and force (Γ_C and Γ_D by physical surfaces), an unstructured
// mesh (tetrahedra split into hexahedra) the box's solution to its discretization error, and the
// keys and meshes such scenes refuse, by name; Gmsh's tetrahedra the box's solution too.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "support/cli_runner.hpp"

namespace hpcontact::testing {
namespace {

const std::string kStudies = std::string(HPCONTACT_SOURCE_DIR) + "/studies/three_d/";

nlohmann::json summary_of(const std::filesystem::path& out) {
  std::ifstream file(out / "summary.json");
  return nlohmann::json::parse(file);
}

std::string write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
  return path.string();
}

TEST(SolidGmshScene, ExtrudedBlockGivesTheBoxScenesEnergies) {
  const auto dir = scratch("solid_gmsh_extruded");
  const auto box = run("solve " + kStudies + "extruded_signorini.toml --out " + (dir / "box").string());
  ASSERT_EQ(box.exit_code, 0) << box.output;
  const auto gmsh = run("solve " + kStudies + "extruded_gmsh.toml --out " + (dir / "gmsh").string());
  ASSERT_EQ(gmsh.exit_code, 0) << gmsh.output;
  const auto box_summary = summary_of(dir / "box"), gmsh_summary = summary_of(dir / "gmsh");
  for (const char* effect : {"signorini", "friction_s"}) {
    const double expected = box_summary.at(effect).at("energy").get<double>();
    EXPECT_NEAR(gmsh_summary.at(effect).at("energy").get<double>(), expected, 1e-10 * std::abs(expected)) << effect;
  }
  EXPECT_EQ(gmsh_summary.at("dimension").get<int>(), 3);
  EXPECT_EQ(gmsh_summary.at("faces_on_contact").get<int>(), 16);
}

TEST(SolidGmshScene, ElasticBlockWithRollersByGroupGivesTheBoxScenesEnergyAndForce) {
  // extruded_frictionless.toml on the Gmsh block: Γ_D the top, the rollers u_y = 0 by predicate.
  const auto dir = scratch("solid_gmsh_elastic");
  const std::string scene = write(dir / "block.toml", "[domain]\nmesh = \"" + kStudies +
                                                          "extruded_block.geo\"\n"
                                                          "[boundary]\ncontact_groups = [\"bottom\"]\n"
                                                          "dirichlet_groups = [\"top\"]\n"
                                                          "fixed_y = \"abs(y) < 1e-9 || abs(y - 0.5) < 1e-9\"\n"
                                                          "[contact_mesh]\nratio = 1\n[discretization]\np = 2\npC = 1\n"
                                                          "[material]\nE = \"1\"\nnu = \"0.3\"\n"
                                                          "[data]\nf_z = \"-1\"\ng = \"0.05 + 0.2 * (x - 1)^2\"\n"
                                                          "[run]\neffects = [\"frictionless\"]\n");
  const auto gmsh = run("solve " + scene + " --out " + (dir / "gmsh").string());
  ASSERT_EQ(gmsh.exit_code, 0) << gmsh.output;
  const auto box = run("solve " + kStudies + "extruded_frictionless.toml --out " + (dir / "box").string());
  ASSERT_EQ(box.exit_code, 0) << box.output;
  const auto gmsh_result = summary_of(dir / "gmsh").at("frictionless");
  const auto box_result = summary_of(dir / "box").at("frictionless");
  for (const char* key : {"energy", "total_force"}) {
    const double expected = box_result.at(key).get<double>();
    EXPECT_NEAR(gmsh_result.at(key).get<double>(), expected, 1e-9 * std::abs(expected)) << key;
  }
}

// The unit cube, Γ_C its face z = 0 (OpenCASCADE's surface 5), Γ_D its face z = 1 (surface 6).
std::string cube_geo(const std::filesystem::path& dir, const std::string& options) {
  return write(dir / "cube.geo", "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n" + options +
                                     "\nPhysical Surface(\"floor\") = {5};\nPhysical Surface(\"lid\") = {6};\n"
                                     "Physical Volume(\"cube\") = {1};\n");
}

// The scalar Signorini problem on the unit cube: -Δu = -1, u = 0 on the lid, u ≥ g on the floor.
std::string cube_scene(const std::string& domain, const std::string& contact, const std::string& dirichlet) {
  return "[domain]\n" + domain + "[boundary]\n" + contact + dirichlet +
         "[contact_mesh]\nm = 4\n[discretization]\np = 2\npC = 1\n"
         "[data]\nf = \"-1\"\ng = \"-0.5 * (x - 0.5)^2 - 0.2\"\n[run]\neffects = [\"signorini\"]\n";
}

/// The energy of cube_scene's problem on the 8³ box of hexahedra (p = 2), solved in dir/box.
double box_energy(const std::filesystem::path& dir) {
  const auto box =
      run("solve " +
          write(dir / "box.toml",
                cube_scene("x_min = 0.0\nx_max = 1.0\ny_min = 0.0\ny_max = 1.0\nn_x = 8\nn_y = 8\nn_z = 8\n",
                           "contact = \"abs(z) < 1e-9\"\n", "dirichlet = \"abs(z - 1) < 1e-9\"\n")) +
          " --out " + (dir / "box").string());
  EXPECT_EQ(box.exit_code, 0) << box.output;
  return summary_of(dir / "box").at("signorini").at("energy").get<double>();
}

/// The value of an attribute in the first element of an XML file that has it.
std::string xml_attribute(const std::filesystem::path& file, const std::string& name) {
  std::ifstream in(file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto at = text.find(name + "=\"");
  if (at == std::string::npos) return "";
  const auto from = at + name.size() + 2;
  return text.substr(from, text.find('"', from) - from);
}

TEST(SolidGmshScene, TetrahedraGiveTheBoxSolutionToDiscretizationError) {
  // studies/three_d/tetrahedra.toml: the cube meshed by Gmsh's defaults, Delaunay tetrahedra, Γ_C
  // of triangles clipped against the 4 × 4 grid T_{C,H}, p = 3 (measured: 1.7e-5 relative to the
  // energy on the 8³ box of hexahedra).
  const auto dir = scratch("solid_gmsh_tetrahedra");
  const auto result = run("solve " + kStudies + "tetrahedra.toml --out " + (dir / "tet").string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const double expected = box_energy(dir);
  const double energy = summary_of(dir / "tet").at("signorini").at("energy").get<double>();
  std::printf("energy: tetrahedra %.8f, box %.8f\n", energy, expected);
  EXPECT_NEAR(energy, expected, 2e-4 * std::abs(expected));
  EXPECT_NEAR(summary_of(dir / "tet").at("signorini").at("contact_area").get<double>(), 1.0, 1e-9);
  // The solution's VTU: p³ = 27 linear tetrahedra per cell on 20 lattice points each.
  const int cells = std::stoi(xml_attribute(dir / "tet" / "solution_signorini.vtu", "NumberOfCells"));
  const int points = std::stoi(xml_attribute(dir / "tet" / "solution_signorini.vtu", "NumberOfPoints"));
  EXPECT_EQ(cells % 27, 0);
  EXPECT_EQ(points, cells / 27 * 20);
}

TEST(SolidGmshScene, BoxOfTetrahedraGivesTheBoxOfHexahedraSolutionToDiscretizationError) {
  // domain.cells = "tetrahedra" cuts each of the 6³ hexahedra into six; at p = 3 both spaces have
  // (3 · 6 + 1)³ lattice points of unknowns (measured: energies 5e-5 apart).
  const auto dir = scratch("solid_box_tetrahedra");
  const std::string box = cube_scene("x_min = 0.0\nx_max = 1.0\ny_min = 0.0\ny_max = 1.0\nn_x = 6\nn_y = 6\nn_z = 6\n",
                                     "contact = \"abs(z) < 1e-9\"\n", "dirichlet = \"abs(z - 1) < 1e-9\"\n");
  const std::string scene = write(dir / "box.toml", box);
  std::array<double, 2> energy{};
  for (int k = 0; k < 2; ++k) {
    const auto out = dir / (k == 0 ? "hexahedra" : "tetrahedra");
    const auto result = run("solve " + scene + " --set discretization.p=3" +
                            (k == 1 ? " --set 'domain.cells=\"tetrahedra\"'" : "") + " --out " + out.string());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("ndofs 6498"), std::string::npos) << result.output;
    energy[k] = summary_of(out).at("signorini").at("energy").get<double>();
  }
  std::printf("energy: hexahedra %.8f, tetrahedra %.8f\n", energy[0], energy[1]);
  EXPECT_NEAR(energy[1], energy[0], 2e-4 * std::abs(energy[0]));
  EXPECT_NE(energy[1], energy[0]);  // (another mesh: not the hexahedra again)
  // Triangles cut no box, tetrahedra no rectangle, and a 3-D .geo decides its own cells.
  expect_refused(run("solve " + scene + " --set 'domain.cells=\"triangles\"' --out " + (dir / "x").string()),
                 "hexahedra (the default) or tetrahedra in a 3-D box");
  expect_refused(
      run("solve " + kStudies + "tetrahedra.toml --set 'domain.cells=\"tetrahedra\"' --out " + (dir / "x").string()),
      "its own settings decide its cells");
  expect_refused(
      run("solve " + std::string(HPCONTACT_SOURCE_DIR) +
          "/studies/elasticity/square.toml --set 'domain.cells=\"tetrahedra\"' --out " + (dir / "x").string()),
      "quadrilaterals or triangles in a planar scene");
}

TEST(SolidGmshScene, UnstructuredHexahedraGiveTheBoxSolutionToDiscretizationError) {
  const auto dir = scratch("solid_gmsh_unstructured");
  const std::string geo = cube_geo(dir, "Mesh.SubdivisionAlgorithm = 2;\nMeshSize{ PointsOf{ Volume{1}; } } = 0.6;");
  const auto gmsh =
      run("solve " +
          write(dir / "gmsh.toml", cube_scene("mesh = \"" + geo + "\"\nmesh_size = 0.35\n",
                                              "contact_groups = [\"floor\"]\n", "dirichlet_groups = [\"lid\"]\n")) +
          " --out " + (dir / "gmsh").string());
  ASSERT_EQ(gmsh.exit_code, 0) << gmsh.output;
  const double expected = box_energy(dir);
  const auto gmsh_result = summary_of(dir / "gmsh").at("signorini");
  std::printf("energy: Gmsh mesh %.8f, box %.8f\n", gmsh_result.at("energy").get<double>(), expected);
  // (measured: 2.9e-5 relative, the two meshes' discretization errors)
  EXPECT_NEAR(gmsh_result.at("energy").get<double>(), expected, 2e-4 * std::abs(expected));
  EXPECT_GT(gmsh_result.at("contact_area").get<double>(), 0.0);
}

TEST(SolidGmshScene, MeshesAndKeysThatDoNotFitAreRefusedByName) {
  const auto dir = scratch("solid_gmsh_refused");
  const std::string block = "mesh = \"" + kStudies + "extruded_block.geo\"\n";
  const auto missing_group = run(
      "solve " +
      write(dir / "group.toml", cube_scene(block, "contact_groups = [\"floor\"]\n", "dirichlet_groups = [\"top\"]\n")) +
      " --out " + (dir / "out").string());
  expect_refused(missing_group, "boundary.contact_groups");
  expect_refused(missing_group, "physical surfaces of the mesh: bottom, top");
  // Each group name must exist, even beside one that does.
  expect_refused(run("solve " +
                     write(dir / "misspelt.toml", cube_scene(block, "contact_groups = [\"bottom\", \"botom\"]\n",
                                                             "dirichlet_groups = [\"top\"]\n")) +
                     " --out " + (dir / "out").string()),
                 "key 'boundary.contact_groups' = \"botom\"");
  // Γ_D taking part of Γ_C is refused, as in planar scenes.
  expect_refused(run("solve " +
                     write(dir / "overlap.toml", cube_scene(block, "contact_groups = [\"bottom\"]\n",
                                                            "dirichlet = \"z < -0.9 && x > 0\"\n")) +
                     " --out " + (dir / "out").string()),
                 "Γ_C and Γ_D overlap");
  // A file Gmsh cannot read is refused when the scene is read, with Gmsh's message.
  const std::string broken = write(dir / "broken.geo", "Point(1) = {0, 0, 0;\n");
  expect_refused(
      run("solve " + write(dir / "broken.toml", cube_scene("mesh = \"" + broken + "\"\n", "contact = \"1\"\n", "")) +
          " --out " + (dir / "out").string()),
      "key 'domain.mesh': ");
  expect_refused(run("solve " +
                     write(dir / "box_key.toml", cube_scene(block + "n_z = 4\n", "contact_groups = [\"bottom\"]\n",
                                                            "dirichlet_groups = [\"top\"]\n")) +
                     " --out " + (dir / "out").string()),
                 "domain.n_z");
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "summary.json"));
}

}  // namespace
}  // namespace hpcontact::testing
