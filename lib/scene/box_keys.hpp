// The [domain] keys of a box (a 3-D scene): n_z, z_min, z_max, the node lists x_nodes, y_nodes,
// z_nodes and grading_z.
#pragma once

#include <vector>

#include "scene/scene_keys.hpp"

namespace hpcontact::scene {

/// Appends domain.n_z, x_nodes, y_nodes, z_nodes, z_min, z_max, grading_z, in the order they are
/// read (n_z and z_nodes first: they make the scene 3-D).
void add_box_keys(std::vector<SceneKey>& keys);

}  // namespace hpcontact::scene
