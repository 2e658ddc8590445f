// α of 3-D scenes: the scene's T_{C,H} on a discretized T_h, analysed and recorded.
#include "driver/solid_pairing.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "infsup/solid_infsup.hpp"

namespace hpcontact::driver {

void check_solid_pairing(const scene::Scene& scene) {
  if (!scene.contact_mesh_file.empty())
    throw_bad_input(scene.where("contact_mesh.mesh"), "contact_mesh.mesh", scene.contact_mesh_file,
                    "m or ratio for α in a 3-D scene: its interpolation norm is computed on a grid T_{C,H} (the "
                    "cosine moments of tensor multipliers); a triangle T_{C,H} solves contact problems only");
  if (scene.norm == infsup::GramNorm::extension)
    throw_bad_input(scene.where("infsup.norm"), "infsup.norm", "extension",
                    "interp in a 3-D scene: α takes the interpolation norm of the flat Γ_C");
  if (scene.problem == infsup::PairingProblem::friction && scene.friction_bound.empty() && !scene.is_elastic())
    throw_bad_input(scene.where("data.s"), "data.s", "(missing)",
                    "the friction pairing (22) of infsup.problem needs the friction bound s");
}

SolidPairingFacts solid_pairing_facts(const scene::Scene& scene, const SolidDiscretization& d) {
  SolidPairingFacts facts;
  facts.faces = static_cast<int>(d.surface->faces().size());
  facts.h_min = std::numeric_limits<double>::infinity();
  const mesh::SolidMesh& mesh = *d.mesh;
  for (const auto& face : d.surface->faces()) {
    const auto corners = mesh.local_face_vertices(face.local_face);
    const auto& cell = mesh.cell(face.cell);
    // (a square's corners are in tensor order: its edges join corners 0–1, 2–3, 0–2, 1–3)
    const std::vector<std::pair<int, int>> edges =
        mesh.is_tetrahedral() ? std::vector<std::pair<int, int>>{{0, 1}, {1, 2}, {0, 2}}
                              : std::vector<std::pair<int, int>>{{0, 1}, {2, 3}, {0, 2}, {1, 3}};
    for (const auto& [a, b] : edges)
      facts.h_min = std::min(facts.h_min, (mesh.vertex(cell[corners[a]]) - mesh.vertex(cell[corners[b]])).norm());
  }
  facts.multiplier_cells = solid_multiplier_mesh(scene, *d.surface)->n_cells();
  return facts;
}

SolidAlpha solid_scene_alpha(const scene::Scene& scene, const SolidDiscretization& d, infsup::EigenBackend backend,
                             const assembly::CondensedFactor* gram_factor, int level,
                             const linalg::Distribution& distribution) {
  check_solid_pairing(scene);
  const auto multiplier_mesh = solid_multiplier_mesh(scene, *d.surface);
  const space::SurfaceMultiplierSpace multipliers(*multiplier_mesh, scene.pc.value);
  infsup::SolidInfSupSetup setup;
  setup.space = d.space.get();
  setup.vector_space = d.vector_space.get();  // (elastic scenes: the elastic pairing)
  setup.multipliers = &multipliers;
  setup.problem = scene.problem;
  if (scene.problem == infsup::PairingProblem::friction && !d.vector_space)  // (s only where (22) reads it)
    setup.friction_bound = solid_scene_function(scene, scene.friction_bound, "data.s");
  setup.alpha_tolerance = scene.alpha_tolerance;
  setup.gram_factor = gram_factor;
  setup.path = scene.alpha_operator;
  setup.distribution = distribution;
  SolidAlpha out;
  out.result = infsup::analyse_solid_infsup(setup, backend);
  const SolidPairingFacts facts = solid_pairing_facts(scene, d);
  const infsup::PairingFacts pairing{
      .problem = scene.problem,
      .norm = infsup::GramNorm::interpolation,
      .family = scene.family,
      .p = scene.p.value,
      .pc = scene.pc.value,
      .level = level,
      .n = facts.faces,
      .m = multiplier_mesh->n_cells(),
      .h_min = facts.h_min,
      // (without a ratio: h/H from the mean cell areas, h² = area of a square, 2 × area of a triangle,
      // √(cells of T_{C,H} / trace faces) on uniform grids of squares; m / n would be its square)
      .ratio = scene.ratio.size() == 1 ? scene.ratio.front().value
                                       : std::sqrt((d.mesh->is_tetrahedral() ? 2.0 : 1.0) * multiplier_mesh->n_cells() /
                                                   ((multiplier_mesh->is_grid() ? 1.0 : 2.0) * facts.faces))};
  InfSupSummary& s = out.summary;
  s.record = infsup::make_infsup_record(pairing, out.result);
  s.record.alpha_predicted = std::numeric_limits<double>::quiet_NaN();
  s.reference_level = out.result.reference_level;
  s.lambda_unique = !out.result.singular;
  s.lambda_min = out.result.lambda_min;
  s.lambda_max = out.result.lambda_max;
  s.eigensolver = out.result.method;
  s.residual = out.result.residual;
  return out;
}

}  // namespace hpcontact::driver
