// A scene: the geometry, boundary parts, contact mesh, discretization and data of one run, and
// which effects (contact problems, inf-sup constant, convergence under refinement) and outputs
// the run produces. Every value is typed and checked when the scene is read (scene_reader.hpp);
// the keys, their ranges and defaults are declared once in scene_keys.cpp, which also generates
// their reference (docs/scene_keys.md).
#pragma once

#include <fmt/format.h>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "assembly/elastic_system.hpp"
#include "contact/contact_problem.hpp"
#include "contact/elastic_contact.hpp"
#include "contact/obstacle_gap.hpp"
#include "contact/trace_operator.hpp"
#include "core/error.hpp"
#include "infsup/infsup_operators.hpp"
#include "mesh/mesh.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "scene/ratio.hpp"
#include "space/multiplier_family.hpp"

namespace hpcontact::scene {

/// The scalar model's contact problems (9), (13), (15), the inf-sup constant, convergence under
/// refinement, and the contact problems of an elastic body (frictionless, Tresca, Coulomb).
enum class Effect { signorini, friction, friction_s, infsup, convergence, frictionless, tresca, coulomb, tied };
enum class Output { summary, boundary, vtu, mode };

/// The names used in scene files and outputs ("friction_s", "vtu").
std::string to_string(Effect effect);
std::string to_string(Output output);
const std::vector<Effect>& all_effects();
const std::vector<Output>& all_outputs();

/// A degree p (p_C) given as one integer or as a rule: an expression in x, y evaluated at cell
/// centres (segment midpoints) that must give whole numbers in range.
struct Degree {
  int value = 1;     ///< when `rule` is empty
  std::string rule;  ///< the expression's text
  /// As written: the integer, or the rule's text.
  std::string label() const { return rule.empty() ? std::to_string(value) : rule; }
};

struct ContactPair;

/// [adapt]: hp-adaptivity of T_h and T_{C,H} from the residual estimator (driver/adaptive_run.hpp).
struct AdaptSettings {
  double target = 0.0;  ///< stop at an estimated error in the energy η²/2 ≤ target; 0: not adaptive
  long long max_unknowns = 200000;
  int max_steps = 60;
  double fraction = 0.5;    ///< Dörfler's share of η² that the marked leaves hold
  double smoothness = 0.5;  ///< Legendre decay ratio up to which a marked cell gets p + 1 rather than split
  int max_degree = 14;
  std::optional<double> reference_energy;  ///< the exact energy, for the error and effectivity columns
};

struct Scene {
  std::string file;  ///< the scene file (or the name of a built-in scene)
  // Two-body scenes ([[body]] and [[pair]] tables): each body is read as a scene of its own; the
  // slave's carries the pair, and with it the master's scene.
  std::string body;                         ///< the body's name; empty for a one-body scene
  std::shared_ptr<const ContactPair> pair;  ///< on the slave's scene of a two-body scene
  /// The master of a pair: its scene describes a body only (T_{C,H}, p_C and the multiplier's
  /// data belong to the slave).
  bool is_master = false;
  // [domain]: a rectangle with n_x × n_y cells, or a Gmsh file.
  std::string mesh_file;            ///< empty for a rectangle; else absolute or relative to the working folder
  std::optional<double> mesh_size;  ///< a .geo mesh_file: Gmsh's maximal element size
  int mesh_dimension = 2;           ///< of mesh_file's model: 3 for hexahedra (a 3-D scene)
  /// Whether cells follow the mesh file's curves, or only its vertices (the polygonal domain).
  enum class Geometry { curved, polygonal } geometry = Geometry::curved;
  /// The cells of the rectangle, or of a .geo mesh_file (a .msh file holds its own).
  mesh::GeneratedCells cells = mesh::GeneratedCells::quadrilaterals;
  mesh::Rectangle rectangle;  ///< when mesh_file is empty
  int n_x = 0, n_y = 0;
  /// A box (3-D): the rectangle times [z_min, z_max] with n_z cells along z; n_z = 0: planar.
  double z_min = 0.0, z_max = 1.0;
  int n_z = 0;
  /// A box: its nodes along x, y, z given one by one (each replaces that axis's min, max, n and
  /// grading); a z_nodes list makes the domain a box too.
  std::array<std::vector<double>, 3> box_nodes;
  double perturb = 0.0;
  std::uint32_t seed = 1;
  std::vector<double> grading_x, grading_y;  ///< see mesh::graded_nodes
  std::vector<double> grading_z;             ///< a box: planes z = c the mesh is graded towards
  std::vector<mesh::Point> grading_points;   ///< see mesh::grade_towards_vertices
  double domain_grading = 0.5;
  int grading_layers = 0;
  int refinements = 0;  ///< uniform refinements after building; T_{C,H} follows
  // [boundary]: predicates in x, y on edge midpoints (non-zero = inside), or Gmsh group names.
  std::string contact_predicate, dirichlet_predicate;
  std::vector<std::string> contact_groups, dirichlet_groups;
  /// Elastic scenes: edges where u_x = 0 (u_y = 0) alone (rollers), by predicate or Gmsh group.
  std::string fixed_x_predicate, fixed_y_predicate;
  std::string fixed_z_predicate;  ///< a box: faces where u_z = 0 alone
  std::vector<std::string> fixed_x_groups, fixed_y_groups, fixed_z_groups;
  /// Dirichlet data, expressions in x, y: u_D on Γ_D (scalar model), u_D,x and u_D,y wherever that
  /// component is fixed (Γ_D and rollers; elastic scenes). Empty: 0.
  std::string dirichlet_value, dirichlet_x, dirichlet_y;
  // [contact_mesh]: exactly one of m, ratio (= h/H), breakpoints, mesh (3-D). m and ratio hold one
  // value for every zone of Γ_C or one per zone (in the zones' order, ContactBoundary); empty: not
  // given.
  std::vector<int> m;
  std::vector<Ratio> ratio;
  std::vector<double> breakpoints;
  std::string contact_mesh_file;            ///< a 3-D T_{C,H} of triangles from Gmsh; empty: none
  std::optional<double> contact_mesh_size;  ///< a .geo contact_mesh_file: Gmsh's maximal element size
  double grading = 1.0;
  space::MultiplierFamily family;  ///< the multiplier family on T_{C,H}
  // [discretization]
  Degree p{1, {}}, pc{0, {}};
  // [data]: expressions in x, y.
  std::string friction_bound;  ///< s (may be empty)
  std::string load = "-1";     ///< f
  std::string obstacle;        ///< g (may be empty)
  // [obstacle]: a rigid obstacle as geometry, instead of g (used when obstacle.type is given).
  contact::RigidObstacle rigid_obstacle;
  // [material] (elastic effects): Young's modulus and Poisson's ratio, expressions in x, y
  // evaluated at cell centres (so cell groups may differ), and the plane model.
  std::string young = "1", poisson = "0.3";
  assembly::PlaneModel plane_model = assembly::PlaneModel::strain;
  // [data] of the elastic effects: body force, traction on Γ_N, Coulomb's coefficient.
  std::string body_force_x = "0", body_force_y = "0", traction_x = "0", traction_y = "0";
  std::string body_force_z = "0";  ///< a box
  double friction_coefficient = 0.0;
  // [exact] (elastic effects): a known displacement and contact pressure, expressions in x, y that
  // the run compares its solution with; empty: none.
  std::string exact_x, exact_y, exact_pressure;
  // [infsup]
  infsup::GramNorm norm = infsup::GramNorm::interpolation;
  infsup::PairingProblem problem = infsup::PairingProblem::signorini;
  operators::PrimalNorm primal_norm = operators::PrimalNorm::h1;  ///< elastic scenes: h1 or energy
  double alpha_tolerance = 1e-4;
  contact::SchurPath alpha_operator = contact::SchurPath::automatic;  ///< infsup.operator (3-D)
  // [solve]
  /// |𝒞| per segment (Remark 3): one value, or one per zone of Γ_C; empty: p_C + 1.
  std::vector<int> constraint_points;
  bool fit_free_boundary = false;
  /// What a solve does when its pairing is predicted unstable (infsup/local_alpha.hpp).
  enum class StabilityPolicy { warn, refuse, ignore } stability = StabilityPolicy::warn;
  contact::SchurPath trace_solve = contact::SchurPath::automatic;  ///< solve.trace_operator (3-D)
  // [run]: empty effects when the scene has no [run] table (`solve` then needs --effects).
  std::vector<Effect> effects;
  std::vector<Output> outputs = all_outputs();
  // [convergence]
  int convergence_refinements = 3;
  // [adapt]
  AdaptSettings adapt;
  /// Whether the run adapts T_h and T_{C,H} (adapt.target given).
  bool is_adaptive() const { return adapt.target > 0.0; }

  /// 3 for a box (domain.n_z or domain.z_nodes given) or a 3-D Gmsh mesh, else 2: the variables
  /// of the scene's expressions.
  int dimension() const { return n_z > 0 || !box_nodes[2].empty() || mesh_dimension == 3 ? 3 : 2; }
  /// Whether the obstacle is given as geometry ([obstacle]) rather than by g.
  bool has_rigid_obstacle() const { return given.contains("obstacle.type"); }
  /// Whether the contact problems have their obstacle: g or [obstacle].
  bool has_obstacle() const { return !obstacle.empty() || has_rigid_obstacle(); }

  /// Dotted keys the scene (or an override) gives, and where each overridden value came from.
  std::set<std::string> given;
  std::map<std::string, std::string> origins;

  /// Where the value of a dotted key came from, for messages: an option such as
  /// "hpcontact solve --p" if one replaced it, else the file.
  std::string where(const std::string& key) const;
  /// The value of a per-zone list (one value for all zones, or one per zone) for zone `zone` of
  /// `n_zones`. @throws InputError naming `key` if the list has another length.
  template <typename T>
  const T& of_zone(const std::vector<T>& values, int zone, int n_zones, const std::string& key) const;
  bool is_rectangle() const { return mesh_file.empty(); }
  bool has_effect(Effect effect) const;
  /// The contact problems among the effects, in the order signorini, friction, friction_s.
  std::vector<contact::ContactProblem> contact_effects() const;
  /// The elastic contact problems among the effects, in the order frictionless, tresca, coulomb, tied.
  std::vector<contact::ElasticContactProblem> elastic_effects() const;
  /// Whether the scene poses an elastic body (an elastic effect, or a [material] table) rather
  /// than the scalar model.
  bool is_elastic() const;
  bool wants_output(Output output) const;
};

/// The contact pair of a two-body scene: its name (in file names, boundary_<pair>_<effect>.csv)
/// and the master body. Γ_C of each body is its boundary.contact part; T_{C,H} and the multiplier
/// live on the slave's.
struct ContactPair {
  std::string name;
  Scene master;
};

/// The effect of a contact problem.
Effect effect_of(contact::ContactProblem problem);
/// The contact problem of an effect: (9), (13), (15); empty for infsup and convergence.
std::optional<contact::ContactProblem> contact_problem_of(Effect effect);
/// The effect of an elastic contact problem, and back (empty for the other effects).
Effect effect_of(contact::ElasticContactProblem problem);
std::optional<contact::ElasticContactProblem> elastic_problem_of(Effect effect);
/// The effect with this name ("friction_s"); empty if none has it.
std::optional<Effect> effect_named(const std::string& name);

template <typename T>
const T& Scene::of_zone(const std::vector<T>& values, int zone, int n_zones, const std::string& key) const {
  if (values.size() == 1) return values.front();
  if (static_cast<int>(values.size()) != n_zones)
    throw_bad_input(
        where(key), key, fmt::format("(a list of {})", values.size()),
        fmt::format("one value, or one per zone of Γ_C: the scene has {} zone{}", n_zones, n_zones == 1 ? "" : "s"));
  return values[static_cast<std::size_t>(zone)];
}

}  // namespace hpcontact::scene
