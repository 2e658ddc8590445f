// The run pipeline: a scalar and an elastic scene run through the one driver, its typed
// result agrees with the summary.json written from it, and the convergence effect's rows are
// complete and measured against the finest level, for both models.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "driver/scene_run.hpp"
#include "driver/summary_json.hpp"
#include "scene/scene_reader.hpp"
#include "support/slepc_test_environment.hpp"

using namespace hpcontact;

namespace {

// The §7 scene with `effects`, and further overrides.
scene::Scene paper_scene(const std::vector<std::string>& effects, std::vector<scene::SceneOverride> overrides = {}) {
  overrides.push_back({"run.effects", effects, "test"});
  overrides.push_back({"data.g", std::string("-x^2"), "test"});
  return scene::parse_scene(scene::paper_scene_text(), scene::paper_scene_name, overrides);
}

// An elastic square clamped on top, pressed by its weight onto an obstacle below (elastic square
// of the stability sweep, smaller).
scene::Scene elastic_scene(const std::vector<std::string>& effects) {
  return scene::parse_scene(R"toml([domain]
n_x = 4
n_y = 4
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
nu = "0.3"
[data]
f_y = "-1"
g = "0.05 + 0.2 * x^2"
s = "0.01"
)toml",
                            "elastic.toml", {{"run.effects", effects, "test"}});
}

driver::RunResult run(const scene::Scene& scene) {
  driver::SceneRunOptions options;
  options.write_files = false;
  return driver::run_scene(scene, options);
}

// Every contact result as summary.json has it: the one JSON writer reads the same fields.
void expect_summary_matches(const driver::RunResult& result) {
  const auto summary = nlohmann::json::parse(driver::summary_json(result));
  EXPECT_EQ(summary["ndofs"].get<long long>(), result.n_dofs);
  for (const auto& contact : result.contacts) {
    ASSERT_TRUE(summary.contains(contact.problem)) << contact.problem;
    EXPECT_EQ(summary[contact.problem]["energy"].get<double>(), contact.energy);
    EXPECT_EQ(summary[contact.problem]["solver"]["iterations"].get<int>(), contact.solver.iterations);
    EXPECT_EQ(summary[contact.problem].contains("total_force"), contact.total_force.has_value());
    if (contact.contact_force)
      EXPECT_EQ(summary[contact.problem]["contact_force"].get<std::vector<double>>(),
                (std::vector<double>{contact.contact_force->at(0), contact.contact_force->at(1)}));
  }
  ASSERT_EQ(summary.contains("infsup"), result.infsup.has_value());
  if (result.infsup) {
    EXPECT_EQ(summary["infsup"]["alpha"].get<double>(), result.infsup->record.alpha);
  }
}

}  // namespace

TEST(RunPipeline, ScalarSceneGivesTypedResultsOfEveryEffect) {
  const auto result = run(paper_scene({"signorini", "friction_s", "infsup"}));
  ASSERT_EQ(result.contacts.size(), 2u);
  EXPECT_EQ(result.contacts[0].problem, "signorini");
  EXPECT_EQ(result.contacts[1].problem, "friction_s");
  for (const auto& contact : result.contacts) {
    EXPECT_LT(contact.solver.kkt_residual, 1e-12) << contact.problem;
    EXPECT_TRUE(contact.constraint_points.has_value()) << "scalar problems report their constraint points";
    EXPECT_FALSE(contact.total_force.has_value());
    EXPECT_EQ(contact.n_dofs, result.n_dofs);
  }
  EXPECT_LT(result.contact("signorini").energy, 0.0);
  EXPECT_THROW(result.contact("tresca"), std::out_of_range);
  ASSERT_TRUE(result.infsup.has_value());
  EXPECT_GT(result.infsup->record.alpha, 0.1);  // p = 1, p_C = 0, h/H = 1 on the §7 mesh: stable at n = 8
  EXPECT_FALSE(result.material.has_value());
  expect_summary_matches(result);
}

TEST(RunPipeline, ElasticSceneRunsThroughTheSamePipeline) {
  const auto result = run(elastic_scene({"frictionless", "tresca", "infsup"}));
  ASSERT_EQ(result.contacts.size(), 2u);
  for (const auto& contact : result.contacts) {
    EXPECT_LT(contact.solver.kkt_residual, 1e-10) << contact.problem;
    ASSERT_TRUE(contact.total_force.has_value()) << "an elastic body reports its total force";
    EXPECT_GT(*contact.total_force, 0.0) << contact.problem;
    EXPECT_FALSE(contact.constraint_points.has_value());
    // Γ_C is the bottom edge: n = (0, −1), t = (1, 0), so ∫ (−p n + σ_nt t) ds = (T, P).
    ASSERT_TRUE(contact.contact_force.has_value() && contact.tangential_force.has_value());
    EXPECT_NEAR(contact.contact_force->at(0), *contact.tangential_force, 1e-14);
    EXPECT_NEAR(contact.contact_force->at(1), *contact.total_force, 1e-13 * *contact.total_force);
  }
  ASSERT_TRUE(result.material.has_value());
  EXPECT_EQ(result.material->model, "plane_strain");
  ASSERT_TRUE(result.infsup.has_value());
  EXPECT_TRUE(result.infsup->primal_norm.has_value());
  expect_summary_matches(result);
}

// One convergence for every model: each problem on 1 + refinements levels, in problem order, the
// finest level its own reference (errors 0), the energy errors falling towards it.
TEST(RunPipeline, ConvergenceRowsOfBothModelsAreCompleteAndAgainstTheFinestLevel) {
  const std::vector<scene::SceneOverride> two_levels{{"convergence.refinements", 2LL, "test"}};
  auto scalar = paper_scene({"signorini", "convergence"}, two_levels);
  auto elastic = elastic_scene({"frictionless", "convergence"});
  elastic.convergence_refinements = 2;
  for (const auto& scene : {scalar, elastic}) {
    const auto result = run(scene);
    ASSERT_EQ(result.convergence.size(), 3u) << scene.file;
    for (int k = 0; k < 3; ++k) {
      const auto& row = result.convergence[static_cast<std::size_t>(k)];
      EXPECT_EQ(row.level, k);
      EXPECT_EQ(row.problem, result.contacts.front().problem);
      if (k > 0) {
        EXPECT_GT(row.n_dofs, result.convergence[static_cast<std::size_t>(k) - 1].n_dofs);
      }
    }
    EXPECT_EQ(result.convergence.back().error_energy, 0.0);
    EXPECT_EQ(result.convergence.back().error_lambda, 0.0);
    EXPECT_GT(result.convergence[0].error_energy, result.convergence[1].error_energy) << scene.file;
    EXPECT_EQ(result.convergence[0].energy, result.contacts.front().energy) << "level 0 is the scene's own solve";
    // Each refined level's operators are in the log under its name.
    int level_records = 0;
    for (const auto& record : result.operators)
      level_records += record.name.find("(convergence level") != std::string::npos;
    EXPECT_GT(level_records, 0);
  }
}
