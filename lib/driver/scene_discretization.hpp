// A scene turned into a discretization: T_h, Γ_C, T_{C,H} and the degrees, and the contact
// problem set up on them. Shared by `solve` (every effect), the convergence effect and the
// work–precision study, so that all read scenes the same way.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "contact/contact_problem.hpp"
#include "infsup/infsup_operators.hpp"
#include "linalg/distribution.hpp"
#include "mesh/boundary_mesh.hpp"
#include "mesh/contact_boundary.hpp"
#include "mesh/mesh.hpp"
#include "operators/elastic_operators.hpp"
#include "operators/primal_operators.hpp"
#include "scene/scene.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::driver {

struct SceneDiscretization {
  /// T_h whole; null once released (release_whole_mesh): a distributed run's operators hold the
  /// rank's part, and nothing after them reads the whole mesh. Distributed, on the first rank only.
  std::unique_ptr<mesh::Mesh> mesh;
  /// Γ_C's cells of T_h as a part of it (mesh::Mesh::extract), where `contact` lives, so that Γ_C
  /// (arc length, points, normals) outlives the whole mesh.
  std::unique_ptr<mesh::Mesh> contact_cells;
  std::unique_ptr<mesh::ContactBoundary> contact;  ///< refers to `contact_cells`
  std::unique_ptr<mesh::BoundaryMesh> boundary_mesh;
  std::vector<std::array<bool, 2>> held_zone_ends;  ///< SceneMesh::held_zone_ends
  /// p_T per cell of T_h: where `mesh` is, emptied with it (release_whole_mesh), as long as it.
  std::vector<int> cell_degrees;
  int smallest_cell_degree = 0, largest_cell_degree = 0;  ///< of cell_degrees, on every rank
  std::vector<int> segment_degrees;
  std::unique_ptr<space::MultiplierSpace> multipliers;  ///< M^{p_C}(T_{C,H}), refers to boundary_mesh
  /// p_T of the cell of each edge of Γ_C (contact->edges()' order) where the cells' degrees are not
  /// the scene's (an adapted mesh); empty: the scene's (scene::scene_trace_degrees).
  std::vector<int> trace_degrees;
};

/// T_h with its degrees, and Γ_C's cells of T_h as a part of it (mesh::Mesh::extract).
struct SceneMesh {
  std::unique_ptr<mesh::Mesh> mesh;  ///< distributed: on the first rank only
  std::vector<int> cell_degrees;     ///< where `mesh` is
  std::unique_ptr<mesh::Mesh> contact_cells;
  /// Per zone of Γ_C (ContactBoundary's order), whether each end lies on Γ_D, where the traces
  /// vanish: what the local α predictor needs of the mesh beyond Γ_C's cells. On every rank.
  std::vector<std::array<bool, 2>> held_zone_ends;
};
/// The scene's T_h and degrees where they are built (serial: here; distributed: on the first rank
/// of `distribution` only, null and empty on the others), Γ_C's cells on every rank. Collective on
/// the ranks when distributed. @throws InputError as the scene's builders do, on every rank alike.
SceneMesh build_scene_mesh_on_first_rank(const scene::Scene& scene, const linalg::Distribution& distribution);

/// Builds the meshes and degrees. Held by pointer: its parts refer to each other. Distributed, T_h
/// and its degrees are built by the first rank of `distribution` (collective on its ranks), which
/// alone holds them: the operators and the extension norm's references are built from it and
/// send every rank its part (PrimalOperators). Γ_C's cells, T_{C,H} and the degree extremes are
/// on every rank. @throws InputError as the scene's builders do, on every rank alike.
std::unique_ptr<SceneDiscretization> discretize_scene(const scene::Scene& scene,
                                                      const linalg::Distribution& distribution = {});

/// The discretization of an adapted T_h (serial): `mesh` with `cell_degrees`, T_{C,H} its trace on
/// Γ_C (a segment per edge), p_C = max(p_T − `degree_drop`, 0) on each segment.
/// @throws InputError as the scene's builders do.
std::unique_ptr<SceneDiscretization> discretize_adapted(const scene::Scene& scene, mesh::Mesh mesh,
                                                        std::vector<int> cell_degrees, int degree_drop);

/// Frees the whole T_h of `discretization` and its cells' degrees when the operators built on it
/// live on a part of it (`operators_mesh`, the space's mesh: a distributed run), so that no rank
/// holds an array of the whole mesh's length for the rest of the run; nothing when they live on the whole mesh
/// (serial). Call it once nothing else of the run needs the whole mesh (the extension norm's references refine it).
void release_whole_mesh(SceneDiscretization& discretization, const mesh::Mesh& operators_mesh);
/// Whether a run of `scene` reads the whole mesh after its operators are built: the inf-sup effect
/// in the extension norm, whose references refine it.
bool reads_whole_mesh_after_operators(const scene::Scene& scene);

/// The scene's expression `text` (the value of `key`) as a function of the point, its messages
/// naming where the key came from; empty for empty text.
std::function<double(const mesh::Point&)> scene_function(const scene::Scene& scene, const std::string& key,
                                                         const std::string& text);
/// @throws InputError naming the scene's Γ_D key (boundary.dirichlet, or boundary.dirichlet_groups
/// if given) and its file unless `held` (some edge holds the body): `needed_by` needs it held.
void check_scene_has_dirichlet(const scene::Scene& scene, bool held, const std::string& needed_by);
/// The obstacle's gap on Γ_C: data.g, or the rigid obstacle of [obstacle] along `contact`'s
/// outward normal (`contact` must outlive the function).
std::function<double(const mesh::Point&)> scene_gap(const scene::Scene& scene, const mesh::ContactBoundary& contact);

/// The contact problem `problem` of the scene on `discretization` (data from the scene's
/// expressions, s ≥ 0 checked where evaluated). `primal` must belong to the discretization.
/// @throws InputError if the constraint points are fewer than p_C + 1 somewhere (naming where
/// solve.constraint_points came from).
contact::ContactSetup contact_setup_of(const scene::Scene& scene, const SceneDiscretization& discretization,
                                       contact::ContactProblem problem, const operators::PrimalOperators& primal);

/// solve.constraint_points (one value or one per zone) checked against every segment's p_C for
/// `problem`. @throws InputError naming the key, the zone and p_C + 1 where it is too small.
std::vector<int> checked_constraint_points(const scene::Scene& scene, const SceneDiscretization& discretization,
                                           contact::ContactProblem problem);

/// The weight of the norm in which multiplier errors of `problem` are measured, as a function of
/// the arc length on Γ_C: s for (13), where the data determine only sλ (λ itself not where s
/// vanishes, so ‖λ_H − λ‖ would measure an undetermined part); none (L²) for (9) and (15).
std::function<double(double)> multiplier_error_weight(const scene::Scene& scene,
                                                      const SceneDiscretization& discretization,
                                                      contact::ContactProblem problem);

/// The inf-sup pairing of the scene ([infsup] problem: (11), or (22) with the scene's s) in its
/// H^{-1/2} realization ([infsup] norm) on T_h (`mesh`, `cell_degrees`) and T_{C,H}
/// (`boundary_mesh`, `segment_degrees`); `primal` must belong to T_h. `mesh` may be null when it
/// was released (release_whole_mesh) and the norm is the interpolation norm, and on the ranks but
/// the first of a distributed run (which alone holds it).
infsup::InfSupSetup infsup_setup_of(const scene::Scene& scene, const mesh::Mesh* mesh, std::vector<int> cell_degrees,
                                    const mesh::BoundaryMesh& boundary_mesh, std::vector<int> segment_degrees,
                                    const operators::PrimalOperators& primal);
/// The same for an elastic scene: the normal multiplier (problem friction: the normal and the
/// tangential one) paired with [S^p(T_h)]² in [infsup] primal_norm; `elastic` built on T_h.
infsup::InfSupSetup infsup_setup_of(const scene::Scene& scene, const mesh::Mesh* mesh, std::vector<int> cell_degrees,
                                    const mesh::BoundaryMesh& boundary_mesh, std::vector<int> segment_degrees,
                                    const operators::ElasticOperators& elastic);

/// One contact problem of a scene, solved from scratch with its own operators.
struct SceneContactRun {
  std::unique_ptr<SceneDiscretization> discretization;
  contact::ContactSolution solution;
  double seconds = 0.0;  ///< wall time from the meshes to u: what this discretization costs
};

/// Discretizes the scene and solves `problem`; operators built are recorded in `log` if given.
SceneContactRun solve_scene_contact(const scene::Scene& scene, contact::ContactProblem problem,
                                    OperatorLog* log = nullptr);

}  // namespace hpcontact::driver
