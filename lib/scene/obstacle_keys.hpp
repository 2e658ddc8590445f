// The [obstacle] section: a rigid obstacle as geometry (contact/obstacle_gap.hpp), its keys and
// the rules between them.
#pragma once

#include <vector>

#include "scene/scene_keys.hpp"

namespace hpcontact::scene {

/// Appends obstacle.type, .point, .normal, .radius, .distance.
void add_obstacle_keys(std::vector<SceneKey>& keys);

/// The keys a type needs are given, the others absent, and data.g is not given beside them.
/// @throws InputError naming the file and the key.
void check_obstacle(const Scene& scene);

}  // namespace hpcontact::scene
