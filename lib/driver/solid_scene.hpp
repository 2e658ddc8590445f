// A 3-D scene turned into its discretization: the checks of what 3-D scenes take, the box (graded
// as the rectangle is) with its boundary parts, rollers and materials, Γ_C, T_{C,H} and the spaces.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "assembly/material.hpp"
#include "assembly/solid_load.hpp"
#include "contact/solid_elastic_contact.hpp"
#include "driver/scene_run.hpp"
#include "mesh/contact_surface.hpp"
#include "scene/scene.hpp"
#include "space/solid_space.hpp"
#include "space/solid_vector_space.hpp"
#include "space/surface_multiplier_space.hpp"

namespace hpcontact::driver {

/// @throws InputError for a key or an effect that 3-D scenes do not take, naming it and what
/// they take; `needs_effects`: a scene without run.effects is refused too (a solve; α does not
/// need them).
void check_solid_scene(const scene::Scene& scene, bool needs_effects = true);

/// Held by pointer: its parts refer to each other.
struct SolidDiscretization {
  std::unique_ptr<mesh::SolidMesh> mesh;  ///< faces labelled "contact", "dirichlet"
  std::unique_ptr<space::SolidH1Space> space;
  std::unique_ptr<space::SolidVectorSpace> vector_space;  ///< elastic scenes
  std::vector<assembly::Material> materials;              ///< elastic scenes: per cell
  std::unique_ptr<mesh::FlatContactSurface> surface;
  std::unique_ptr<mesh::SurfaceMultiplierMesh> multiplier_mesh;
  std::unique_ptr<space::SurfaceMultiplierSpace> multipliers;
};

/// @throws InputError as the builders do, naming the scene's keys. Without `multipliers`, T_{C,H}
/// and its space are not built (a sweep's points build their own on Γ_C).
std::unique_ptr<SolidDiscretization> discretize_solid_scene(const scene::Scene& scene, bool multipliers = true);

/// The scene's expression `text` (key `key`, in x, y, z) as a function; empty for an empty text.
assembly::SolidFunction solid_scene_function(const scene::Scene& scene, const std::string& text, const char* key);

/// The elastic contact problem of `scene` on `d` for `effect` (frictionless, Tresca or Coulomb):
/// materials, body force, gap, Tresca's threshold or Coulomb's coefficient, the scene's path of S.
/// @throws InputError naming data.g or data.s where the effect needs them and they are missing.
contact::SolidElasticSetup solid_elastic_setup(const scene::Scene& scene, const SolidDiscretization& d,
                                               scene::Effect effect);

/// T_{C,H} of the scene on Γ_C: contact_mesh.m (one or two counts), contact_mesh.ratio, or the
/// triangles of contact_mesh.mesh.
/// @throws InputError naming the key.
std::unique_ptr<mesh::SurfaceMultiplierMesh> solid_multiplier_mesh(const scene::Scene& scene,
                                                                   const mesh::FlatContactSurface& surface);

}  // namespace hpcontact::driver
