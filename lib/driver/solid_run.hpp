// A 3-D scene (a box of hexahedra, domain.n_z given) through `hpcontact solve`: the scalar contact
// problems (9), (13), (15) on a flat Γ_C with a grid T_{C,H}, with the outputs of the planar
// runs (summary.json, boundary_<problem>.csv, solution_<problem>.vtu).
#pragma once

#include "driver/run_result.hpp"
#include "driver/scene_run.hpp"
#include "scene/scene.hpp"

namespace hpcontact::driver {

/// Runs the scene's contact problems and writes into options.out:
///   summary.json            the RunResult (dimension 3, faces_on_contact, contact_area per problem)
///   boundary_<problem>.csv  x,y,z,w,u,obstacle|s,lambda on Γ_C at quadrature points of the overlaps of
///                           trace faces and T_{C,H} (Σ w·lambda = ∫ λ)
///   solution_<problem>.vtu  u on every cell's lattice of linear hexahedra
///   multiplier_<problem>.vtu λ (scalar) or the pressure (elastic) on T_{C,H}'s cells, each cut into
///                           linear quadrilaterals through its lattice
/// @throws InputError for a key, effect or run setting 3-D scenes do not take (named, with the
/// keys they take), and as the solver does.
RunResult run_solid_scene(const scene::Scene& scene, const SceneRunOptions& options);

}  // namespace hpcontact::driver
