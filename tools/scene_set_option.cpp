// `--set KEY=VALUE`: the option and the reading of its value as a scene override.
#include "scene_set_option.hpp"

#include <toml++/toml.h>

#include "core/error.hpp"

namespace hpcontact::tools {
namespace {

/// The numbers of a TOML array, if every element is one.
std::optional<std::vector<double>> number_list(const toml::array& array) {
  std::vector<double> numbers;
  for (const auto& element : array)
    if (auto x = element.value<double>()) numbers.push_back(*x);
  if (numbers.size() != array.size()) return std::nullopt;
  return numbers;
}

/// The elements of a TOML array as one of the override's list types, if they are all of one kind
/// (numbers, integers, texts, or lists of numbers).
std::optional<scene::SceneOverride::Value> list_value(const toml::array& array) {
  std::vector<long long> integers;
  std::vector<std::string> texts;
  std::vector<std::vector<double>> number_lists;
  for (const auto& element : array) {
    if (auto i = element.value_exact<std::int64_t>()) integers.push_back(*i);
    if (auto s = element.value_exact<std::string>()) texts.push_back(*s);
    if (const auto* inner = element.as_array())
      if (auto numbers = number_list(*inner)) number_lists.push_back(std::move(*numbers));
  }
  if (integers.size() == array.size()) return integers;
  if (auto numbers = number_list(array)) return *numbers;
  if (texts.size() == array.size()) return texts;
  if (number_lists.size() == array.size()) return number_lists;
  return std::nullopt;
}

/// VALUE as TOML ("v = VALUE"); text that is no TOML value stays text, so that
/// `--set boundary.contact=y<1e-12` needs no quotes.
scene::SceneOverride::Value value_of(const std::string& text) {
  toml::table parsed;
  try {
    parsed = toml::parse("v = " + text);
  } catch (const toml::parse_error&) {
    return text;
  }
  const toml::node& node = *parsed.get("v");
  if (auto b = node.value_exact<bool>()) return *b;
  if (auto i = node.value_exact<std::int64_t>()) return static_cast<long long>(*i);
  if (auto x = node.value_exact<double>()) return *x;
  if (auto s = node.value_exact<std::string>()) return *s;
  if (const auto* array = node.as_array())
    if (auto list = list_value(*array)) return *list;
  return text;
}

}  // namespace

void add_set_option(CLI::App& command, std::vector<std::string>& texts) {
  command
      .add_option("--set", texts,
                  "Override any scene key, KEY=VALUE with KEY as in docs/scene_keys.md (domain.n_x=128, "
                  "material.E=210e9, contact_mesh.ratio=\"1/2\"); repeatable, checked like the file's value")
      ->type_name("KEY=VALUE")
      ->take_all()
      ->allow_extra_args(false);
}

std::vector<scene::SceneOverride> set_overrides(const std::vector<std::string>& texts, const std::string& where) {
  std::vector<scene::SceneOverride> overrides;
  for (const auto& text : texts) {
    const auto equals = text.find('=');
    if (equals == std::string::npos || equals == 0)
      throw_bad_input(where + " --set", "--set", text, "KEY=VALUE with a scene key, e.g. domain.n_x=128");
    const std::string key = text.substr(0, equals);
    overrides.push_back({key, value_of(text.substr(equals + 1)), where + " --set " + key});
  }
  return overrides;
}

}  // namespace hpcontact::tools
