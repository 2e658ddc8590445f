// The [adapt] keys and check_adapt.
#include "scene/adapt_keys.hpp"

#include <fmt/format.h>

#include "core/error.hpp"

namespace hpcontact::scene {

using io::TomlTable;

void add_adapt_keys(std::vector<SceneKey>& keys) {
  const auto add = [&](SceneKey key) { keys.push_back(std::move(key)); };
  add({"adapt", "target", "number", "", "(0, 1]",
       "adapt until the estimated error in the energy, η²/2, is at most this; giving it makes the scene adaptive", "",
       [](const TomlTable& table, Scene& scene) {
         if (!table.has("target")) return;
         scene.adapt.target = table.number_in("target", 0.0, 1.0);
         if (!(scene.adapt.target > 0.0))
           throw_bad_input(table.origin("target"), table.qualified("target"), "0", "a number in (0, 1]");
       }});
  add({"adapt", "max_unknowns", "integer", "200000", "[10, 100000000]",
       "stop before a step whose T_h would have more unknowns", "", [](const TomlTable& table, Scene& scene) {
         scene.adapt.max_unknowns = table.integer("max_unknowns", 10, 100000000, 200000);
       }});
  add({"adapt", "max_steps", "integer", "60", "[1, 1000]", "stop after this many solves", "",
       [](const TomlTable& table, Scene& scene) {
         scene.adapt.max_steps = static_cast<int>(table.integer("max_steps", 1, 1000, 60));
       }});
  add({"adapt", "fraction", "number", "0.5", "[0.05, 1]",
       "Dörfler marking: the fewest leaves whose indicators hold this share of η² are refined", "",
       [](const TomlTable& table, Scene& scene) {
         scene.adapt.fraction = table.number_in("fraction", 0.05, 1.0, 0.5);
       }});
  add({"adapt", "smoothness", "number", "0.5", "[0.01, 0.99]",
       "a marked cell whose Legendre coefficients decay by at most this ratio per degree gets p + 1, any other is "
       "split",
       "", [](const TomlTable& table, Scene& scene) {
         scene.adapt.smoothness = table.number_in("smoothness", 0.01, 0.99, 0.5);
       }});
  add({"adapt", "max_degree", "integer", "14", "[1, 20]", "p is not raised beyond this (a cell at it is split)", "",
       [](const TomlTable& table, Scene& scene) {
         scene.adapt.max_degree = static_cast<int>(table.integer("max_degree", 1, 20, 14));
       }});
  add({"adapt", "reference_energy", "number", "", "finite",
       "the exact energy, if known: adapt.csv then has the columns error_energy and effectivity", "",
       [](const TomlTable& table, Scene& scene) {
         if (table.has("reference_energy")) scene.adapt.reference_energy = table.number("reference_energy");
       }});
}

void check_adapt(const Scene& scene) {
  if (!scene.is_adaptive()) {
    for (const auto& key : scene.given)
      if (key.starts_with("adapt."))
        throw_bad_input(scene.where(key), key, "(given)", "with adapt.target, which makes the scene adaptive");
    return;
  }
  const auto refuse = [&](const std::string& key, const std::string& value, const std::string& allowed) {
    throw_bad_input(scene.where(key), key, value, allowed + " in an adaptive scene (adapt.target given)");
  };
  if (scene.dimension() == 3) refuse("adapt.target", "(given)", "a planar scene: 3-D scenes do not adapt yet");
  if (!scene.body.empty())
    refuse("adapt.target", "(given)", "a scene of one body against a rigid obstacle: two bodies do not adapt yet");
  const auto problems = scene.is_elastic() ? scene.elastic_effects().size() : scene.contact_effects().size();
  if (problems != 1)
    refuse("run.effects", fmt::format("({} contact problems)", problems),
           "exactly one contact problem (signorini, friction, friction_s; frictionless, tresca, coulomb, tied), "
           "which the mesh adapts to");
  if (scene.has_effect(Effect::convergence)) refuse("run.effects", "convergence", "no convergence effect");
  if (scene.fit_free_boundary)
    refuse("solve.fit_free_boundary", "true", "false (the adaptivity finds the free boundary itself)");
  if (!scene.given.contains("contact_mesh.ratio") || scene.ratio.size() != 1 || scene.ratio[0].value != 1.0)
    refuse("contact_mesh", "(not ratio = 1)", "ratio = 1: T_{C,H} is the trace of T_h, refined with it");
  if (!scene.p.rule.empty() || !scene.pc.rule.empty())
    refuse(!scene.p.rule.empty() ? "discretization.p" : "discretization.pC",
           !scene.p.rule.empty() ? scene.p.rule : scene.pc.rule,
           "a number: the start is uniform, p_T − p_C stays p − p_C on every segment");
  if (scene.pc.value >= scene.p.value)
    refuse("discretization.pC", std::to_string(scene.pc.value),
           fmt::format("below p = {}: p_C = p_T − (p − p_C) follows every raised p_T", scene.p.value));
  if (scene.p.value > scene.adapt.max_degree)
    refuse("discretization.p", std::to_string(scene.p.value),
           fmt::format("at most adapt.max_degree = {}", scene.adapt.max_degree));
}

}  // namespace hpcontact::scene
