// Typed builders of scene keys: each returns the SceneKey whose reader checks the range that the
// generated reference shows (number, integer, expression, names, numbers, choice, enum list).
#pragma once

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "scene/scene_keys.hpp"

namespace hpcontact::scene {

SceneKey number_key(const char* section, const char* name, double low, double high, double fallback,
                    double Scene::*member, const char* doc);

SceneKey any_number_key(const char* section, const char* name, double fallback, double mesh::Rectangle::*member,
                        const char* doc);

/// An integer; `fallback` empty: no default (the member keeps its value; rules elsewhere say when
/// the key is required).
SceneKey integer_key(const char* section, const char* name, long long low, long long high,
                     std::optional<long long> fallback, int Scene::*member, const char* doc);

/// An expression in x, y (x, y, z in a 3-D scene), parsed now, so that a typo is reported before any work.
SceneKey expression_key(const char* section, const char* name, const char* fallback, std::string Scene::*member,
                        const char* doc);

SceneKey names_key(const char* section, const char* name, std::vector<std::string> Scene::*member, const char* doc);

/// Finite numbers (numbers or their text), each checked by `valid`.
SceneKey numbers_key(const char* section, const char* name, const char* allowed, std::vector<double> Scene::*member,
                     const char* doc, std::function<bool(double)> valid = {}, const char* group = "");

template <typename Enum>
std::vector<std::string> choice_names(const std::vector<std::pair<std::string, Enum>>& choices) {
  std::vector<std::string> names;
  for (const auto& [text, value] : choices) names.push_back(text);
  return names;
}

template <typename Enum>
SceneKey choice_key(const char* section, const char* name, std::vector<std::pair<std::string, Enum>> choices,
                    Enum fallback, Enum Scene::*member, const char* doc) {
  std::string fallback_text;
  for (const auto& [text, value] : choices)
    if (value == fallback && fallback_text.empty()) fallback_text = text;
  return {section,
          name,
          "string",
          fmt::format("\"{}\"", fallback_text),
          fmt::format("{}", fmt::join(choice_names(choices), ", ")),
          doc,
          "",
          [=, names = choice_names(choices)](const io::TomlTable& table, Scene& scene) {
            const std::string chosen = table.choice(name, names, fallback_text);
            for (const auto& [text, value] : choices)
              if (text == chosen) scene.*member = value;
          }};
}

/// A list of names from a fixed set (effects, outputs), each at most once.
template <typename Enum>
SceneKey enum_list_key(const char* section, const char* name, const std::vector<Enum>& all,
                       std::vector<Enum> Scene::*member, const char* default_text, const char* doc) {
  std::vector<std::string> names;
  for (Enum value : all) names.push_back(to_string(value));
  const std::string allowed = fmt::format("any of {}", fmt::join(names, ", "));
  return {
      section, name, "list of strings", default_text, allowed, doc, "", [=](const io::TomlTable& table, Scene& scene) {
        if (!table.has(name)) return;
        std::vector<Enum> values;
        for (const auto& text : table.string_list(name)) {
          const auto found = std::find(names.begin(), names.end(), text);
          if (found == names.end()) throw_bad_input(table.origin(name), table.qualified(name), text, allowed);
          const Enum value = all[static_cast<std::size_t>(found - names.begin())];
          if (std::find(values.begin(), values.end(), value) != values.end())
            throw_bad_input(table.origin(name), table.qualified(name), text, "each at most once");
          values.push_back(value);
        }
        scene.*member = values;
      }};
}

}  // namespace hpcontact::scene
