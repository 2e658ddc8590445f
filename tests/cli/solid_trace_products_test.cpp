// The products path of 3-D solves (solve.trace_operator = "products": S = B K⁻¹ Bᵀ applied by one
// solve each, MPRGP or FISTA, S never formed) against the dense path (S from the factor's trailing
// block, the active-set method) through `hpcontact solve`: the same energy, multiplier samples and
// gap for the scalar problems (9), (15), frictionless and Tresca contact (and on a T_{C,H} of
// triangles); the summary names the
// path and counts the products; planar scenes refuse the key by name.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/cli_runner.hpp"

namespace hpcontact::testing {
namespace {

const std::string kStudies = std::string(HPCONTACT_SOURCE_DIR) + "/studies/";
const std::string kTriangles = std::string(HPCONTACT_SOURCE_DIR) + "/tests/data/extruded_contact.geo";

struct Case {
  const char* name;
  std::string scene_and_keys;
  const char* effect;
  const char* multiplier;  ///< the boundary CSV's multiplier column
};

nlohmann::json solve_on_path(const Case& c, const char* path, const std::filesystem::path& out) {
  const auto solved = run("solve " + c.scene_and_keys + " --effects " + c.effect + " --set 'solve.trace_operator=\"" +
                          path + "\"' --out " + out.string());
  EXPECT_EQ(solved.exit_code, 0) << solved.output;
  std::ifstream file(out / "summary.json");
  return nlohmann::json::parse(file).at(c.effect);
}

TEST(SolidTraceProducts, ProductsPathEqualsTheDensePath) {
  const std::string extruded = kStudies + "three_d/extruded_signorini.toml";
  const std::string elastic = kStudies + "three_d/extruded_frictionless.toml";
  const std::vector<Case> cases{
      {"signorini", extruded, "signorini", "lambda"},
      {"friction_s", extruded, "friction_s", "lambda"},
      {"frictionless", elastic, "frictionless", "pressure"},
      {"tresca", elastic + " --set 'data.f_x=\"0.05\"' --set 'data.s=\"0.1\"'", "tresca", "traction_1"},
      // the cube of the 3-D stability study, 8 × 8 × 8 cells, H = h, p_C = 0 (64 multipliers)
      {"cube",
       kStudies + "three_d/cube.toml --set domain.n_x=8 --set domain.n_y=8 --set domain.n_z=8 --set "
                  "'contact_mesh.ratio=\"1\"' --set discretization.pC=0",
       "signorini", "lambda"},
      // T_{C,H} of triangles from Gmsh (P_1 at the vertices), scalar and elastic
      {"triangles_signorini", extruded + " --set 'contact_mesh.mesh=\"" + kTriangles + "\"'", "signorini", "lambda"},
      {"triangles_frictionless", elastic + " --set 'contact_mesh.mesh=\"" + kTriangles + "\"'", "frictionless",
       "pressure"}};
  for (const Case& c : cases) {
    const auto dir = scratch(std::string("trace_products_") + c.name);
    const auto dense = solve_on_path(c, "dense", dir / "dense");
    const auto products = solve_on_path(c, "products", dir / "products");
    EXPECT_EQ(dense.at("solver").at("trace_operator"), "dense") << c.name;
    EXPECT_EQ(products.at("solver").at("trace_operator"), "products") << c.name;
    // (MPRGP for bounds, FISTA for Tresca's discs; each step takes at least one product)
    EXPECT_EQ(products.at("solver").at("method"), std::string(c.effect) == "tresca" ? "projected-gradient" : "mprgp")
        << c.name;
    EXPECT_GT(products.at("solver").at("iterations").get<long>(), 0) << c.name;
    EXPECT_GE(products.at("solver").at("products").get<long>(), products.at("solver").at("iterations").get<long>())
        << c.name;
    const double energy = dense.at("energy").get<double>();
    EXPECT_NEAR(products.at("energy").get<double>(), energy, 1e-10 * std::abs(energy)) << c.name;
    // The samples on Γ_C: the multiplier and the primal trace (u, or the gap) at every point.
    const auto a = read_csv(dir / "dense" / (std::string("boundary_") + c.effect + ".csv")).numeric_columns();
    const auto b = read_csv(dir / "products" / (std::string("boundary_") + c.effect + ".csv")).numeric_columns();
    for (const char* column : {c.multiplier, std::string(c.multiplier) == "lambda" ? "u" : "gap"}) {
      const auto& x = a.at(column);
      const auto& y = b.at(column);
      ASSERT_EQ(x.size(), y.size());
      double scale = 0.0, worst = 0.0;
      for (std::size_t k = 0; k < x.size(); ++k) {
        scale = std::max(scale, std::abs(x[k]));
        worst = std::max(worst, std::abs(x[k] - y[k]));
      }
      EXPECT_LT(worst, 1e-8 * std::max(scale, 1e-3)) << c.name << " " << column;
    }
  }
}

TEST(SolidTraceProducts, PlanarScenesRefuseTheKey) {
  const auto planar = run("solve " + kStudies +
                          "paper/figure1_signorini.toml --effects signorini --set "
                          "'solve.trace_operator=\"products\"' --out " +
                          (scratch("trace_products_planar") / "out").string());
  expect_refused(planar, "solve.trace_operator");
  const auto misspelt = run("solve " + kStudies +
                            "three_d/extruded_signorini.toml --set "
                            "'solve.trace_operator=\"sparse\"' --out " +
                            (scratch("trace_products_misspelt") / "out").string());
  expect_refused(misspelt, "auto, dense, products");
}

TEST(SolidTraceProducts, TriangleMultiplierMeshesRefuseWhatTheyCannotDo) {
  const std::string scene =
      kStudies + "three_d/extruded_signorini.toml --set 'contact_mesh.mesh=\"" + kTriangles + "\"'";
  const auto quadratic =
      run("solve " + scene + " --set discretization.pC=2 --out " + (scratch("triangles_quadratic") / "out").string());
  expect_refused(quadratic, "discretization.pC");
  const auto alpha = run("solve " + scene + " --effects infsup --out " + (scratch("triangles_alpha") / "out").string());
  expect_refused(alpha, "contact_mesh.mesh");
  const auto fine = run("solve " + scene + " --set contact_mesh.mesh_size=1e-4 --out " +
                        (scratch("triangles_fine") / "out").string());
  expect_refused(fine, "contact_mesh.mesh_size");
  const auto quads = run("solve " + kStudies + "three_d/extruded_signorini.toml --set 'contact_mesh.mesh=\"" +
                         std::string(HPCONTACT_SOURCE_DIR) + "/tests/data/square_2x2.msh\"' --out " +
                         (scratch("triangles_quads") / "out").string());
  expect_refused(quads, "contact_mesh.mesh");
  const auto planar = run("solve " + kStudies + "paper/figure1_signorini.toml --set 'contact_mesh.mesh=\"" +
                          kTriangles + "\"' --out " + (scratch("triangles_planar") / "out").string());
  expect_refused(planar, "contact_mesh.mesh");
}

}  // namespace
}  // namespace hpcontact::testing
