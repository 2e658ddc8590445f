// Reading scenes and building their meshes.
#include "io/scene.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>

#include "core/error.hpp"
#include "core/expression.hpp"
#include "io/toml_reader.hpp"
#include "mesh/cell_map.hpp"
#include "mesh/gmsh_reader.hpp"
#include "studies/stability_sweep.hpp"

namespace hpcontact::io {

Scene read_scene(const std::string& path) { return parse_scene(read_text_file(path), path); }

Scene parse_scene(const std::string& text, const std::string& path) {
  const TomlTable root = parse_toml_string(text, path);
  Scene scene;
  scene.file = path;
  // Misspelt section names are reported before "missing section" errors.
  for (const char* section : {"domain", "boundary", "contact_mesh", "discretization", "data", "infsup", "solve"})
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
    if (!(r.x_max > r.x_min) || !(r.y_max > r.y_min))
      throw_bad_input(path, "domain.x_max / domain.y_max", "", "the rectangle must satisfy x_min < x_max and y_min < y_max");
    scene.rectangle = r;
    scene.n_x = static_cast<int>(domain.integer("n_x", 1, 100000));
    scene.n_y = static_cast<int>(domain.integer("n_y", 1, 100000));
  }
  scene.perturb = domain.number_in("perturb", 0.0, 0.24, 0.0);
  scene.seed = static_cast<std::uint32_t>(domain.integer("seed", 0, 1u << 30, 1));
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
  if (contact_mesh.has("breakpoints"))
    for (const auto& text : contact_mesh.string_list("breakpoints")) {
      char* end = nullptr;
      const double value = std::strtod(text.c_str(), &end);
      if (text.empty() || *end != '\0' || !std::isfinite(value) || value <= 0.0)
        throw_bad_input(path, "contact_mesh.breakpoints", text,
                        "positive arc lengths (numbers), strictly increasing, the last the length of Γ_C");
      scene.breakpoints.push_back(value);
    }
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
  infsup.reject_unknown_keys();
  const auto solve = root.table("solve");
  scene.contact_problem = solve.choice("problem", {"signorini", "friction", "friction_s"}, "signorini");
  // The lower limit p_C + 1 depends on the segment; it is checked when the constraints are built.
  if (solve.has("constraint_points")) scene.constraint_points = static_cast<int>(solve.integer("constraint_points", 1, 64));
  solve.reject_unknown_keys();
  if (scene.problem == "friction" && scene.friction_bound.empty())
    throw_bad_input(path, "data.s", "(missing)", "the friction problem needs the friction bound s");
  root.reject_unknown_keys();
  return scene;
}

mesh::QuadMesh build_scene_mesh(const Scene& scene) {
  mesh::QuadMesh mesh = scene.mesh_file.empty()
                            ? mesh::make_rectangle_mesh(*scene.rectangle, scene.n_x, scene.n_y)
                            : mesh::read_gmsh_mesh(scene.mesh_file);
  if (scene.perturb > 0) mesh::perturb_interior_vertices(mesh, scene.perturb, scene.seed);
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
    throw_bad_input(scene.file, by_groups ? "boundary.contact_groups" : "boundary.contact", value,
                    "it must select at least one boundary edge (Γ_C is empty)");
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

mesh::BoundaryMesh build_scene_boundary_mesh(const Scene& scene, const mesh::ContactBoundary& contact) {
  if (!scene.breakpoints.empty()) {
    auto nodes = scene.breakpoints;
    if (std::abs(nodes.back() - contact.length()) > 1e-10 * contact.length())
      throw_bad_input(scene.file, "contact_mesh.breakpoints", fmt::format("last = {}", nodes.back()),
                      fmt::format("must run from 0 to the length of Γ_C, {}", contact.length()));
    nodes.back() = contact.length();
    return mesh::BoundaryMesh(nodes, scene.file + ": key 'contact_mesh.breakpoints'");
  }
  int m = scene.m;
  if (!scene.ratio.empty()) {
    const int n = static_cast<int>(contact.edges().size());
    const double exact = n * studies::parse_ratio(scene.ratio, scene.file);
    m = static_cast<int>(std::lround(exact));
    if (m < 1 || std::abs(exact - m) > 1e-9 * exact)
      throw_bad_input(scene.file, "contact_mesh.ratio", scene.ratio,
                      fmt::format("Γ_C has {} edges of T_h; {} · ratio = {} must be a whole number of segments", n, n, exact));
  }
  return mesh::BoundaryMesh::graded(contact.length(), m, scene.grading);
}

}  // namespace hpcontact::io
