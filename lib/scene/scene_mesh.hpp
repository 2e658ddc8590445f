// A scene's meshes and degree distributions: T_h with its boundary parts, p_T per cell, p_C per
// segment, and T_{C,H} on Γ_C.
#pragma once

#include <array>
#include <vector>

#include "mesh/boundary_mesh.hpp"
#include "mesh/contact_boundary.hpp"
#include "mesh/mesh.hpp"
#include "scene/scene.hpp"

namespace hpcontact::scene {

/// T_h with boundary parts. @throws InputError if Γ_C is empty or Γ_C and Γ_D overlap.
mesh::Mesh build_scene_mesh(const Scene& scene);

/// The boundary edges where one displacement component alone vanishes (rollers of an elastic
/// scene: [boundary] fixed_x, fixed_y and their _groups), one mask per component, each of size
/// n_edges (empty when the scene gives none). @throws InputError naming the key if a roller edge
/// lies on Γ_C or Γ_D, or a key selects no edge.
std::array<std::vector<char>, 2> scene_fixed_components(const Scene& scene, const mesh::Mesh& mesh);

/// p_T per cell (the rule at Ψ_T(0,0), or p). @throws InputError for values that are not whole
/// numbers in [1, 20].
std::vector<int> scene_cell_degrees(const Scene& scene, const mesh::Mesh& mesh);
/// @throws InputError naming the scene's key unless its multiplier family fits T_{C,H} and the
/// degrees: p_C ≥ 1 for the standard and dual families, and no zone of one segment with p_C = 1
/// under the end modification.
void check_family_fits(const Scene& scene, const mesh::BoundaryMesh& boundary_mesh,
                       const std::vector<int>& segment_degrees);
/// The degree of the trace on each edge of `contact` (its cell's p_T): from the cells of
/// contact.mesh(), so that every rank of a distributed run has it.
std::vector<int> scene_trace_degrees(const Scene& scene, const mesh::ContactBoundary& contact);
/// p_C per segment (the rule at the segment midpoint, or pC), whole numbers in [0, 19].
std::vector<int> scene_segment_degrees(const Scene& scene, const mesh::ContactBoundary& contact,
                                       const mesh::BoundaryMesh& boundary_mesh);

/// T_{C,H} on Γ_C of the scene's mesh.
mesh::BoundaryMesh build_scene_boundary_mesh(const Scene& scene, const mesh::ContactBoundary& contact);

}  // namespace hpcontact::scene
