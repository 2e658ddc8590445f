// Scenes derived from a base scene file, the mechanism by which study files extend a scene:
//   set  = a table laid out like a scene ({ domain = { n_x = 64 } }): keys replaced in every variant
//   vary = dotted scene keys with lists or integer ranges ({ "discretization.p" = "1..6" }), varied
//          jointly: variant i takes element i of every list (so n_x and n_y can move together).
// Each variant is parsed and checked as a whole scene, so every scene rule applies to it.
#pragma once

#include <string>
#include <vector>

#include "io/toml_reader.hpp"
#include "scene/scene.hpp"

namespace hpcontact::scene {

struct SceneVariant {
  Scene scene;
  std::string label;  ///< the varied values, e.g. "discretization.p=3 discretization.pC=2"
  /// Every key of the variant's scene as "section.key = value", sorted: what a stored result of it
  /// depends on (a sweep's identity).
  std::vector<std::string> keys;
};

/// `set` and `vary` are tables of the study file (empty tables: the base scene once); `where`
/// names them in messages. @throws InputError naming the study file, the key and, for errors
/// the scene checks find, the variant.
std::vector<SceneVariant> scene_variants(const std::string& base_path, const io::TomlTable& set,
                                         const io::TomlTable& vary, const std::string& where);

}  // namespace hpcontact::scene
