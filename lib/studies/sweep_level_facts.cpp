// sweep_level_facts: each level's meshes built and measured on the first rank, the facts sent to
// the others as bytes.
#include "studies/sweep_level_facts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "core/byte_buffer.hpp"
#include "core/error.hpp"
#include "driver/solid_pairing.hpp"
#include "infsup/infsup_record.hpp"
#include "mesh/boundary_mesh.hpp"
#include "mesh/contact_boundary.hpp"
#include "scene/scene_mesh.hpp"
#include "studies/sweep_plan.hpp"

namespace hpcontact::studies {
namespace {

using LevelFacts = StabilitySweep::LevelFacts;

// Every family and p_C of the sweep on T_{C,H} (a point the sweep lists must not stop it half-way).
void check_families(const StabilitySweep& sweep, const scene::Scene& at_ratio, const mesh::ContactBoundary& contact,
                    const mesh::BoundaryMesh& boundary) {
  std::vector<std::optional<int>> degrees(sweep.multiplier_degrees.begin(), sweep.multiplier_degrees.end());
  if (degrees.empty()) degrees.emplace_back();  // the scene's own
  for (const auto& family : sweep.families)
    for (const auto pc : degrees) {
      const auto at_point = point_scene(at_ratio, {.pc = pc, .family = family});
      const auto segment_degrees = scene::scene_segment_degrees(at_point, contact, boundary);
      // (list_sweep_points skips the points whose largest p_C is 0 for these families)
      if (*std::max_element(segment_degrees.begin(), segment_degrees.end()) < 1) continue;
      try {
        scene::check_family_fits(at_point, boundary, segment_degrees);
      } catch (const InputError& error) {
        throw InputError(fmt::format("with sweep.family = {}{}: {}", space::to_string(family),
                                     pc ? fmt::format(", sweep.pC = {}", *pc) : "", error.what()));
      }
    }
}

// A 3-D level: its box and Γ_C, T_{C,H} at every ratio; every norm, problem and family the sweep lists
// checked on it (α of 3-D scenes takes the interpolation norm and the discontinuous family).
LevelFacts facts_of_solid_level(const StabilitySweep& sweep, const scene::Scene& scene,
                                const std::vector<std::optional<scene::Ratio>>& ratios) {
  driver::check_solid_scene(scene, false);
  for (const auto norm : sweep.norms)
    for (const auto problem : sweep.problems)
      driver::check_solid_pairing(point_scene(scene, {.problem = problem, .norm = norm}));
  for (const auto& family : sweep.families)
    if (family.kind != space::MultiplierFamilyKind::discontinuous)
      throw_bad_input(sweep.file, "sweep.family", space::to_string(family),
                      "discontinuous in a sweep of a 3-D scene: its multipliers are discontinuous Q_pC");
  const auto d = driver::discretize_solid_scene(scene, false);  // (T_{C,H} per ratio below)
  LevelFacts facts;
  facts.cells = d->mesh->n_cells();
  facts.scene_p = scene.p.value;
  for (const auto& ratio : ratios) {
    const auto at_point = point_scene(scene, {.ratio = ratio});
    try {
      const driver::SolidPairingFacts pairing = driver::solid_pairing_facts(at_point, *d);
      facts.contact_edges = pairing.faces;
      facts.contact_h_min = pairing.h_min;
      facts.segments.push_back(pairing.multiplier_cells);
    } catch (const InputError& error) {
      if (!ratio) throw;
      throw InputError(fmt::format("with sweep.ratio = {}: {}", ratio->text, error.what()));
    }
    facts.scene_pc.push_back(scene.pc.value);
  }
  return facts;
}

LevelFacts facts_of_level(const StabilitySweep& sweep, const scene::Scene& scene,
                          const std::vector<std::optional<scene::Ratio>>& ratios, bool friction) {
  if (friction && scene.friction_bound.empty() && !scene.is_elastic())
    throw_bad_input(scene.file, "data.s", "(missing)",
                    "the friction pairing (22) of sweep.problem needs the friction bound s");
  if (scene.dimension() == 3) return facts_of_solid_level(sweep, scene, ratios);
  const auto mesh = scene::build_scene_mesh(scene);
  const mesh::ContactBoundary contact(mesh);
  LevelFacts facts;
  facts.cells = mesh.n_cells();
  facts.contact_edges = static_cast<int>(contact.edges().size());
  facts.contact_h_min = infsup::shortest_contact_edge(contact);
  const auto cell_degrees = scene::scene_cell_degrees(scene, mesh);
  facts.scene_p = *std::min_element(cell_degrees.begin(), cell_degrees.end());
  for (const auto& ratio : ratios) {
    const auto at_point = point_scene(scene, {.ratio = ratio});
    std::optional<mesh::BoundaryMesh> built;
    try {
      built.emplace(scene::build_scene_boundary_mesh(at_point, contact));
    } catch (const InputError& error) {
      if (!ratio) throw;
      throw InputError(fmt::format("with sweep.ratio = {}: {}", ratio->text, error.what()));
    }
    const auto segment_degrees = scene::scene_segment_degrees(at_point, contact, *built);
    check_families(sweep, at_point, contact, *built);
    facts.segments.push_back(built->n_segments());
    facts.scene_pc.push_back(*std::max_element(segment_degrees.begin(), segment_degrees.end()));
  }
  return facts;
}

std::vector<char> facts_as_bytes(const std::vector<LevelFacts>& levels) {
  ByteWriter out;
  out.put(static_cast<std::uint64_t>(levels.size()));
  for (const auto& facts : levels) {
    out.put(facts.cells), out.put(facts.contact_edges), out.put(facts.contact_h_min), out.put(facts.scene_p);
    out.put(facts.segments), out.put(facts.scene_pc);
  }
  return out.take();
}

std::vector<LevelFacts> facts_from_bytes(const std::vector<char>& bytes) {
  ByteReader in(bytes);
  std::vector<LevelFacts> levels(in.get_count(1));
  for (auto& facts : levels) {
    facts.cells = in.get<int>(), facts.contact_edges = in.get<int>();
    facts.contact_h_min = in.get<double>(), facts.scene_p = in.get<int>();
    facts.segments = in.get_vector<int>(), facts.scene_pc = in.get_vector<int>();
  }
  HPC_VERIFY(in.at_end(), "bytes of a sweep's level facts left over");
  return levels;
}

}  // namespace

std::vector<LevelFacts> sweep_level_facts(const StabilitySweep& sweep, const std::string& base, MPI_Comm ranks) {
  const bool friction =
      std::find(sweep.problems.begin(), sweep.problems.end(), infsup::PairingProblem::friction) != sweep.problems.end();
  const auto ratios = ratio_choices(sweep);
  std::optional<std::vector<LevelFacts>> levels;  // the first rank's own
  const auto bytes = bytes_made_by_first_rank(
      [&] {
        levels.emplace();
        for (std::size_t level = 0; level < sweep.levels.size(); ++level) try {
            levels->push_back(facts_of_level(sweep, sweep.levels[level].scene, ratios, friction));
          } catch (const InputError& error) {
            throw InputError(
                fmt::format("{}: {} of the scene {}: {}", sweep.file, level_name(sweep, level), base, error.what()));
          }
        return facts_as_bytes(*levels);
      },
      ranks);
  return levels ? std::move(*levels) : facts_from_bytes(bytes);
}

}  // namespace hpcontact::studies
