// The paper's §7 scene for tests that need it as a file (the command line, a sweep's base scene)
// or with a key that scene::SceneOverride cannot carry (a list of pairs): scene::paper_scene_text()
// with single keys replaced, added or removed. Tests that read a scene in-process pass the rest as
// scene::SceneOverride to scene::parse_scene.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "scene/scene_reader.hpp"

namespace hpcontact::testing {

/// A dotted scene key ("domain.n_x") and its TOML value as written in a file ("8", "\"1/2\"",
/// "[[1, 0]]"); no value removes the key.
using SceneKeyText = std::pair<std::string, std::optional<std::string>>;

/// scene::paper_scene_text() with `keys` applied in order (a key of a section the scene lacks adds
/// the section). Keys of an exclusive group (contact_mesh.m, .ratio) are not removed for each
/// other: remove the scene's own explicitly.
inline std::string paper_scene_with(const std::vector<SceneKeyText>& keys) {
  // The scene as its sections' "key = value" lines, in order.
  std::vector<std::pair<std::string, std::vector<std::pair<std::string, std::string>>>> sections;
  const std::string text = scene::paper_scene_text();
  for (std::size_t begin = 0, end; begin < text.size(); begin = end + 1) {
    end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(begin, end - begin);
    if (line.empty()) continue;
    if (line.front() == '[') {
      sections.push_back({line.substr(1, line.size() - 2), {}});
      continue;
    }
    const auto equals = line.find(" = ");
    if (equals == std::string::npos || sections.empty())
      throw std::logic_error("paper_scene_with: unexpected line '" + line + "'");
    sections.back().second.emplace_back(line.substr(0, equals), line.substr(equals + 3));
  }
  for (const auto& [dotted, value] : keys) {
    const auto dot = dotted.find('.');
    if (dot == std::string::npos) throw std::logic_error("paper_scene_with: '" + dotted + "' is not section.key");
    const std::string section = dotted.substr(0, dot), key = dotted.substr(dot + 1);
    auto own = sections.begin();
    while (own != sections.end() && own->first != section) ++own;
    if (own == sections.end()) own = sections.insert(own, {section, {}});
    auto& lines = own->second;
    auto at = lines.begin();
    while (at != lines.end() && at->first != key) ++at;
    if (!value) {
      if (at == lines.end()) throw std::logic_error("paper_scene_with: no key '" + dotted + "' to remove");
      lines.erase(at);
    } else if (at == lines.end()) {
      lines.emplace_back(key, *value);
    } else {
      at->second = *value;
    }
  }
  std::string out;
  for (const auto& [section, lines] : sections) {
    out += "[" + section + "]\n";
    for (const auto& [key, value] : lines) out += key + " = " + value + "\n";
  }
  return out;
}

}  // namespace hpcontact::testing
