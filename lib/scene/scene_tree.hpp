// The scene reader's two halves on a parsed tree (overrides applied): a one-body scene, and a
// two-body scene whose bodies are each read as a one-body scene (two_body_scene.cpp).
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
/// of a two-body scene it describes (empty: a one-body scene). @throws InputError.
Scene read_scene_tree(const std::shared_ptr<toml::table>& tree, const std::string& path,
                      std::map<std::string, std::string> origins, const std::string& body);

/// A two-body scene ([[body]], [[pair]]): the slave's scene, holding the pair and the master's.
/// @throws InputError.
Scene read_two_body_tree(const std::shared_ptr<toml::table>& tree, const std::string& path,
                         const std::map<std::string, std::string>& origins);

}  // namespace hpcontact::scene
