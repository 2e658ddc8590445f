// Scene variants: base scene + replaced keys + jointly varied keys, re-parsed as scenes.
#include "scene/scene_variants.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <sstream>

#include "core/error.hpp"
#include "scene/scene_reader.hpp"
#include "scene/scene_tree.hpp"

namespace hpcontact::scene {
namespace {

/// Copies `from` into `into`, descending into tables both have.
void merge_into(toml::table& into, const toml::table& from) {
  for (const auto& [key, node] : from) {
    auto* existing = into.get_as<toml::table>(key);
    if (existing && node.is_table())
      merge_into(*existing, *node.as_table());
    else
      into.insert_or_assign(key, node);
  }
}

/// Values of one varied key: a list of values, or an integer range "a..b".
toml::array variant_values(const toml::node& node, const std::string& where, const std::string& key) {
  toml::array values;
  if (const auto* list = node.as_array()) {
    values = *list;
  } else if (const auto* text = node.as_string()) {
    long long first = 0, last = 0;
    char tail = 0;
    if (std::sscanf(text->get().c_str(), "%lld..%lld%c", &first, &last, &tail) != 2 || last < first ||
        last - first > 1000)
      throw_bad_input(where, key, text->get(),
                      "a list of values, or an integer range \"a..b\" with a <= b (at most 1001 values)");
    for (long long v = first; v <= last; ++v) values.push_back(static_cast<int64_t>(v));
  } else {
    throw_bad_input(where, key, "(not a list)", "a list of values, or an integer range \"a..b\"");
  }
  if (values.empty()) throw_bad_input(where, key, "[]", "at least one value");
  return values;
}

std::string value_text(const toml::node& node) {
  std::ostringstream out;
  node.visit([&](const auto& value) { out << value; });
  return out.str();
}

// `table`'s keys as "prefix.key = value" lines, descending into tables.
void flatten(const toml::table& table, const std::string& prefix, std::vector<std::string>& lines) {
  for (const auto& [key, node] : table) {
    const std::string name = prefix + std::string(key.str());
    if (const auto* inner = node.as_table())
      flatten(*inner, name + ".", lines);
    else
      lines.push_back(name + " = " + value_text(node));
  }
}

}  // namespace

std::vector<SceneVariant> scene_variants(const std::string& base_path, const io::TomlTable& set,
                                         const io::TomlTable& vary, const std::string& where) {
  toml::table base;
  try {
    base = toml::parse(io::read_text_file(base_path), base_path);
  } catch (const toml::parse_error&) {
    read_scene(base_path);  // reports the error with line and column
  }
  merge_into(base, set.raw());
  // Varied keys and their values, all lists of one length.
  std::vector<std::pair<std::string, toml::array>> varied;
  for (const auto& [key, node] : vary.raw()) {
    const std::string name(key.str());
    varied.emplace_back(name, variant_values(node, where, vary.qualified(name)));
    if (varied.back().second.size() != varied.front().second.size())
      throw_bad_input(where, vary.qualified(name), fmt::format("{} values", varied.back().second.size()),
                      fmt::format("as many values as '{}' ({}): varied keys move together", varied.front().first,
                                  varied.front().second.size()));
  }
  const std::size_t count = varied.empty() ? 1 : varied.front().second.size();
  std::vector<SceneVariant> variants;
  for (std::size_t i = 0; i < count; ++i) {
    toml::table scene = base;
    std::string label;
    for (const auto& [name, values] : varied) {
      // "section.key" or "body.<name>.section.key", the section made if the base scene has none.
      const KeyPlace place = place_of_key(scene, name, where, vary.qualified(name));
      place.table->insert_or_assign(place.key, values[i]);
      label += fmt::format("{}{}={}", label.empty() ? "" : " ", name, value_text(values[i]));
    }
    std::ostringstream text;
    text << scene;
    try {
      std::vector<std::string> keys;
      flatten(scene, "", keys);
      std::sort(keys.begin(), keys.end());
      variants.push_back({parse_scene(text.str(), base_path), label, std::move(keys)});
    } catch (const InputError& error) {
      throw InputError(fmt::format("{}: variant {} ({}) of the scene {}: {}", where, i + 1,
                                   label.empty() ? "no varied keys" : label, base_path, error.what()));
    }
  }
  return variants;
}

}  // namespace hpcontact::scene
