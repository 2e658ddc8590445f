// Names of effects and outputs, and the questions asked of a scene.
#include "scene/scene.hpp"

#include <algorithm>
#include <array>

namespace hpcontact::scene {

std::string to_string(Effect effect) {
  switch (effect) {
    case Effect::signorini:
      return "signorini";
    case Effect::friction:
      return "friction";
    case Effect::friction_s:
      return "friction_s";
    case Effect::infsup:
      return "infsup";
    case Effect::convergence:
      return "convergence";
    case Effect::frictionless:
    case Effect::tresca:
    case Effect::coulomb:
    case Effect::tied:
      return contact::to_string(*elastic_problem_of(effect));
  }
  return "?";
}

std::string to_string(Output output) {
  switch (output) {
    case Output::summary:
      return "summary";
    case Output::boundary:
      return "boundary";
    case Output::vtu:
      return "vtu";
    case Output::mode:
      return "mode";
  }
  return "?";
}

const std::vector<Effect>& all_effects() {
  static const std::vector<Effect> effects{Effect::signorini, Effect::friction,    Effect::friction_s,
                                           Effect::infsup,    Effect::convergence, Effect::frictionless,
                                           Effect::tresca,    Effect::coulomb,     Effect::tied};
  return effects;
}

const std::vector<Output>& all_outputs() {
  static const std::vector<Output> outputs{Output::summary, Output::boundary, Output::vtu, Output::mode};
  return outputs;
}

Effect effect_of(contact::ContactProblem problem) {
  switch (problem) {
    case contact::ContactProblem::signorini:
      return Effect::signorini;
    case contact::ContactProblem::friction:
      return Effect::friction;
    case contact::ContactProblem::friction_s:
      return Effect::friction_s;
  }
  return Effect::signorini;
}

std::optional<contact::ContactProblem> contact_problem_of(Effect effect) {
  for (auto problem :
       {contact::ContactProblem::signorini, contact::ContactProblem::friction, contact::ContactProblem::friction_s})
    if (effect_of(problem) == effect) return problem;
  return std::nullopt;
}

Effect effect_of(contact::ElasticContactProblem problem) {
  switch (problem) {
    case contact::ElasticContactProblem::frictionless:
      return Effect::frictionless;
    case contact::ElasticContactProblem::tresca:
      return Effect::tresca;
    case contact::ElasticContactProblem::coulomb:
      return Effect::coulomb;
    case contact::ElasticContactProblem::tied:
      return Effect::tied;
  }
  return Effect::frictionless;
}

namespace {
constexpr std::array kElasticProblems{contact::ElasticContactProblem::frictionless,
                                      contact::ElasticContactProblem::tresca, contact::ElasticContactProblem::coulomb,
                                      contact::ElasticContactProblem::tied};
}

std::optional<contact::ElasticContactProblem> elastic_problem_of(Effect effect) {
  for (auto problem : kElasticProblems)
    if (effect_of(problem) == effect) return problem;
  return std::nullopt;
}

std::optional<Effect> effect_named(const std::string& name) {
  for (Effect effect : all_effects())
    if (to_string(effect) == name) return effect;
  return std::nullopt;
}

std::string Scene::where(const std::string& key) const {
  const auto found = origins.find(key);
  return found == origins.end() ? file : found->second;
}

bool Scene::has_effect(Effect effect) const {
  return std::find(effects.begin(), effects.end(), effect) != effects.end();
}

bool Scene::wants_output(Output output) const {
  return std::find(outputs.begin(), outputs.end(), output) != outputs.end();
}

std::vector<contact::ContactProblem> Scene::contact_effects() const {
  std::vector<contact::ContactProblem> problems;
  for (auto problem :
       {contact::ContactProblem::signorini, contact::ContactProblem::friction, contact::ContactProblem::friction_s})
    if (has_effect(effect_of(problem))) problems.push_back(problem);
  return problems;
}

std::vector<contact::ElasticContactProblem> Scene::elastic_effects() const {
  std::vector<contact::ElasticContactProblem> problems;
  for (auto problem : kElasticProblems)
    if (has_effect(effect_of(problem))) problems.push_back(problem);
  return problems;
}

bool Scene::is_elastic() const {
  if (!elastic_effects().empty()) return true;
  return std::any_of(given.begin(), given.end(), [](const std::string& key) { return key.starts_with("material."); });
}

}  // namespace hpcontact::scene
