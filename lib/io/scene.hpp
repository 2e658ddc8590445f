// Scene files (TOML): the geometry, boundary parts, contact mesh, discretization and data of one
// run, and which effects (contact problems, inf-sup constant, convergence under refinement) and
// outputs the run produces. Every key is documented in studies/README.md.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "mesh/boundary_mesh.hpp"
#include "mesh/contact_boundary.hpp"
#include "mesh/quad_mesh.hpp"
#include "mesh/rectangle_mesh.hpp"

namespace hpcontact::io {

struct Scene {
  std::string file;
  // [domain]: a rectangle with n_x × n_y cells, or a Gmsh file.
  std::optional<mesh::Rectangle> rectangle;
  int n_x = 0, n_y = 0;
  std::string mesh_file;
  double perturb = 0.0;
  std::uint32_t seed = 1;
  /// Rectangle only: `grading_layers` geometric layers (sizes shrinking by `domain_grading`)
  /// towards each of these x (y) coordinates; see mesh::graded_nodes.
  std::vector<double> grading_x, grading_y;
  /// Points (vertices after snapping) whose surrounding cells get `grading_layers` local
  /// geometric layers; see mesh::grade_towards_vertices. Rectangle or Gmsh mesh.
  std::vector<mesh::Point> grading_points;
  double domain_grading = 0.5;
  int grading_layers = 0;
  /// Uniform refinements of the mesh (each cell into four) after building and perturbing it;
  /// T_{C,H} follows (m and breakpoint segments split alike, ratio kept).
  int refinements = 0;
  // [boundary]: predicates in x, y on edge midpoints (non-zero = inside), or Gmsh group names.
  std::string contact_predicate, dirichlet_predicate;
  std::vector<std::string> contact_groups, dirichlet_groups;
  // [contact_mesh]: exactly one of m, ratio (= h/H, m = n_C · ratio), breakpoints.
  int m = 0;
  std::string ratio;
  std::vector<double> breakpoints;
  double grading = 1.0;
  // [discretization]: an integer, or a rule: an expression in x, y evaluated at cell centres
  // (p) or segment midpoints (pC), which must give whole numbers in range.
  int p = 1, pc = 0;
  std::string p_rule, pc_rule;
  // [data]
  std::string friction_bound;  ///< s, expression in x, y (may be empty)
  std::string load = "-1";     ///< f
  std::string obstacle;        ///< g (Signorini)
  // [infsup]
  std::string norm = "interp", problem = "signorini";
  double alpha_tolerance = 1e-4;  ///< relative error of α (alpha_tol)
  // [solve]
  std::optional<int> constraint_points;  ///< |𝒞| per segment (Remark 3); empty: p_C + 1
  /// Grade the mesh towards the free boundary of the scene's contact problems before running its
  /// effects (studies::fit_free_boundary; rectangle domains).
  bool fit_free_boundary = false;
  // [run]: what the run computes and writes (see `effect_names`, `output_names`).
  /// Empty when the scene has no [run] table: `solve` then needs --effects; `infsup --scene` and
  /// sweeps over the scene do not read it.
  std::vector<std::string> effects;
  std::vector<std::string> outputs = {"summary", "boundary", "vtu", "mode"};
  bool outputs_given = false;  ///< listed outputs must apply; the default writes those that do
  // [convergence]: levels of uniform refinement beyond the scene's own mesh.
  int convergence_refinements = 3;

  /// p and p_C as written: the integer, or the degree rule's text.
  std::string p_label() const { return p_rule.empty() ? std::to_string(p) : p_rule; }
  std::string pc_label() const { return pc_rule.empty() ? std::to_string(pc) : pc_rule; }

  bool has_effect(const std::string& effect) const;
  /// The contact problems among the effects, in the order signorini, friction, friction_s.
  std::vector<std::string> contact_effects() const;
  bool wants_output(const std::string& output) const;
};

/// Allowed values of [run] effects: signorini, friction, friction_s, infsup, convergence.
const std::vector<std::string>& effect_names();
/// Allowed values of [run] outputs: summary, boundary, vtu, mode.
const std::vector<std::string>& output_names();

/// Checks the effects against the data (g for signorini, s for friction problems, a contact
/// problem for convergence) and the outputs against the effects; `where` names the source of the
/// effects in messages. @throws InputError.
void check_effects(const Scene& scene, const std::string& where);

/// @throws InputError naming file, key, value and the allowed range.
Scene read_scene(const std::string& path);

/// The same from the text of a scene; `path` names it in messages and anchors relative mesh paths.
Scene parse_scene(const std::string& text, const std::string& path);

/// T_h with boundary parts. @throws InputError if Γ_C is empty or Γ_C and Γ_D overlap.
mesh::QuadMesh build_scene_mesh(const Scene& scene);

/// p_T per cell (the rule at Ψ_T(0,0), or p). @throws InputError for values that are not whole
/// numbers in [1, 20].
std::vector<int> scene_cell_degrees(const Scene& scene, const mesh::QuadMesh& mesh);
/// p_C per segment (the rule at the segment midpoint, or pC), whole numbers in [0, 19].
std::vector<int> scene_segment_degrees(const Scene& scene, const mesh::ContactBoundary& contact,
                                       const mesh::BoundaryMesh& boundary_mesh);

/// T_{C,H} on Γ_C of the scene's mesh.
mesh::BoundaryMesh build_scene_boundary_mesh(const Scene& scene, const mesh::ContactBoundary& contact);

}  // namespace hpcontact::io
