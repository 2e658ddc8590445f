// The [adapt] keys (hp-adaptivity of T_h and T_{C,H}, driver/adaptive_run.hpp) and the rules a
// scene must follow to adapt.
#pragma once

#include <vector>

#include "scene/scene_keys.hpp"

namespace hpcontact::scene {

/// Appends adapt.target, max_unknowns, max_steps, fraction, smoothness, max_degree,
/// reference_energy.
void add_adapt_keys(std::vector<SceneKey>& keys);

/// @throws InputError naming the key unless an adaptive scene (adapt.target given) is one the
/// adaptivity serves: a planar scalar scene with one contact problem, T_{C,H}
/// the trace of T_h (contact_mesh.ratio = 1), p and p_C numbers with p > p_C, no fit of the free
/// boundary and no convergence effect.
void check_adapt(const Scene& scene);

}  // namespace hpcontact::scene
