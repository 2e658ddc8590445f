// The scene reader's two halves on a parsed tree (overrides applied): a one-body scene, and a
// two-body scene whose bodies are each read as a one-body scene (two_body_scene.cpp); and where a
// dotted key lives in a tree, for overrides and study variants.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "scene/scene.hpp"

namespace toml {
inline namespace v3 {
class table;
}
}  // namespace toml

namespace hpcontact::scene {

/// A one-body scene from `tree`; `origins` names where overridden keys came from, `body` the body
/// of a two-body scene it describes (empty: a one-body scene), `is_master` whether that body is
/// its pair's master. @throws InputError.
Scene read_scene_tree(const std::shared_ptr<toml::table>& tree, const std::string& path,
                      std::map<std::string, std::string> origins, const std::string& body, bool is_master = false);

/// The place of a dotted key in a scene tree: "section.key" in the section's table, or
/// "body.<name>.section.key" in that [[body]]'s section (two-body scenes).
struct KeyPlace {
  toml::table* table = nullptr;  ///< the section's table, made if missing
  std::string section, key;      ///< "domain", "n_x"
};
/// @throws InputError naming `origin` and the key (`shown_name`, else `name`) if the name has
/// neither form, names no body of the scene, or a section is not a table.
KeyPlace place_of_key(toml::table& root, const std::string& name, const std::string& origin,
                      const std::string& shown_name = "");

/// A two-body scene ([[body]], [[pair]]): the slave's scene, holding the pair and the master's.
/// @throws InputError.
Scene read_two_body_tree(const std::shared_ptr<toml::table>& tree, const std::string& path,
                         const std::map<std::string, std::string>& origins);

}  // namespace hpcontact::scene
