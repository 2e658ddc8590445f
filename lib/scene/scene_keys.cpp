// The scene keys: one row per key, built from typed helpers so that the range a reader checks and
// the range the reference shows are the same numbers.
#include "scene/scene_keys.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>

#include "core/error.hpp"
#include "core/expression.hpp"
#include "mesh/gmsh_solid_reader.hpp"
#include "scene/adapt_keys.hpp"
#include "scene/box_keys.hpp"
#include "scene/key_builders.hpp"
#include "scene/obstacle_keys.hpp"

namespace hpcontact::scene {
namespace {

using io::TomlTable;

/// An integer in [low, high], or a rule (an expression in x, y; a string).
SceneKey degree_key(const char* name, int low, int high, Degree Scene::*member, const char* doc) {
  return {"discretization",
          name,
          "integer or expression in x, y",
          "",
          fmt::format("[{}, {}]", low, high),
          doc,
          "",
          [=](const TomlTable& table, Scene& scene) {
            const std::string text = table.string_list(name).front();
            char* end = nullptr;
            std::strtoll(text.c_str(), &end, 10);
            if (end != text.c_str() && *end == '\0') {
              scene.*member = Degree{static_cast<int>(table.integer(name, low, high)), {}};
              return;
            }
            Expression(text, table.origin(name) + ": key '" + table.qualified(name) + "'", scene.dimension());
            scene.*member = Degree{-1, text};  // evaluated per cell (segment) when the mesh exists
          }};
}

/// `mesh`: a Gmsh file, relative to the scene file; unreadable files are reported now, with the
/// reason, before any work.
void read_mesh_path(const TomlTable& table, const Scene& scene, std::string& file) {
  if (!table.has("mesh")) return;
  const std::string path = table.string("mesh");
  const bool relative = !path.empty() && path.front() != '/';
  file = relative ? (std::filesystem::path(scene.file).parent_path() / path).string() : path;
  if (file.empty()) throw_bad_input(table.origin("mesh"), table.qualified("mesh"), "\"\"", "a file name");
  errno = 0;
  if (!std::ifstream(file))
    throw_bad_input(table.origin("mesh"), table.qualified("mesh"), "\"" + path + "\"",
                    describe_io_failure("a readable Gmsh file; cannot open", file));
}

/// `mesh_size`: Gmsh's maximal element size for the .geo `file` of `file_key`.
void read_mesh_size(const TomlTable& table, const std::string& file, std::optional<double>& size,
                    const char* file_key) {
  if (!table.has("mesh_size")) return;
  size = table.number_in("mesh_size", 0.0, 1e6);
  if (!(*size > 0.0)) throw_bad_input(table.origin("mesh_size"), table.qualified("mesh_size"), "0", "a number > 0");
  if (std::filesystem::path(file).extension() != ".geo")
    throw_bad_input(table.origin("mesh_size"), table.qualified("mesh_size"), fmt::format("{}", *size),
                    fmt::format("only with a Gmsh geometry file (.geo) as {}", file_key));
}

/// domain.cells: what the rectangle, a planar .geo or a box is cut into; refused beside a mesh file.
SceneKey cells_key() {
  SceneKey cells = choice_key<mesh::GeneratedCells>(
      "domain", "cells",
      {{"quadrilaterals", mesh::GeneratedCells::quadrilaterals},
       {"triangles", mesh::GeneratedCells::triangles},
       {"tetrahedra", mesh::GeneratedCells::tetrahedra}},
      mesh::GeneratedCells::quadrilaterals, &Scene::cells,
      "the rectangle's cells (triangles: each cut along its diagonal from lower left to upper right), or the "
      "cells a planar .geo `mesh` is meshed into (a mesh file holds its own); a box's cells: hexahedra (the "
      "default) or tetrahedra (each hexahedron cut into six around its diagonal from its lowest corner); a 3-D "
      ".geo's own settings decide its cells");
  cells.read = [choose = cells.read](const TomlTable& table, Scene& scene) {
    choose(table, scene);
    if (table.has("cells") && !scene.mesh_file.empty() && std::filesystem::path(scene.mesh_file).extension() != ".geo")
      throw_bad_input(table.origin("cells"), table.qualified("cells"), table.string("cells"),
                      "only with the rectangle or a Gmsh geometry file (.geo) as domain.mesh: " + scene.mesh_file +
                          " holds its own cells");
  };
  return cells;
}

void add_domain_keys(std::vector<SceneKey>& keys) {
  auto add = [&](SceneKey key) { keys.push_back(std::move(key)); };
  add({"domain", "mesh", "string", "",
       "a Gmsh mesh file (MSH 2.2 or 4, ASCII or binary) of triangles and/or quadrilaterals, or of hexahedra or "
       "tetrahedra (a "
       "3-D scene), or a Gmsh geometry (.geo; one with a Volume is meshed in 3-D)",
       "Gmsh mesh, or geometry meshed on the fly (see `cells`), relative to the scene file; absent: the "
       "rectangle below",
       "", [](const TomlTable& table, Scene& scene) {
         read_mesh_path(table, scene, scene.mesh_file);
         if (scene.mesh_file.empty()) return;
         // Its dimension decides what the scene takes (x, y or x, y, z; planar or 3-D keys). Only
         // regular files are opened: Gmsh would read a device such as /dev/zero forever.
         std::error_code error;
         if (!std::filesystem::is_regular_file(scene.mesh_file, error))
           throw_bad_input(table.origin("mesh"), table.qualified("mesh"), "\"" + table.string("mesh") + "\"",
                           "a regular file (a Gmsh mesh or .geo)");
         try {
           scene.mesh_dimension = mesh::gmsh_file_dimension(scene.mesh_file) == 3 ? 3 : 2;
         } catch (const InputError& failure) {
           throw InputError(table.origin("mesh") + ": key '" + table.qualified("mesh") + "': " + failure.what());
         }
       }});
  add({"domain", "mesh_size", "number", "the .geo's sizes", "(0, 1e6]",
       "a .geo `mesh`: Gmsh's maximal element size (Mesh.MeshSizeMax), before the split into quadrilaterals "
       "(which halves it) when cells = \"quadrilaterals\"",
       "", [](const TomlTable& table, Scene& scene) {
         read_mesh_size(table, scene.mesh_file, scene.mesh_size, "domain.mesh");
       }});
  add(choice_key<Scene::Geometry>(
      "domain", "geometry", {{"curved", Scene::Geometry::curved}, {"polygonal", Scene::Geometry::polygonal}},
      Scene::Geometry::curved, &Scene::geometry,
      "a Gmsh `mesh`: cells follow its curves (a .geo's exact curves, a high-order mesh's edge nodes), or "
      "only its vertices"));
  add(cells_key());
  add(any_number_key("domain", "x_min", -1.0, &mesh::Rectangle::x_min, "rectangle: left end"));
  add(any_number_key("domain", "x_max", 1.0, &mesh::Rectangle::x_max, "rectangle: right end"));
  add(any_number_key("domain", "y_min", -1.0, &mesh::Rectangle::y_min, "rectangle: bottom end"));
  add(any_number_key("domain", "y_max", 1.0, &mesh::Rectangle::y_max, "rectangle: top end"));
  add(integer_key("domain", "n_x", 1, 100000, std::nullopt, &Scene::n_x, "rectangle: cells along x (required)"));
  add(integer_key("domain", "n_y", 1, 100000, std::nullopt, &Scene::n_y, "rectangle: cells along y (required)"));
  add_box_keys(keys);  // (after n_x, n_y: a box's keys read them)
  add(number_key("domain", "perturb", 0.0, 0.24, 0.0, &Scene::perturb,
                 "moves interior vertices randomly by up to this fraction of the local cell size"));
  add({"domain", "seed", "integer", "1", fmt::format("[0, {}]", 1u << 30), "random seed of `perturb`", "",
       [](const TomlTable& table, Scene& scene) {
         scene.seed = static_cast<std::uint32_t>(table.integer("seed", 0, 1u << 30, 1));
       }});
  add(numbers_key("domain", "grading_x", "x coordinates (numbers) inside the rectangle", &Scene::grading_x,
                  "rectangle: lines x = c the mesh is graded towards (geometric layers)"));
  add(numbers_key("domain", "grading_y", "y coordinates (numbers) inside the rectangle", &Scene::grading_y,
                  "rectangle: lines y = c the mesh is graded towards"));
  add({"domain", "grading_points", "list of pairs [[x, y], ...]", "", "vertices of the mesh (after snapping)",
       "points whose surrounding cells get `grading_layers` local geometric layers", "",
       [](const TomlTable& table, Scene& scene) {
         scene.grading_points.clear();
         for (const auto& [x, y] : table.pair_list("grading_points")) scene.grading_points.emplace_back(x, y);
       }});
  add(number_key("domain", "grading", 0.01, 0.99, 0.5, &Scene::domain_grading,
                 "size ratio of consecutive geometric layers"));
  add(integer_key("domain", "grading_layers", 0, 40, 0, &Scene::grading_layers,
                  "geometric layers per grading line or point"));
  add(integer_key("domain", "refinements", 0, 10, 0, &Scene::refinements,
                  "uniform refinements (each cell into four) after building; T_{C,H} follows"));
}

void add_boundary_and_contact_mesh_keys(std::vector<SceneKey>& keys) {
  auto add = [&](SceneKey key) { keys.push_back(std::move(key)); };
  add(expression_key("boundary", "contact", "", &Scene::contact_predicate,
                     "Γ_C: edges whose midpoint (3-D: faces whose centre) makes this non-zero (its connected pieces "
                     "are its zones, open or "
                     "closed curves)"));
  add(expression_key(
      "boundary", "dirichlet", "", &Scene::dirichlet_predicate,
      "Γ_D (u = u_D, default 0): edges whose midpoint (3-D: faces whose centre) makes this non-zero; the rest is Γ_N"));
  add(names_key("boundary", "contact_groups", &Scene::contact_groups,
                "Γ_C as Gmsh physical groups (instead of `contact`)"));
  add(names_key("boundary", "dirichlet_groups", &Scene::dirichlet_groups, "Γ_D as Gmsh physical groups"));
  add(expression_key("boundary", "fixed_x", "", &Scene::fixed_x_predicate,
                     "elastic scenes: edges (midpoint predicate) where u_x = 0 alone, a roller; u_y stays free"));
  add(expression_key("boundary", "fixed_y", "", &Scene::fixed_y_predicate,
                     "elastic scenes: edges where u_y = 0 alone, a roller; u_x stays free"));
  add(expression_key("boundary", "fixed_z", "", &Scene::fixed_z_predicate,
                     "3-D elastic scenes: faces (centre predicate) where u_z = 0 alone, a roller"));
  add(names_key("boundary", "fixed_x_groups", &Scene::fixed_x_groups, "`fixed_x` as Gmsh physical groups"));
  add(names_key("boundary", "fixed_y_groups", &Scene::fixed_y_groups, "`fixed_y` as Gmsh physical groups"));
  add(names_key("boundary", "fixed_z_groups", &Scene::fixed_z_groups, "3-D: `fixed_z` as Gmsh physical surfaces"));
  add(expression_key("boundary", "u_D", "", &Scene::dirichlet_value,
                     "scalar model: Dirichlet data, u = u_D on Γ_D (empty: 0)"));
  add(expression_key("boundary", "u_D_x", "", &Scene::dirichlet_x,
                     "elastic scenes: u_x = u_D_x on Γ_D and on the `fixed_x` edges (empty: 0)"));
  add(expression_key("boundary", "u_D_y", "", &Scene::dirichlet_y,
                     "elastic scenes: u_y = u_D_y on Γ_D and on the `fixed_y` edges (empty: 0)"));
  // [contact_mesh]
  const char* size_group = "contact_mesh size";
  add({"contact_mesh", "m", "integer or list", "", "[1, 1000000]; one value, or one per zone of Γ_C",
       "segments of T_{C,H} per zone of Γ_C, graded by `grading` (a list: zone by zone)", size_group,
       [](const TomlTable& table, Scene& scene) {
         if (!table.has("m")) return;
         scene.m.clear();
         for (long long m : table.integer_list("m", 1, 1000000)) scene.m.push_back(static_cast<int>(m));
         if (scene.m.empty()) throw_bad_input(table.origin("m"), table.qualified("m"), "[]", "at least one value");
       }});
  add({"contact_mesh", "ratio", "number, fraction or list", "",
       "(0, 64], e.g. 1, 0.5, \"2/3\"; one value, or one per zone of Γ_C",
       "h/H in each zone of Γ_C (a list: zone by zone): on a uniform T_h there m = n · ratio; on a graded one 1/k "
       "merges k edges, k splits each edge",
       size_group, [](const TomlTable& table, Scene& scene) {
         if (!table.has("ratio")) return;
         scene.ratio.clear();
         for (const auto& text : table.string_list("ratio"))
           scene.ratio.push_back(parse_ratio(text, table.origin("ratio"), table.qualified("ratio")));
         if (scene.ratio.empty())
           throw_bad_input(table.origin("ratio"), table.qualified("ratio"), "[]", "at least one value");
       }});
  add(numbers_key(
      "contact_mesh", "breakpoints", "positive arc lengths (numbers), strictly increasing, the last the length of Γ_C",
      &Scene::breakpoints,
      "the interior and last breakpoints of T_{C,H} by arc length (the zones of Γ_C one after the other; their ends "
      "are added)",
      [](double v) { return v > 0.0; }, size_group));
  add({"contact_mesh", "mesh", "string", "",
       "a Gmsh mesh file of triangles (MSH 2.2 or 4) or a Gmsh geometry (.geo) of Γ_C; 3-D scenes",
       "T_{C,H} of a 3-D scene: triangles covering Γ_C (nodes in x, y, z on its plane), relative to the scene file; "
       "a .geo is meshed into triangles on the fly",
       size_group,
       [](const TomlTable& table, Scene& scene) { read_mesh_path(table, scene, scene.contact_mesh_file); }});
  add({"contact_mesh", "mesh_size", "number", "the .geo's sizes", "(0, 1e6]",
       "a .geo `mesh`: Gmsh's maximal triangle size (Mesh.MeshSizeMax)", "", [](const TomlTable& table, Scene& scene) {
         read_mesh_size(table, scene.contact_mesh_file, scene.contact_mesh_size, "contact_mesh.mesh");
       }});
  add(number_key("contact_mesh", "grading", 1e-3, 1.0, 1.0, &Scene::grading,
                 "with `m`: each segment this times the previous one (1: uniform)"));
  std::vector<std::pair<std::string, space::MultiplierFamily>> families;
  for (const auto& family : space::all_multiplier_families()) families.emplace_back(space::to_string(family), family);
  add(choice_key<space::MultiplierFamily>(
      "contact_mesh", "family", families, space::MultiplierFamily{}, &Scene::family,
      "the multiplier on T_{C,H}: discontinuous P_{p_C} (the paper's), continuous P_{p_C} (standard mortar: `ratio = "
      "1`, p_C = p or p − 1) or its dual (biorthogonal) basis; `-modified`: the end modification at the ends of each "
      "open zone (the end node dropped, the end segment one degree lower). Standard and dual need p_C ≥ 1 and impose "
      "their constraints on their coefficients at the Gauss–Lobatto nodes (no `constraint_points`)"));
}

void add_discretization_and_data_keys(std::vector<SceneKey>& keys) {
  auto add = [&](SceneKey key) { keys.push_back(std::move(key)); };
  add(degree_key("p", 1, 20, &Scene::p, "degree p of S^p(T_h), or a rule evaluated at cell centres (required)"));
  add(degree_key("pC", 0, 19, &Scene::pc,
                 "multiplier degree p_C, or a rule evaluated at segment midpoints (required)"));
  // [data]
  add(expression_key("data", "f", "-1", &Scene::load, "load f"));
  add(expression_key("data", "g", "", &Scene::obstacle, "obstacle g of the Signorini problem (9)"));
  add(expression_key("data", "s", "", &Scene::friction_bound,
                     "friction bound s ≥ 0 of (13), (15) and of the pairing (22); Tresca's threshold"));
  add(expression_key("data", "f_x", "0", &Scene::body_force_x, "elastic effects: body force, x component"));
  add(expression_key("data", "f_y", "0", &Scene::body_force_y, "elastic effects: body force, y component"));
  add(expression_key("data", "f_z", "0", &Scene::body_force_z, "3-D elastic effects: body force, z component"));
  add(expression_key("data", "t_x", "0", &Scene::traction_x, "elastic effects: traction on Γ_N, x component"));
  add(expression_key("data", "t_y", "0", &Scene::traction_y, "elastic effects: traction on Γ_N, y component"));
  add(number_key("data", "friction_coefficient", 0.0, 100.0, 0.0, &Scene::friction_coefficient,
                 "Coulomb's friction coefficient F (effect coulomb): |σ_nt| ≤ F |σ_nn|"));
  // [material]
  add(expression_key("material", "E", "1", &Scene::young,
                     "Young's modulus E > 0, evaluated at cell centres (cell groups may differ)"));
  add(expression_key("material", "nu", "0.3", &Scene::poisson,
                     "Poisson's ratio ν in (-1, 0.5), evaluated at cell centres"));
  add(choice_key<assembly::PlaneModel>(
      "material", "model",
      {{"plane_strain", assembly::PlaneModel::strain}, {"plane_stress", assembly::PlaneModel::stress}},
      assembly::PlaneModel::strain, &Scene::plane_model, "2-D model of the elastic body"));
  // [exact]
  add(expression_key("exact", "u_x", "", &Scene::exact_x,
                     "elastic effects: the exact displacement's x component (with u_y); the run reports "
                     "max |u_h − u| / max |u| over the body"));
  add(expression_key("exact", "u_y", "", &Scene::exact_y, "elastic effects: the exact displacement's y component"));
  add(expression_key("exact", "pressure", "", &Scene::exact_pressure,
                     "elastic effects: the exact contact pressure on Γ_C; the run reports max |p_h − p| / max |p| "
                     "there"));
}

void add_run_keys(std::vector<SceneKey>& keys) {
  auto add = [&](SceneKey key) { keys.push_back(std::move(key)); };
  add(choice_key<infsup::GramNorm>("infsup", "norm",
                                   {{"interp", infsup::GramNorm::interpolation},
                                    {"interpolation", infsup::GramNorm::interpolation},
                                    {"extension", infsup::GramNorm::extension}},
                                   infsup::GramNorm::interpolation, &Scene::norm, "realization of H^{-1/2}(Γ_C)"));
  add(choice_key<infsup::PairingProblem>(
      "infsup", "problem",
      {{"signorini", infsup::PairingProblem::signorini}, {"friction", infsup::PairingProblem::friction}},
      infsup::PairingProblem::signorini, &Scene::problem,
      "pairing: (11) or (22) with the scene's s; elastic scenes: the normal multiplier with u·n, or the normal and "
      "tangential ones with (u·n, u·t)"));
  add(choice_key<operators::PrimalNorm>(
      "infsup", "primal_norm", {{"h1", operators::PrimalNorm::h1}, {"energy", operators::PrimalNorm::energy}},
      operators::PrimalNorm::h1, &Scene::primal_norm,
      "norm of the displacement in α of an elastic scene: vector H¹, or the energy a(v, v) + ‖v‖² (depends on E, ν)"));
  add(number_key("infsup", "alpha_tol", 1e-12, 0.1, 1e-4, &Scene::alpha_tolerance,
                 "relative error of α: the H^{-1/2} reference is refined until the estimate is below it"));
  add(choice_key<contact::SchurPath>(
      "infsup", "operator",
      {{"auto", contact::SchurPath::automatic},
       {"dense", contact::SchurPath::dense},
       {"products", contact::SchurPath::products}},
      contact::SchurPath::automatic, &Scene::alpha_operator,
      "3-D scenes: α from S_G = B A_G⁻¹ Bᵀ and G formed densely, or from products only (Davidson; S_G one solve "
      "with A_G's factor per product, G by its cosine moments; memory linear in the multipliers); auto: products "
      "from 64 multipliers unless --eigensolver dense"));
  // [solve]
  add({"solve", "constraint_points", "integer or list", "p_C + 1",
       "[1, 64], at least p_C + 1; one value, or one per zone of Γ_C",
       "constraint points per segment (Chebyshev–Lobatto, Remark 3; a list: zone by zone)", "",
       [](const TomlTable& table, Scene& scene) {
         if (!table.has("constraint_points")) return;
         scene.constraint_points.clear();
         for (long long q : table.integer_list("constraint_points", 1, 64))
           scene.constraint_points.push_back(static_cast<int>(q));
         if (scene.constraint_points.empty())
           throw_bad_input(table.origin("constraint_points"), table.qualified("constraint_points"), "[]",
                           "at least one value");
       }});
  add({"solve", "fit_free_boundary", "boolean", "false", "true, false",
       "grade the mesh towards the free boundary of the contact problems first (rectangle domains)", "",
       [](const TomlTable& table, Scene& scene) {
         scene.fit_free_boundary = table.boolean("fit_free_boundary", false);
       }});
  add(choice_key<Scene::StabilityPolicy>(
      "solve", "stability",
      {{"warn", Scene::StabilityPolicy::warn},
       {"refuse", Scene::StabilityPolicy::refuse},
       {"ignore", Scene::StabilityPolicy::ignore}},
      Scene::StabilityPolicy::warn, &Scene::stability,
      "a pairing predicted unstable (local α below 0.2): warn and name a stable alternative, refuse to solve (exit "
      "2), or say nothing (the prediction is in the summary either way)"));
  add(choice_key<contact::SchurPath>(
      "solve", "trace_operator",
      {{"auto", contact::SchurPath::automatic},
       {"dense", contact::SchurPath::dense},
       {"products", contact::SchurPath::products},
       {"saddle_point", contact::SchurPath::saddle_point}},
      contact::SchurPath::automatic, &Scene::trace_solve,
      "3-D scenes: S = B K⁻¹ Bᵀ formed densely from the factor's trailing block, or applied by products (one solve "
      "with K's factor each; MPRGP, FISTA), never formed; auto: products from 1e4 primal unknowns when the "
      "multipliers exceed a quarter of (primal unknowns)^(2/3), where they cost less; saddle_point (elastic "
      "frictionless contact, --distributed-solver gamg or bddc): no S, a primal-dual active set whose steps are K's "
      "conjugate gradients projected onto the active constraints"));
  // [run]
  add(enum_list_key<Effect>("run", "effects", all_effects(), &Scene::effects, "",
                            "what the run computes; absent: `solve` needs --effects"));
  add(enum_list_key<Output>("run", "outputs", all_outputs(), &Scene::outputs, "those that apply",
                            "what the run writes; listed outputs must apply to the effects"));
  // [convergence]
  add(integer_key("convergence", "refinements", 1, 6, 3, &Scene::convergence_refinements,
                  "levels of uniform refinement beyond the scene's mesh (effect convergence)"));
}

std::vector<SceneKey> declare_keys() {
  std::vector<SceneKey> keys;
  add_domain_keys(keys);
  add_boundary_and_contact_mesh_keys(keys);
  add_discretization_and_data_keys(keys);
  add_obstacle_keys(keys);
  add_run_keys(keys);
  add_adapt_keys(keys);
  return keys;
}

}  // namespace

const std::vector<SceneKey>& scene_keys() {
  static const std::vector<SceneKey> keys = declare_keys();
  return keys;
}

const SceneKey* find_scene_key(const std::string& dotted) {
  for (const auto& key : scene_keys())
    if (key.dotted() == dotted) return &key;
  return nullptr;
}

}  // namespace hpcontact::scene
