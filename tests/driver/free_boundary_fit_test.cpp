// Meshes fitted to the free boundary (its points located by contact/free_boundary_test.cpp's
// functions), which is what makes hp refinement of the §7 problems converge exponentially (the
// work–precision references).
#include "driver/free_boundary_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "driver/scene_discretization.hpp"
#include "scene/scene_mesh.hpp"
#include "scene/scene_reader.hpp"
#include "support/paper_scene.hpp"

using namespace hpcontact;

namespace {

// The §7 scene graded towards (1, 0) and (1, -1), with g, degrees p and p - 2 and one effect.
scene::Scene paper_scene(const std::string& effect, int p, int layers) {
  return scene::parse_scene(hpcontact::testing::paper_scene_with({{"domain.grading_points", "[[1, 0], [1, -1]]"}}),
                            "paper_scene.toml",
                            {{"domain.grading", 0.2, "test"},
                             {"domain.grading_layers", static_cast<long long>(layers), "test"},
                             {"discretization.p", static_cast<long long>(p), "test"},
                             {"discretization.pC", static_cast<long long>(p - 2), "test"},
                             {"data.g", std::string("-x^2"), "test"},
                             {"run.effects", std::vector<std::string>{effect}, "test"}});
}

double energy(const scene::Scene& scene, const std::string& effect) {
  return driver::solve_scene_contact(scene, *scene::contact_problem_of(*scene::effect_named(effect))).solution.energy;
}

}  // namespace

// On meshes fitted to the free boundary, raising p from 8 to 10 changes the energy 30 times less
// than on the same meshes graded only at the corners: the fit turns algebraic into exponential
// convergence.
TEST(FreeBoundary, FittedMeshesConvergeExponentially) {
  for (const std::string effect : {"signorini", "friction_s"}) {
    const auto fit = driver::fit_free_boundary(paper_scene(effect, 8, 8),
                                               {*scene::contact_problem_of(*scene::effect_named(effect))});
    EXPECT_EQ(fit.points.size(), effect == "signorini" ? 2u : 1u) << effect;
    EXPECT_LE(fit.moved, 1e-6 * 2.0) << effect;
    EXPECT_LE(fit.solves, 12) << effect;
    auto fitted_p10 = paper_scene(effect, 10, 8);
    fitted_p10.grading_points = fit.scene.grading_points;
    const double fitted_change = std::abs(energy(fit.scene, effect) - energy(fitted_p10, effect));
    const double unfitted_change =
        std::abs(energy(paper_scene(effect, 8, 8), effect) - energy(paper_scene(effect, 10, 8), effect));
    EXPECT_LT(30 * fitted_change, unfitted_change)
        << effect << ": fitted " << fitted_change << ", unfitted " << unfitted_change;
    EXPECT_LT(fitted_change, 3e-9) << effect;
  }
}
