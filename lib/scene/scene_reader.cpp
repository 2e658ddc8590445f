// Scene text + overrides → a checked Scene: keys read through the declared table, then the rules
// between keys.
#include "scene/scene_reader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <toml++/toml.h>

#include <cmath>
#include <memory>
#include <tuple>

#include "core/error.hpp"
#include "core/memory_limit.hpp"
#include "io/toml_reader.hpp"
#include "scene/adapt_keys.hpp"
#include "scene/obstacle_keys.hpp"
#include "scene/scene_keys.hpp"
#include "scene/scene_tree.hpp"

namespace hpcontact::scene {
namespace {

/// The override's value as a TOML node.
void assign(toml::table& section, const std::string& name, const SceneOverride::Value& value) {
  std::visit(
      [&](const auto& v) {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, long long>) {
          section.insert_or_assign(name, static_cast<std::int64_t>(v));
        } else if constexpr (std::is_same_v<T, std::vector<long long>>) {
          toml::array list;
          for (long long k : v) list.push_back(static_cast<std::int64_t>(k));
          section.insert_or_assign(name, std::move(list));
        } else if constexpr (std::is_same_v<T, std::vector<std::string>> || std::is_same_v<T, std::vector<double>>) {
          toml::array list;
          for (const auto& element : v) list.push_back(element);
          section.insert_or_assign(name, std::move(list));
        } else if constexpr (std::is_same_v<T, std::vector<std::vector<double>>>) {
          toml::array list;
          for (const auto& inner : v) {
            toml::array numbers;
            for (double x : inner) numbers.push_back(x);
            list.push_back(std::move(numbers));
          }
          section.insert_or_assign(name, std::move(list));
        } else {
          section.insert_or_assign(name, v);
        }
      },
      value);
}

/// Applies the overrides to the parsed file; returns the origins of the values they set.
std::map<std::string, std::string> apply_overrides(toml::table& root, const std::vector<SceneOverride>& overrides) {
  std::map<std::string, std::string> origins;
  for (const auto& override : overrides) {
    const KeyPlace place = place_of_key(root, override.key, override.origin);
    const SceneKey* key = find_scene_key(place.section + "." + place.key);
    if (!key) {
      std::vector<std::string> names;
      for (const auto& known : scene_keys()) names.push_back(known.dotted());
      const auto nearest = io::nearest_name(place.section + "." + place.key, names);
      throw InputError(
          fmt::format("{}: unknown scene key '{}'{}; the keys are listed in docs/scene_keys.md "
                      "(hpcontact scene-keys)",
                      override.origin, override.key, nearest ? fmt::format(" (did you mean '{}'?)", *nearest) : ""));
    }
    if (!key->group.empty())
      for (const auto& other : scene_keys())
        if (other.group == key->group && other.section == key->section) {
          place.table->erase(other.name);
          // (a .geo's size goes with it: another size key would leave it without its file)
          if (other.name == "mesh" && key->name != "mesh") place.table->erase("mesh_size");
        }
    assign(*place.table, key->name, override.value);
    origins[override.key] = override.origin;
  }
  return origins;
}

void check_domain(const Scene& scene) {
  if (scene.dimension() == 2)
    for (const char* key : {"domain.grading_z", "boundary.fixed_z", "boundary.fixed_z_groups", "data.f_z",
                            "solve.trace_operator", "infsup.operator", "contact_mesh.mesh", "contact_mesh.mesh_size"})
      if (scene.given.contains(key))
        throw_bad_input(scene.where(key), key, "(given)",
                        "only in a 3-D scene (a box: domain.n_z given, or a Gmsh mesh of hexahedra or tetrahedra)");
  if (!scene.is_rectangle()) {
    for (const char* key : {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max", "n_x", "n_y", "n_z", "grading_x",
                            "grading_y", "grading_z", "x_nodes", "y_nodes", "z_nodes"})
      if (scene.given.contains(fmt::format("domain.{}", key)))
        throw_bad_input(scene.where(fmt::format("domain.{}", key)), fmt::format("domain.{}", key), "(given)",
                        "applies to a rectangle, not to the Gmsh mesh of domain.mesh");
    if (scene.fit_free_boundary)
      throw_bad_input(scene.where("solve.fit_free_boundary"), "solve.fit_free_boundary", "true",
                      "a rectangle domain: the located points become vertices by moving the nearest nodes, which a "
                      "Gmsh mesh does not allow");
    return;
  }
  for (const auto& [key, nodes] :
       {std::pair{"domain.n_x", "domain.x_nodes"}, std::pair{"domain.n_y", "domain.y_nodes"}})
    if (!scene.given.contains(key) && !(scene.dimension() == 3 && scene.given.contains(nodes)))
      throw_bad_input(scene.file, key, "(missing)",
                      scene.dimension() == 3 ? fmt::format("an integer in [1, 100000], or {}", nodes)
                                             : std::string("an integer in [1, 100000] is required"));
  // A box's axis given by its nodes takes none of the keys they replace.
  for (int axis = 0; axis < 3; ++axis) {
    const std::string name = std::string(1, "xyz"[axis]);
    const std::string nodes = "domain." + name + "_nodes";
    if (!scene.given.contains(nodes)) continue;
    if (scene.dimension() == 2)
      throw_bad_input(scene.where(nodes), nodes, "(given)",
                      "only in a 3-D scene (a box: domain.n_z or domain.z_nodes)");
    for (const std::string& replaced : {name + "_min", name + "_max", "n_" + name, "grading_" + name})
      if (scene.given.contains("domain." + replaced))
        throw_bad_input(scene.where("domain." + replaced), "domain." + replaced, "(given)",
                        fmt::format("not with {}, which gives the axis's nodes", nodes));
  }
  const auto& r = scene.rectangle;
  for (const auto& [axis, low, high] : {std::tuple{"x", r.x_min, r.x_max}, std::tuple{"y", r.y_min, r.y_max}}) {
    if (scene.given.contains(fmt::format("domain.{}_nodes", axis))) continue;
    const std::string key = fmt::format("domain.{}_min, domain.{}_max", axis, axis);
    const std::string value = fmt::format("{}, {}", low, high);
    if (!(high > low)) throw_bad_input(scene.file, key, value, fmt::format("must satisfy {}_min < {}_max", axis, axis));
    // Narrower than this, the vertices of even a coarse mesh coincide in floating point.
    if (high - low <= 1e-9 * std::max({std::abs(low), std::abs(high), 1e-290}) || high - low < 1e-280)
      throw_bad_input(scene.file, key, value,
                      fmt::format("the width {:.3g} is below the resolution of the coordinates: at least 1e-9 of their "
                                  "magnitude (and 1e-280)",
                                  high - low));
  }
}

void check_boundary_and_contact_mesh(const Scene& scene) {
  if (scene.contact_predicate.empty() == scene.contact_groups.empty())
    throw_bad_input(scene.where("boundary.contact"), "boundary.contact",
                    "(" + std::string(scene.contact_predicate.empty() ? "missing" : "both given") + ")",
                    "give exactly one of 'contact' (a predicate in x, y) and 'contact_groups' (Gmsh physical names)");
  if (!scene.contact_groups.empty() && scene.is_rectangle())
    throw_bad_input(scene.where("boundary.contact_groups"), "boundary.contact_groups", "",
                    "needs a Gmsh mesh in domain.mesh");
  int given = 0;
  for (const char* key : {"contact_mesh.m", "contact_mesh.ratio", "contact_mesh.breakpoints", "contact_mesh.mesh"})
    given += scene.given.contains(key) ? 1 : 0;
  if (given != 1)
    throw_bad_input(scene.file, "contact_mesh", fmt::format("({} of m, ratio, breakpoints, mesh given)", given),
                    "give exactly one of m, ratio, breakpoints (and mesh in 3-D)");
  // (The elastic friction pairing, normal and tangential multipliers, has no weight s.)
  if (scene.problem == infsup::PairingProblem::friction && scene.friction_bound.empty() && !scene.is_elastic())
    throw_bad_input(scene.where("data.s"), "data.s", "(missing)", "the friction problem needs the friction bound s");
}

// A scene whose discretization cannot fit: refused before anything is allocated. The estimate is
// the rectangle's cells (with grading layers and refinements) times (p + 1)² dofs and 1.2 KB per
// dof, the peak measured for the condensed factorizations at p = 4 (1.2 GB at 1.05e6 dofs).
void check_scene_size(const Scene& scene) {
  if (!scene.is_rectangle()) return;  // a Gmsh mesh is as large as its file
  const double layers = 2.0 * scene.grading_layers;
  // Cells along an axis: a box's nodes count them, else n and the grading's layers.
  const auto along = [&](int axis, int n, const std::vector<double>& grading) {
    if (!scene.box_nodes[axis].empty()) return static_cast<double>(scene.box_nodes[axis].size() - 1);
    return n + layers * static_cast<double>(grading.size());
  };
  const double cells = along(0, scene.n_x, scene.grading_x) * along(1, scene.n_y, scene.grading_y) *
                       std::pow(4.0, scene.refinements) *
                       (scene.dimension() == 3 ? along(2, scene.n_z, scene.grading_z) : 1.0);
  const double p = scene.p.rule.empty() ? scene.p.value : 1.0;  // a rule: at least degree 1 everywhere
  // Per unknown: 1.2 KB in 2-D; in 3-D, whose factors fill far more, 17.5 KB (3-D Hertz on the grid
  // T_{C,H}, hertz_grid.toml, p = 2, 191520 unknowns: 3.35 GB; the triangles of hertz.toml on the
  // finer box measure 19.9 KB: the estimate is a guide, not a bound), three per node for an
  // elastic box.
  const bool solid = scene.dimension() == 3;
  const double dofs = cells * std::pow(p, scene.dimension()) * (solid && scene.is_elastic() ? 3.0 : 1.0);
  const double bytes = (solid ? 17.5e3 : 1.2e3) * dofs;
  const MemoryLimit memory = memory_limit();
  const std::string counts = scene.dimension() == 3 ? fmt::format("{} x {} x {}", along(0, scene.n_x, {}),
                                                                  along(1, scene.n_y, {}), along(2, scene.n_z, {}))
                                                    : fmt::format("{} x {}", scene.n_x, scene.n_y);
  const std::string keys = scene.dimension() == 3 ? "domain.n_x, domain.n_y, domain.n_z" : "domain.n_x, domain.n_y";
  const std::string size = fmt::format("{:.3g} cells ({}{}) at p = {}: about {:.3g} unknowns", cells, counts,
                                       scene.refinements ? fmt::format(", {} refinements", scene.refinements) : "",
                                       scene.p.rule.empty() ? std::to_string(scene.p.value) : "its rule", dofs);
  if (dofs > 2147483647.0) throw_bad_input(scene.file, keys, size, "at most 2^31 - 1 unknowns (32-bit indices)");
  if (bytes > memory.bytes)
    throw_bad_input(scene.file, keys, size,
                    fmt::format("needs about {:.3g} GB ({} KB per unknown), more than {}", bytes / 1e9,
                                solid ? "17.5" : "1.2", memory.describe()));
}

}  // namespace

namespace {

// Keys that apply only to one kind of body: given for the other, they would silently do nothing.
const std::vector<std::string>& elastic_only_keys() {
  static const std::vector<std::string> keys{"material.E",
                                             "material.nu",
                                             "material.model",
                                             "data.f_x",
                                             "data.f_y",
                                             "data.f_z",
                                             "data.t_x",
                                             "data.t_y",
                                             "data.friction_coefficient",
                                             "boundary.fixed_x",
                                             "boundary.fixed_y",
                                             "boundary.fixed_z",
                                             "boundary.fixed_x_groups",
                                             "boundary.fixed_y_groups",
                                             "boundary.fixed_z_groups",
                                             "boundary.u_D_x",
                                             "boundary.u_D_y",
                                             "exact.u_x",
                                             "exact.u_y",
                                             "exact.pressure"};
  return keys;
}

void check_elastic_effects(const Scene& scene) {
  const std::string where = scene.where("run.effects");
  if (!scene.contact_effects().empty())
    throw_bad_input(where, "run.effects", to_string(effect_of(scene.contact_effects().front())),
                    "one body per scene: the scalar model's problems (signorini, friction, friction_s) or, with "
                    "[material], the elastic ones (frictionless, tresca, coulomb, tied), not both");
  if (scene.fit_free_boundary)
    throw_bad_input(scene.where("solve.fit_free_boundary"), "solve.fit_free_boundary", "true",
                    "false with the elastic effects (the fit grades towards the scalar model's free boundary)");
  if (scene.given.contains("data.f"))
    throw_bad_input(scene.where("data.f"), "data.f", scene.load,
                    "absent in an elastic scene: its body force is data.f_x, data.f_y");
  if (scene.given.contains("boundary.u_D"))
    throw_bad_input(scene.where("boundary.u_D"), "boundary.u_D", scene.dirichlet_value,
                    "absent in an elastic scene: its Dirichlet data are boundary.u_D_x, boundary.u_D_y");
  if (!scene.body.empty() && scene.has_rigid_obstacle())
    throw_bad_input(scene.where("obstacle.type"), "obstacle.type", to_string(scene.rigid_obstacle.type),
                    "absent for a body of a contact pair: the other body is its obstacle");
  if (!scene.body.empty() && scene.given.contains("data.g"))
    throw_bad_input(scene.where("data.g"), "data.g", scene.obstacle,
                    "absent for a body of a contact pair: the gap is the distance between the bodies along the "
                    "slave's normal (move a body to open or close it)");
  if (scene.body.empty() && !scene.elastic_effects().empty() && !scene.has_obstacle())
    throw_bad_input(scene.where("data.g"), "data.g", "(missing)",
                    "the elastic contact problems need the gap g to the obstacle along the normal, or the obstacle "
                    "as geometry in [obstacle]");
  if (scene.exact_x.empty() != scene.exact_y.empty()) {
    const std::string missing = scene.exact_x.empty() ? "exact.u_x" : "exact.u_y";
    throw_bad_input(scene.where(missing), missing, "(missing)",
                    "both components of the exact displacement, or neither");
  }
  if (scene.is_master) return;  // the multiplier's data are the slave's
  if (scene.has_effect(Effect::tresca) && scene.friction_bound.empty())
    throw_bad_input(scene.where("data.s"), "data.s", "(missing)", "the effect 'tresca' needs the threshold s");
  if (scene.has_effect(Effect::coulomb) && !scene.given.contains("data.friction_coefficient"))
    throw_bad_input(scene.where("data.friction_coefficient"), "data.friction_coefficient", "(missing)",
                    "the effect 'coulomb' needs the friction coefficient F");
}

}  // namespace

void check_effects(const Scene& scene) {
  const std::string where = scene.where("run.effects");
  if (scene.effects.empty()) {
    std::vector<std::string> names;
    for (Effect effect : all_effects()) names.push_back(to_string(effect));
    throw_bad_input(where, "run.effects", "[]", fmt::format("at least one of {}", fmt::join(names, ", ")));
  }
  if (scene.is_elastic()) {
    check_elastic_effects(scene);
  } else {
    if (scene.primal_norm != operators::PrimalNorm::h1)
      throw_bad_input(scene.where("infsup.primal_norm"), "infsup.primal_norm", "energy",
                      "\"h1\" for the scalar model (its energy norm is the H¹ seminorm, already in h1)");
    for (const auto& key : elastic_only_keys())
      if (scene.given.contains(key))
        throw_bad_input(scene.where(key), key, "(given)",
                        "only with an elastic effect (frictionless, tresca, coulomb, tied) among run.effects");
  }
  if (scene.has_effect(Effect::signorini) && !scene.has_obstacle())
    throw_bad_input(scene.where("data.g"), "data.g", "(missing)",
                    "the effect 'signorini' (problem (9)) needs the obstacle g, or the obstacle as geometry in "
                    "[obstacle]");
  for (Effect problem : {Effect::friction, Effect::friction_s})
    if (scene.has_effect(problem) && scene.friction_bound.empty())
      throw_bad_input(scene.where("data.s"), "data.s", "(missing)",
                      fmt::format("the effect '{}' needs the friction bound s", to_string(problem)));
  const bool contact = !scene.contact_effects().empty() || !scene.elastic_effects().empty();
  if (scene.fit_free_boundary && !contact)
    throw_bad_input(where, "solve.fit_free_boundary", "true",
                    "needs a contact problem among the effects (signorini, friction, friction_s)");
  if (scene.has_effect(Effect::convergence) && !contact)
    throw_bad_input(where, "run.effects", "convergence",
                    "'convergence' refines the contact problems of the scene: add signorini, friction, friction_s, "
                    "frictionless, tresca, coulomb or tied");
  if (!scene.given.contains("run.outputs")) return;
  const std::string outputs_where = scene.where("run.outputs");
  if (scene.wants_output(Output::mode) && !scene.has_effect(Effect::infsup))
    throw_bad_input(outputs_where, "run.outputs", "mode", "the spurious mode needs the effect 'infsup'");
  for (Output output : {Output::boundary, Output::vtu})
    if (scene.wants_output(output) && !contact)
      throw_bad_input(outputs_where, "run.outputs", to_string(output),
                      "needs a contact problem among the effects (signorini, friction, friction_s, frictionless, "
                      "tresca, coulomb, tied)");
}

Scene read_scene_tree(const std::shared_ptr<toml::table>& tree, const std::string& path,
                      std::map<std::string, std::string> origins, const std::string& body, bool is_master) {
  io::TomlTable root(tree, tree.get(), path, "");
  root.set_origins(origins);

  Scene scene;
  scene.file = path;
  scene.body = body;
  scene.is_master = is_master;
  scene.origins = std::move(origins);
  // Misspelt section names are reported before "missing section" errors.
  for (const auto& section : scene_sections()) root.has(section.name);
  root.reject_unknown_keys();
  for (const auto& section : scene_sections()) {
    const io::TomlTable table = root.table(section.name, section.required);
    // Misspelt keys first ("pc" for "pC"): reported as such, not as the key they miss.
    for (const auto& key : scene_keys())
      if (key.section == section.name) table.has(key.name);
    table.reject_unknown_keys();
    for (const auto& key : scene_keys()) {
      if (key.section != section.name) continue;
      if (table.has(key.name)) scene.given.insert(key.dotted());
      key.read(table, scene);
    }
    table.reject_unknown_keys();
  }
  check_domain(scene);
  check_boundary_and_contact_mesh(scene);
  check_obstacle(scene);
  if (scene.given.contains("run.effects") || scene.given.contains("run.outputs")) check_effects(scene);
  check_adapt(scene);
  check_scene_size(scene);
  return scene;
}

Scene parse_scene(const std::string& text, const std::string& path, const std::vector<SceneOverride>& overrides) {
  // Parse errors are reported with line and column by the reader; the tree is then copied so that
  // the overrides can replace values.
  auto tree = std::make_shared<toml::table>(io::parse_toml_string(text, path).raw());
  auto origins = apply_overrides(*tree, overrides);
  if (tree->contains("body") || tree->contains("pair")) return read_two_body_tree(tree, path, origins);
  return read_scene_tree(tree, path, std::move(origins), "");
}

Scene read_scene(const std::string& path, const std::vector<SceneOverride>& overrides) {
  return parse_scene(io::read_text_file(path), path, overrides);
}

std::string paper_scene_text() {
  return R"toml([domain]
n_x = 8
n_y = 8
[boundary]
contact = "abs(y + 1) < 1e-9"
dirichlet = "abs(y - 1) < 1e-9 || (abs(x - 1) < 1e-9 && y > 0)"
[contact_mesh]
ratio = 1
[discretization]
p = 1
pC = 0
[data]
s = "(1 - x)^2"
)toml";
}

}  // namespace hpcontact::scene
