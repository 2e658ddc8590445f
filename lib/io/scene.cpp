// Reading scenes and building their meshes.
#include "io/scene.hpp"

#include <unistd.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <tuple>

#include "core/error.hpp"
#include "core/expression.hpp"
#include "io/toml_reader.hpp"
#include "mesh/cell_map.hpp"
#include "mesh/contact_boundary.hpp"
#include "mesh/gmsh_reader.hpp"
#include "mesh/point_grading.hpp"
#include "mesh/refine.hpp"
#include "studies/stability_sweep.hpp"

namespace hpcontact::io {

Scene read_scene(const std::string& path) { return parse_scene(read_text_file(path), path); }

const std::vector<std::string>& effect_names() {
  static const std::vector<std::string> names{"signorini", "friction", "friction_s", "infsup", "convergence"};
  return names;
}

const std::vector<std::string>& output_names() {
  static const std::vector<std::string> names{"summary", "boundary", "vtu", "mode"};
  return names;
}

bool Scene::has_effect(const std::string& effect) const {
  return std::find(effects.begin(), effects.end(), effect) != effects.end();
}

bool Scene::wants_output(const std::string& output) const {
  return std::find(outputs.begin(), outputs.end(), output) != outputs.end();
}

std::vector<std::string> Scene::contact_effects() const {
  std::vector<std::string> problems;
  for (const char* problem : {"signorini", "friction", "friction_s"})
    if (has_effect(problem)) problems.push_back(problem);
  return problems;
}

void check_effects(const Scene& scene, const std::string& where) {
  if (scene.effects.empty()) throw_bad_input(where, "run.effects", "[]", "at least one of " + fmt::format("{}", fmt::join(effect_names(), ", ")));
  for (std::size_t i = 0; i < scene.effects.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (scene.effects[i] == scene.effects[j]) throw_bad_input(where, "run.effects", scene.effects[i], "each effect at most once");
  if (scene.has_effect("signorini") && scene.obstacle.empty())
    throw_bad_input(scene.file, "data.g", "(missing)", "the effect 'signorini' (problem (9)) needs the obstacle g");
  for (const char* problem : {"friction", "friction_s"})
    if (scene.has_effect(problem) && scene.friction_bound.empty())
      throw_bad_input(scene.file, "data.s", "(missing)", fmt::format("the effect '{}' needs the friction bound s", problem));
  if (scene.fit_free_boundary && scene.contact_effects().empty())
    throw_bad_input(where, "solve.fit_free_boundary", "true", "needs a contact problem among the effects (signorini, friction, friction_s)");
  if (scene.has_effect("convergence") && scene.contact_effects().empty())
    throw_bad_input(where, "run.effects", "convergence", "'convergence' refines the contact problems of the scene: add signorini, friction or friction_s");
  if (scene.outputs_given && scene.wants_output("mode") && !scene.has_effect("infsup"))
    throw_bad_input(where, "run.outputs", "mode", "the spurious mode needs the effect 'infsup'");
  for (const char* output : {"boundary", "vtu"})
    if (scene.outputs_given && scene.wants_output(output) && scene.contact_effects().empty())
      throw_bad_input(where, "run.outputs", output, "needs a contact problem among the effects (signorini, friction, friction_s)");
}

namespace {

/// A list of finite numbers (numbers or their text) under `key`; empty when absent.
std::vector<double> number_list(const TomlTable& table, const std::string& key, const std::string& allowed) {
  std::vector<double> values;
  for (const auto& text : table.string_list(key, std::vector<std::string>{})) {
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(value)) throw_bad_input(table.file(), table.qualified(key), text, allowed);
    values.push_back(value);
  }
  return values;
}

}  // namespace

namespace {

// A scene whose discretization cannot fit: refused before anything is allocated. The estimate is
// the rectangle's cells (with grading layers and refinements) times (p + 1)² dofs and 1.2 KB per
// dof, the peak measured for the condensed factorizations at p = 4 (1.2 GB at 1.05e6 dofs).
void check_scene_size(const Scene& scene) {
  if (!scene.rectangle) return;  // a Gmsh mesh is as large as its file
  const double layers = 2.0 * scene.grading_layers;
  const double cells = (scene.n_x + layers * static_cast<double>(scene.grading_x.size())) *
                       (scene.n_y + layers * static_cast<double>(scene.grading_y.size())) *
                       std::pow(4.0, scene.refinements);
  const double p = scene.p_rule.empty() ? scene.p : 1.0;  // a rule: at least degree 1 everywhere
  const double dofs = cells * p * p, bytes = 1.2e3 * dofs;
  const double memory = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
  const std::string size = fmt::format("{:.3g} cells ({} x {}{}) at p = {}: about {:.3g} unknowns", cells, scene.n_x,
                                       scene.n_y, scene.refinements ? fmt::format(", {} refinements", scene.refinements) : "",
                                       scene.p_rule.empty() ? std::to_string(scene.p) : "its rule", dofs);
  if (dofs > 2147483647.0)
    throw_bad_input(scene.file, "domain.n_x, domain.n_y", size, "at most 2^31 - 1 unknowns (32-bit indices)");
  if (bytes > memory)
    throw_bad_input(scene.file, "domain.n_x, domain.n_y", size,
                    fmt::format("needs about {:.3g} GB (1.2 KB per unknown), more than this machine's {:.3g} GB",
                                bytes / 1e9, memory / 1e9));
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& path) {
  const TomlTable root = parse_toml_string(text, path);
  Scene scene;
  scene.file = path;
  // Misspelt section names are reported before "missing section" errors.
  for (const char* section : {"domain", "boundary", "contact_mesh", "discretization", "data", "infsup", "solve", "run", "convergence"})
    root.has(section);
  root.reject_unknown_keys();

  const auto domain = root.table("domain", true);
  if (domain.has("mesh")) {
    scene.mesh_file = domain.string("mesh");
    if (!scene.mesh_file.empty() && scene.mesh_file.front() != '/')
      scene.mesh_file = (std::filesystem::path(path).parent_path() / scene.mesh_file).string();
  } else {
    mesh::Rectangle r;
    r.x_min = domain.number("x_min", -1.0);
    r.x_max = domain.number("x_max", 1.0);
    r.y_min = domain.number("y_min", -1.0);
    r.y_max = domain.number("y_max", 1.0);
    for (const auto& [axis, low, high] : {std::tuple{"x", r.x_min, r.x_max}, std::tuple{"y", r.y_min, r.y_max}}) {
      const std::string key = fmt::format("domain.{}_min, domain.{}_max", axis, axis);
      const std::string value = fmt::format("{}, {}", low, high);
      if (!(high > low)) throw_bad_input(path, key, value, fmt::format("must satisfy {}_min < {}_max", axis, axis));
      // Narrower than this, the vertices of even a coarse mesh coincide in floating point.
      if (high - low <= 1e-9 * std::max({std::abs(low), std::abs(high), 1e-290}) || high - low < 1e-280)
        throw_bad_input(path, key, value,
                        fmt::format("the width {:.3g} is below the resolution of the coordinates: at least 1e-9 of their "
                                    "magnitude (and 1e-280)", high - low));
    }
    scene.rectangle = r;
    scene.n_x = static_cast<int>(domain.integer("n_x", 1, 100000));
    scene.n_y = static_cast<int>(domain.integer("n_y", 1, 100000));
  }
  scene.perturb = domain.number_in("perturb", 0.0, 0.24, 0.0);
  scene.seed = static_cast<std::uint32_t>(domain.integer("seed", 0, 1u << 30, 1));
  scene.grading_x = number_list(domain, "grading_x", "x coordinates (numbers) inside the rectangle");
  scene.grading_y = number_list(domain, "grading_y", "y coordinates (numbers) inside the rectangle");
  for (const auto& [x, y] : domain.pair_list("grading_points")) scene.grading_points.emplace_back(x, y);
  scene.domain_grading = domain.number_in("grading", 0.01, 0.99, 0.5);
  scene.grading_layers = static_cast<int>(domain.integer("grading_layers", 0, 40, 0));
  if ((!scene.grading_x.empty() || !scene.grading_y.empty()) && !scene.rectangle)
    throw_bad_input(path, "domain.grading_x", "", "grading applies to a rectangle, not to a Gmsh mesh");
  scene.refinements = static_cast<int>(domain.integer("refinements", 0, 10, 0));
  domain.reject_unknown_keys();

  const auto boundary = root.table("boundary", true);
  scene.contact_predicate = boundary.string("contact", "");
  scene.dirichlet_predicate = boundary.string("dirichlet", "");
  scene.contact_groups = boundary.string_list("contact_groups", std::vector<std::string>{});
  scene.dirichlet_groups = boundary.string_list("dirichlet_groups", std::vector<std::string>{});
  if (scene.contact_predicate.empty() == scene.contact_groups.empty())
    throw_bad_input(path, "boundary.contact", "(" + std::string(scene.contact_predicate.empty() ? "missing" : "both given") + ")",
                    "give exactly one of 'contact' (a predicate in x, y) and 'contact_groups' (Gmsh physical names)");
  if (!scene.contact_groups.empty() && scene.mesh_file.empty())
    throw_bad_input(path, "boundary.contact_groups", "", "needs a Gmsh mesh in domain.mesh");
  for (const auto& [key, text] : {std::pair{"contact", scene.contact_predicate}, {"dirichlet", scene.dirichlet_predicate}})
    if (!text.empty()) Expression(text, path + ": key 'boundary." + key + "'");
  boundary.reject_unknown_keys();

  const auto contact_mesh = root.table("contact_mesh", true);
  const int given = contact_mesh.has("m") + contact_mesh.has("ratio") + contact_mesh.has("breakpoints");
  if (given != 1)
    throw_bad_input(path, "contact_mesh", fmt::format("({} of m, ratio, breakpoints given)", given),
                    "give exactly one of m, ratio, breakpoints");
  if (contact_mesh.has("m")) scene.m = static_cast<int>(contact_mesh.integer("m", 1, 1000000));
  if (contact_mesh.has("ratio")) {
    scene.ratio = contact_mesh.string_list("ratio").front();
    studies::parse_ratio(scene.ratio, path + ": key 'contact_mesh.ratio'");
  }
  const char* breakpoints_allowed = "positive arc lengths (numbers), strictly increasing, the last the length of Γ_C";
  scene.breakpoints = number_list(contact_mesh, "breakpoints", breakpoints_allowed);
  for (double value : scene.breakpoints)
    if (value <= 0.0) throw_bad_input(path, "contact_mesh.breakpoints", fmt::format("{}", value), breakpoints_allowed);
  scene.grading = contact_mesh.number_in("grading", 1e-3, 1.0, 1.0);
  contact_mesh.reject_unknown_keys();

  const auto discretization = root.table("discretization", true);
  // An integer, or a rule as a string.
  auto degree = [&](const char* key, long long low, long long high, int& value, std::string& rule) {
    const std::string text = discretization.string_list(key).front();
    char* end = nullptr;
    std::strtoll(text.c_str(), &end, 10);
    if (end != text.c_str() && *end == '\0') {
      value = static_cast<int>(discretization.integer(key, low, high));
      return;
    }
    rule = text;
    Expression(rule, path + ": key 'discretization." + key + "'");
    value = -1;  // set per cell or segment from the rule
  };
  degree("p", 1, 20, scene.p, scene.p_rule);
  degree("pC", 0, 19, scene.pc, scene.pc_rule);
  discretization.reject_unknown_keys();

  const auto data = root.table("data");
  scene.friction_bound = data.string("s", "");
  scene.load = data.string("f", "-1");
  scene.obstacle = data.string("g", "");
  for (const auto& [key, text] : {std::pair{"s", scene.friction_bound}, {"f", scene.load}, {"g", scene.obstacle}})
    if (!text.empty()) Expression(text, path + ": key 'data." + key + "'");
  data.reject_unknown_keys();

  const auto infsup = root.table("infsup");
  scene.norm = infsup.choice("norm", {"interp", "extension"}, "interp");
  scene.problem = infsup.choice("problem", {"signorini", "friction"}, "signorini");
  scene.alpha_tolerance = infsup.number_in("alpha_tol", 1e-12, 0.1, 1e-4);
  infsup.reject_unknown_keys();
  const auto solve = root.table("solve");
  // The lower limit p_C + 1 depends on the segment; it is checked when the constraints are built.
  if (solve.has("constraint_points")) scene.constraint_points = static_cast<int>(solve.integer("constraint_points", 1, 64));
  scene.fit_free_boundary = solve.boolean("fit_free_boundary", false);
  if (scene.fit_free_boundary && !scene.rectangle)
    throw_bad_input(path, "solve.fit_free_boundary", "true",
                    "a rectangle domain: the located points become vertices by moving the nearest nodes, which a "
                    "Gmsh mesh does not allow");
  solve.reject_unknown_keys();
  if (scene.problem == "friction" && scene.friction_bound.empty())
    throw_bad_input(path, "data.s", "(missing)", "the friction problem needs the friction bound s");

  const auto run = root.table("run");
  auto chosen = [&](const char* key, const std::vector<std::string>& allowed, std::vector<std::string>& values) {
    if (!run.has(key)) return;
    values = run.string_list(key);
    for (const auto& value : values)
      if (std::find(allowed.begin(), allowed.end(), value) == allowed.end())
        throw_bad_input(path, std::string("run.") + key, value, fmt::format("any of {}", fmt::join(allowed, ", ")));
  };
  chosen("effects", effect_names(), scene.effects);
  chosen("outputs", output_names(), scene.outputs);
  scene.outputs_given = run.has("outputs");
  run.reject_unknown_keys();
  const auto convergence = root.table("convergence");
  scene.convergence_refinements = static_cast<int>(convergence.integer("refinements", 1, 6, 3));
  convergence.reject_unknown_keys();
  root.reject_unknown_keys();
  if (run.has("effects") || run.has("outputs")) check_effects(scene, path);
  check_scene_size(scene);
  return scene;
}

namespace {

/// The tensor mesh, graded towards the lines of grading_x, grading_y, with a node at every
/// coordinate of the grading points (whose local layers come after).
mesh::QuadMesh build_rectangle(const Scene& scene) {
  const auto& r = *scene.rectangle;
  std::vector<double> point_x, point_y;
  for (const auto& point : scene.grading_points) {
    point_x.push_back(point.x());
    point_y.push_back(point.y());
  }
  return mesh::make_tensor_mesh(
      mesh::graded_nodes(r.x_min, r.x_max, scene.n_x, scene.grading_x, scene.domain_grading, scene.grading_layers,
                         scene.file + ": key 'domain.grading_x'", point_x,
                         scene.file + ": key 'domain.grading_points' (an x coordinate)"),
      mesh::graded_nodes(r.y_min, r.y_max, scene.n_y, scene.grading_y, scene.domain_grading, scene.grading_layers,
                         scene.file + ": key 'domain.grading_y'", point_y,
                         scene.file + ": key 'domain.grading_points' (a y coordinate)"),
      scene.file + ": rectangle");
}

/// Local geometric layers towards the scene's grading points.
mesh::QuadMesh grade_towards_points(const mesh::QuadMesh& mesh, const Scene& scene) {
  if (scene.grading_points.empty()) return mesh;
  const std::string origin = scene.file + ": key 'domain.grading_points'";
  std::vector<int> centres;
  for (const auto& point : scene.grading_points) centres.push_back(mesh::vertex_at(mesh, point, origin));
  return mesh::grade_towards_vertices(mesh, centres, scene.domain_grading, scene.grading_layers, origin);
}

}  // namespace

mesh::QuadMesh build_scene_mesh(const Scene& scene) {
  mesh::QuadMesh mesh = grade_towards_points(
      scene.mesh_file.empty() ? build_rectangle(scene) : mesh::read_gmsh_mesh(scene.mesh_file), scene);
  if (scene.perturb > 0) mesh::perturb_interior_vertices(mesh, scene.perturb, scene.seed);
  for (int k = 0; k < scene.refinements; ++k) mesh = mesh::refine_uniformly(mesh);
  auto predicate = [&](const std::string& text, const char* key) {
    const Expression expression(text, scene.file + ": key 'boundary." + key + "'");
    return [expression](const mesh::Point& x) { return expression(x.x(), x.y()) != 0.0; };
  };
  std::map<std::string, mesh::BoundaryPart> by_label;
  for (const auto& group : scene.contact_groups) by_label[group] = mesh::BoundaryPart::contact;
  if (!scene.contact_predicate.empty())
    mesh::assign_boundary_part(mesh, mesh::BoundaryPart::contact, predicate(scene.contact_predicate, "contact"));
  // Γ_D must not overlap Γ_C: check every edge Γ_D claims before assigning it.
  std::function<bool(const mesh::Point&)> in_dirichlet = [](const mesh::Point&) { return false; };
  if (!scene.dirichlet_predicate.empty()) in_dirichlet = predicate(scene.dirichlet_predicate, "dirichlet");
  for (int e : mesh.boundary_edges()) {
    const bool contact = mesh.edge_part(e) == mesh::BoundaryPart::contact ||
                         by_label.contains(mesh.edge_label(e));
    bool dirichlet = in_dirichlet(mesh.edge_midpoint(e));
    for (const auto& group : scene.dirichlet_groups) dirichlet = dirichlet || mesh.edge_label(e) == group;
    if (contact && dirichlet) {
      const auto m = mesh.edge_midpoint(e);
      throw InputError(fmt::format("{}: Γ_C and Γ_D overlap at the edge with midpoint ({}, {}); "
                                   "key 'boundary.dirichlet' must exclude Γ_C", scene.file, m.x(), m.y()));
    }
    if (contact) mesh.set_edge_part(e, mesh::BoundaryPart::contact);
    if (dirichlet) mesh.set_edge_part(e, mesh::BoundaryPart::dirichlet);
  }
  bool any_contact = false;
  for (int e : mesh.boundary_edges()) any_contact = any_contact || mesh.edge_part(e) == mesh::BoundaryPart::contact;
  if (!any_contact) {
    const bool by_groups = scene.contact_predicate.empty();
    std::string value = scene.contact_predicate;
    for (const auto& group : scene.contact_groups) value += (value.empty() ? "" : ", ") + group;
    std::set<std::string> labels;
    for (int e : mesh.boundary_edges()) labels.insert(mesh.edge_label(e));
    throw_bad_input(scene.file, by_groups ? "boundary.contact_groups" : "boundary.contact", value,
                    by_groups ? fmt::format("it must name a physical group on the boundary (Γ_C is empty); the mesh "
                                            "has: {}", fmt::join(labels, ", "))
                              : "it must select at least one boundary edge (Γ_C is empty)");
  }
  try {
    const mesh::ContactBoundary chain(mesh);
  } catch (const InputError& error) {
    throw InputError(fmt::format("{}: key 'boundary.{}': {}", scene.file,
                                 scene.contact_predicate.empty() ? "contact_groups" : "contact", error.what()));
  }
  return mesh;
}

namespace {

int whole_degree(const Expression& rule, const mesh::Point& x, int low, int high,
                 const std::string& file, const std::string& key) {
  const double value = rule(x.x(), x.y());
  if (std::abs(value - std::round(value)) > 1e-9 || value < low || value > high)
    throw_bad_input(file, key, fmt::format("{} at ({}, {})", value, x.x(), x.y()),
                    fmt::format("the rule must give whole numbers in [{}, {}]", low, high));
  return static_cast<int>(std::lround(value));
}

}  // namespace

std::vector<int> scene_cell_degrees(const Scene& scene, const mesh::QuadMesh& mesh) {
  if (scene.p_rule.empty()) return std::vector<int>(mesh.n_cells(), scene.p);
  const Expression rule(scene.p_rule, scene.file + ": key 'discretization.p'");
  std::vector<int> degrees(mesh.n_cells());
  for (int c = 0; c < mesh.n_cells(); ++c)
    degrees[c] = whole_degree(rule, mesh::CellMap(mesh, c).map(0.0, 0.0), 1, 20, scene.file, "discretization.p");
  return degrees;
}

std::vector<int> scene_segment_degrees(const Scene& scene, const mesh::ContactBoundary& contact,
                                       const mesh::BoundaryMesh& boundary_mesh) {
  if (scene.pc_rule.empty()) return std::vector<int>(boundary_mesh.n_segments(), scene.pc);
  const Expression rule(scene.pc_rule, scene.file + ": key 'discretization.pC'");
  std::vector<int> degrees(boundary_mesh.n_segments());
  for (int k = 0; k < boundary_mesh.n_segments(); ++k)
    degrees[k] = whole_degree(rule, contact.point_at(0.5 * (boundary_mesh.segment_begin(k) + boundary_mesh.segment_end(k))),
                              0, 19, scene.file, "discretization.pC");
  return degrees;
}

namespace {

/// Indices k of the trace vertices s_k (1 ≤ k ≤ n, n always last) that are grading points, or at
/// which Γ_C meets one of the scene's grading lines x = c or y = c at an isolated vertex: the
/// singular points the mesh is graded towards. A line Γ_C runs along (grading towards Γ_C
/// itself) marks none of its vertices.
std::vector<int> grading_nodes_on_contact(const Scene& scene, const mesh::ContactBoundary& contact) {
  const auto s = contact.breakpoints();
  const int n = static_cast<int>(s.size()) - 1;
  const double tolerance = 1e-12 * contact.length();
  auto on_a_line = [&](int k, bool along_x) {
    const auto point = contact.point_at(s[k]);
    const double coordinate = along_x ? point.x() : point.y();
    for (double c : along_x ? scene.grading_x : scene.grading_y)
      if (std::abs(coordinate - c) < tolerance) return true;
    return false;
  };
  auto a_grading_point = [&](int k) {
    const auto point = contact.point_at(s[k]);
    return std::any_of(scene.grading_points.begin(), scene.grading_points.end(),
                       [&](const mesh::Point& q) { return (q - point).norm() < tolerance; });
  };
  auto meets_a_line = [&](int k) {
    for (bool along_x : {true, false})
      if (on_a_line(k, along_x) && !(on_a_line(k - 1, along_x) && on_a_line(k + 1, along_x))) return true;
    return false;
  };
  std::vector<int> nodes;
  for (int k = 1; k < n; ++k)
    if (a_grading_point(k) || meets_a_line(k)) nodes.push_back(k);
  nodes.push_back(n);
  return nodes;
}

}  // namespace

mesh::BoundaryMesh build_scene_boundary_mesh(const Scene& scene, const mesh::ContactBoundary& contact) {
  const int split = 1 << scene.refinements;  // segments per segment of the scene's own T_{C,H}
  if (!scene.breakpoints.empty()) {
    auto given = scene.breakpoints;
    if (std::abs(given.back() - contact.length()) > 1e-10 * contact.length())
      throw_bad_input(scene.file, "contact_mesh.breakpoints", fmt::format("last = {}", given.back()),
                      fmt::format("must run from 0 to the length of Γ_C, {}", contact.length()));
    given.back() = contact.length();
    given.insert(given.begin(), 0.0);
    std::vector<double> nodes{0.0};
    for (std::size_t k = 0; k + 1 < given.size(); ++k)
      for (int i = 1; i <= split; ++i) nodes.push_back(given[k] + (given[k + 1] - given[k]) * i / split);
    nodes.back() = contact.length();
    return mesh::BoundaryMesh(nodes, scene.file + ": key 'contact_mesh.breakpoints'");
  }
  if (scene.ratio.empty()) return mesh::BoundaryMesh::graded(contact.length(), scene.m * split, scene.grading);
  // ratio = h/H. On a uniform T_h|Γ_C: m = n · ratio equal segments. On a graded one, T_{C,H}
  // follows T_h|Γ_C: ratio 1/k merges k neighbouring edges (the last segment also takes the
  // n mod k left over), ratio k splits every edge in k.
  const auto edges = contact.breakpoints();
  const int n = static_cast<int>(edges.size()) - 1;
  const double ratio = studies::parse_ratio(scene.ratio, scene.file);
  bool uniform = true;
  for (int e = 0; e < n; ++e) uniform = uniform && std::abs(edges[e + 1] - edges[e] - contact.length() / n) < 1e-9 * contact.length() / n;
  if (uniform) {
    const double exact = n * ratio;
    const int m = static_cast<int>(std::lround(exact));
    if (m < 1 || std::abs(exact - m) > 1e-9 * exact)
      throw_bad_input(scene.file, "contact_mesh.ratio", scene.ratio,
                      fmt::format("Γ_C has {} edges of T_h; {} · ratio = {} must be a whole number of segments", n, n, exact));
    return mesh::BoundaryMesh::graded(contact.length(), m, scene.grading);
  }
  const long merge = std::lround(1.0 / ratio), divide = std::lround(ratio);
  std::vector<double> nodes{0.0};
  if (merge >= 1 && std::abs(merge * ratio - 1.0) < 1e-9 && n >= merge) {
    // Groups of k edges within each run between grading nodes, so that the singular points the
    // mesh is graded towards stay breakpoints of T_{C,H} (a segment straddling the end of a
    // contact set cannot represent λ's square-root onset); a run's last segment also takes the
    // edges left over, a run shorter than k is one segment.
    const auto runs = grading_nodes_on_contact(scene, contact);
    int run_begin = 0;
    for (int run_end : runs) {
      const int length = run_end - run_begin, groups = std::max(1, length / static_cast<int>(merge));
      for (int g = 1; g < groups; ++g) nodes.push_back(edges[run_begin + g * static_cast<int>(merge)]);
      nodes.push_back(edges[run_end]);
      run_begin = run_end;
    }
  } else if (divide >= 1 && std::abs(ratio - static_cast<double>(divide)) < 1e-9) {
    for (int e = 0; e < n; ++e)
      for (long i = 1; i <= divide; ++i) nodes.push_back(edges[e] + (edges[e + 1] - edges[e]) * i / divide);
  } else {
    throw_bad_input(scene.file, "contact_mesh.ratio", scene.ratio,
                    fmt::format("T_h is not uniform on Γ_C ({} edges): the ratio must be 1/k with k <= {}, or a whole number", n, n));
  }
  nodes.back() = contact.length();
  return mesh::BoundaryMesh(nodes, scene.file + ": key 'contact_mesh.ratio'");
}

}  // namespace hpcontact::io
