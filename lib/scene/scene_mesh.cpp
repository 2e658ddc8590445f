// Building a scene's meshes and degree distributions: T_h with its boundary parts, p_T per cell,
// p_C per segment and T_{C,H}.
#include "scene/scene_mesh.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <set>

#include "core/error.hpp"
#include "core/expression.hpp"
#include "core/memory_limit.hpp"
#include "mesh/cell_map.hpp"
#include "mesh/contact_boundary.hpp"
#include "mesh/gmsh_reader.hpp"
#include "mesh/point_grading.hpp"
#include "mesh/refine.hpp"

namespace hpcontact::scene {

namespace {

/// Tetrahedra are a box's cells, not a planar domain's.
void refuse_solid_cells(const Scene& scene) {
  if (scene.cells == mesh::GeneratedCells::tetrahedra)
    throw_bad_input(scene.where("domain.cells"), "domain.cells", "tetrahedra",
                    "quadrilaterals or triangles in a planar scene (tetrahedra cut a 3-D box: domain.n_z)");
}

/// The tensor mesh, graded towards the lines of grading_x, grading_y, with a node at every
/// coordinate of the grading points (whose local layers come after).
mesh::Mesh build_rectangle(const Scene& scene) {
  const auto& r = scene.rectangle;
  std::vector<double> point_x, point_y;
  for (const auto& point : scene.grading_points) {
    point_x.push_back(point.x());
    point_y.push_back(point.y());
  }
  mesh::Mesh tensor =
      mesh::make_tensor_mesh(mesh::graded_nodes(r.x_min, r.x_max, scene.n_x, scene.grading_x, scene.domain_grading,
                                                scene.grading_layers, scene.file + ": key 'domain.grading_x'", point_x,
                                                scene.file + ": key 'domain.grading_points' (an x coordinate)"),
                             mesh::graded_nodes(r.y_min, r.y_max, scene.n_y, scene.grading_y, scene.domain_grading,
                                                scene.grading_layers, scene.file + ": key 'domain.grading_y'", point_y,
                                                scene.file + ": key 'domain.grading_points' (a y coordinate)"),
                             scene.file + ": rectangle");
  refuse_solid_cells(scene);
  if (scene.cells == mesh::GeneratedCells::triangles)
    return mesh::split_into_triangles(tensor, {}, scene.file + ": rectangle");
  return tensor;
}

/// Local geometric layers towards the scene's grading points.
mesh::Mesh grade_towards_points(mesh::Mesh mesh, const Scene& scene) {  // by value: ungraded, it is moved out
  if (scene.grading_points.empty()) return mesh;
  const std::string origin = scene.file + ": key 'domain.grading_points'";
  std::vector<int> centres;
  for (const auto& point : scene.grading_points) centres.push_back(mesh::vertex_at(mesh, point, origin));
  return mesh::grade_towards_vertices(mesh, centres, scene.domain_grading, scene.grading_layers, origin);
}

/// How the scene's .geo is meshed, with the most cells that fit in memory at its degree (the
/// estimate of the scene size check: 1.2 KB per unknown, p² unknowns per cell).
mesh::GeoMeshing geo_meshing(const Scene& scene) {
  refuse_solid_cells(scene);
  const double p = scene.p.rule.empty() ? scene.p.value : 1.0;  // a rule: at least degree 1 everywhere
  const MemoryLimit memory = memory_limit();
  return {scene.mesh_size,
          scene.cells,
          memory.bytes / (1.2e3 * p * p),
          scene.where("domain.mesh_size"),
          "domain.mesh_size",
          fmt::format("{}, 1.2 KB per unknown at p = {}", memory.describe(), p)};
}

/// The scene's mesh file with its curves (or without, for geometry = "polygonal").
mesh::Mesh read_mesh_file(const Scene& scene) {
  mesh::Mesh mesh = mesh::read_gmsh_mesh(scene.mesh_file, geo_meshing(scene));
  if (scene.geometry == Scene::Geometry::polygonal) mesh.straighten();
  // Grading and perturbation move or add vertices off the curves.
  if (mesh.has_curved_cells())
    for (const auto& [used, key] :
         {std::pair{!scene.grading_points.empty(), "grading_points"}, std::pair{scene.perturb > 0, "perturb"}})
      if (used)
        throw InputError(
            fmt::format("{}: key 'domain.{}': not available on the curved mesh of {}; refine with "
                        "domain.refinements, or set domain.geometry = \"polygonal\"",
                        scene.file, key, scene.mesh_file));
  return mesh;
}

}  // namespace

mesh::Mesh build_scene_mesh(const Scene& scene) {
  // Planar meshes only: every command that reaches here works on planar discretizations.
  if (scene.dimension() == 3) {
    const std::string key = !scene.is_rectangle() ? "domain.mesh" : scene.n_z > 0 ? "domain.n_z" : "domain.z_nodes";
    throw_bad_input(
        scene.where(key), key, scene.n_z > 0 ? std::to_string(scene.n_z) : "(given)",
        "a planar scene here: 3-D scenes (a box or a Gmsh mesh of hexahedra or tetrahedra) run with `hpcontact solve` "
        "and the effects signorini, "
        "friction, friction_s, frictionless; infsup, sweep, advise and the studies take planar scenes");
  }
  mesh::Mesh mesh =
      grade_towards_points(scene.mesh_file.empty() ? build_rectangle(scene) : read_mesh_file(scene), scene);
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
    const bool contact = mesh.edge_part(e) == mesh::BoundaryPart::contact || by_label.contains(mesh.edge_label(e));
    bool dirichlet = in_dirichlet(mesh.edge_midpoint(e));
    for (const auto& group : scene.dirichlet_groups) dirichlet = dirichlet || mesh.edge_label(e) == group;
    if (contact && dirichlet) {
      const auto m = mesh.edge_midpoint(e);
      throw InputError(
          fmt::format("{}: Γ_C and Γ_D overlap at the edge with midpoint ({}, {}); "
                      "key 'boundary.dirichlet' must exclude Γ_C",
                      scene.file, m.x(), m.y()));
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
    for (int e : mesh.boundary_edges())
      if (!mesh.edge_label(e).empty()) labels.insert(mesh.edge_label(e));
    const std::string groups = labels.empty()
                                   ? std::string(
                                         "the mesh has no named physical group on its boundary: name one in the .geo "
                                         "(Physical Curve(\"contact\") = {...};) or select Γ_C by boundary.contact, a "
                                         "predicate in x, y")
                                   : fmt::format("the mesh has: {}", fmt::join(labels, ", "));
    throw_bad_input(scene.file, by_groups ? "boundary.contact_groups" : "boundary.contact", value,
                    by_groups ? fmt::format("it must name a physical group on the boundary (Γ_C is empty); {}", groups)
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

int whole_degree(const Expression& rule, const mesh::Point& x, int low, int high, const std::string& file,
                 const std::string& key) {
  const double value = rule(x.x(), x.y());
  if (std::abs(value - std::round(value)) > 1e-9 || value < low || value > high)
    throw_bad_input(file, key, fmt::format("{} at ({}, {})", value, x.x(), x.y()),
                    fmt::format("the rule must give whole numbers in [{}, {}]", low, high));
  return static_cast<int>(std::lround(value));
}

}  // namespace

std::array<std::vector<char>, 2> scene_fixed_components(const Scene& scene, const mesh::Mesh& mesh) {
  std::array<std::vector<char>, 2> fixed;
  const std::array<const std::string*, 2> predicates{&scene.fixed_x_predicate, &scene.fixed_y_predicate};
  const std::array<const std::vector<std::string>*, 2> groups{&scene.fixed_x_groups, &scene.fixed_y_groups};
  for (int c = 0; c < 2; ++c) {
    if (predicates[c]->empty() && groups[c]->empty()) continue;
    const std::string key =
        std::string("boundary.fixed_") + (c == 0 ? "x" : "y") + (predicates[c]->empty() ? "_groups" : "");
    std::optional<Expression> predicate;
    if (!predicates[c]->empty()) predicate.emplace(*predicates[c], scene.where(key) + ": key '" + key + "'");
    fixed[c].assign(mesh.n_edges(), 0);
    int selected = 0;
    for (int e : mesh.boundary_edges()) {
      const mesh::Point m = mesh.edge_midpoint(e);
      bool on = predicate && (*predicate)(m.x(), m.y()) != 0.0;
      for (const auto& group : *groups[c]) on = on || mesh.edge_label(e) == group;
      if (!on) continue;
      if (mesh.edge_part(e) != mesh::BoundaryPart::neumann)
        throw_bad_input(scene.where(key), key, fmt::format("(the edge with midpoint ({}, {}))", m.x(), m.y()),
                        fmt::format("edges outside Γ_C and Γ_D (this one is {})", mesh::to_string(mesh.edge_part(e))));
      fixed[c][e] = 1;
      ++selected;
    }
    if (selected == 0)
      throw_bad_input(scene.where(key), key,
                      predicates[c]->empty() ? fmt::format("{}", fmt::join(*groups[c], ", ")) : *predicates[c],
                      "it must select at least one boundary edge");
  }
  return fixed;
}

std::vector<int> scene_cell_degrees(const Scene& scene, const mesh::Mesh& mesh) {
  if (scene.p.rule.empty()) return std::vector<int>(mesh.n_cells(), scene.p.value);
  const Expression rule(scene.p.rule, scene.where("discretization.p") + ": key 'discretization.p'");
  std::vector<int> degrees(mesh.n_cells());
  for (int c = 0; c < mesh.n_cells(); ++c)
    degrees[c] = whole_degree(rule, mesh::CellMap(mesh, c).map(0.0, 0.0), 1, 20, scene.where("discretization.p"),
                              "discretization.p");
  return degrees;
}

std::vector<int> scene_trace_degrees(const Scene& scene, const mesh::ContactBoundary& contact) {
  const auto cell_degrees = scene_cell_degrees(scene, contact.mesh());
  std::vector<int> degrees;
  for (const auto& edge : contact.edges()) degrees.push_back(cell_degrees[edge.cell]);
  return degrees;
}

std::vector<int> scene_segment_degrees(const Scene& scene, const mesh::ContactBoundary& contact,
                                       const mesh::BoundaryMesh& boundary_mesh) {
  std::vector<int> degrees(boundary_mesh.n_segments(), scene.pc.value);
  if (!scene.pc.rule.empty()) {
    const Expression rule(scene.pc.rule, scene.where("discretization.pC") + ": key 'discretization.pC'");
    for (int k = 0; k < boundary_mesh.n_segments(); ++k)
      degrees[k] =
          whole_degree(rule, contact.point_at(0.5 * (boundary_mesh.segment_begin(k) + boundary_mesh.segment_end(k))), 0,
                       19, scene.where("discretization.pC"), "discretization.pC");
  }
  return degrees;
}

void check_family_fits(const Scene& scene, const mesh::BoundaryMesh& boundary_mesh,
                       const std::vector<int>& segment_degrees) {
  if (scene.family.kind == space::MultiplierFamilyKind::discontinuous) return;
  const std::string family = space::to_string(scene.family);
  // The standard and dual families are continuous or dual to a continuous space: p_C ≥ 1.
  for (int k = 0; k < boundary_mesh.n_segments(); ++k)
    if (segment_degrees[k] < 1)
      throw_bad_input(scene.where("discretization.pC"), "discretization.pC", std::to_string(segment_degrees[k]),
                      fmt::format("at least 1 with contact_mesh.family = \"{}\" (segment {} of T_{{C,H}})", family, k));
  if (!scene.family.end_modification) return;
  // The end modification drops both end nodes of an open zone: one segment of p_C = 1 keeps none.
  for (int k = 0; k < boundary_mesh.n_segments(); ++k) {
    const int zone = boundary_mesh.zone_of_segment(k);
    const auto& z = boundary_mesh.zones()[zone];
    if (!z.closed && boundary_mesh.segment_begin(k) == z.begin && boundary_mesh.segment_end(k) == z.end &&
        segment_degrees[k] == 1)
      throw_bad_input(
          scene.where("contact_mesh.family"), "contact_mesh.family", family,
          fmt::format("a family without the end modification here: zone {} of Γ_C is one segment of T_{{C,H}} "
                      "with p_C = 1, whose two end nodes the modification drops (or more segments, p_C >= 2)",
                      zone));
  }
}

namespace {

/// Indices k of the trace vertices s_k (first < k ≤ last, last always included) of one zone that
/// are grading points, or at which Γ_C meets one of the scene's grading lines x = c or y = c at an
/// isolated vertex: the singular points the mesh is graded towards. A line Γ_C runs along (grading
/// towards Γ_C itself) marks none of its vertices.
std::vector<int> grading_nodes_on_contact(const Scene& scene, const mesh::ContactBoundary& contact, int first,
                                          int last) {
  const auto s = contact.breakpoints();
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
  for (int k = first + 1; k < last; ++k)
    if (a_grading_point(k) || meets_a_line(k)) nodes.push_back(k);
  nodes.push_back(last);
  return nodes;
}

/// The breakpoints of T_{C,H} after the start of `zone` (its end last) for a ratio h/H: on a
/// uniform T_h|zone m = n · ratio equal segments; on a graded one T_{C,H} follows T_h: ratio 1/k
/// merges k neighbouring edges (the last segment also takes the n mod k left over), ratio k splits
/// every edge in k.
std::vector<double> zone_nodes_by_ratio(const Scene& scene, const mesh::ContactBoundary& contact, int zone_index) {
  const mesh::ContactZone& zone = contact.zones()[static_cast<std::size_t>(zone_index)];
  const Ratio& given =
      scene.of_zone(scene.ratio, zone_index, static_cast<int>(contact.zones().size()), "contact_mesh.ratio");
  const auto edges = contact.breakpoints();
  const int first = zone.first_edge, n = zone.end_edge - zone.first_edge;
  const double ratio = given.value, length = zone.length();
  const std::string ratio_where = scene.where("contact_mesh.ratio");
  bool uniform = true;
  for (int e = first; e < zone.end_edge; ++e)
    uniform = uniform && std::abs(edges[e + 1] - edges[e] - length / n) < 1e-9 * length / n;
  std::vector<double> nodes;
  if (uniform) {
    const double exact = n * ratio;
    const int m = static_cast<int>(std::lround(exact));
    if (m < 1 || std::abs(exact - m) > 1e-9 * exact)
      throw_bad_input(
          ratio_where, "contact_mesh.ratio", given.text,
          fmt::format("a zone of Γ_C has {} edges of T_h; {} · ratio = {} must be a whole number of segments", n, n,
                      exact));
    const auto graded = mesh::BoundaryMesh::graded(length, m, scene.grading).nodes();
    for (std::size_t k = 1; k < graded.size(); ++k) nodes.push_back(zone.s_begin + graded[k]);
    return nodes;
  }
  const long merge = std::lround(1.0 / ratio), divide = std::lround(ratio);
  if (merge >= 1 && std::abs(merge * ratio - 1.0) < 1e-9 && n >= merge) {
    // Groups of k edges within each run between grading nodes, so that the singular points the
    // mesh is graded towards stay breakpoints of T_{C,H} (a segment straddling the end of a
    // contact set cannot represent λ's square-root onset); a run's last segment also takes the
    // edges left over, a run shorter than k is one segment.
    int run_begin = first;
    for (int run_end : grading_nodes_on_contact(scene, contact, first, zone.end_edge)) {
      const int run = run_end - run_begin, groups = std::max(1, run / static_cast<int>(merge));
      for (int g = 1; g < groups; ++g) nodes.push_back(edges[run_begin + g * static_cast<int>(merge)]);
      nodes.push_back(edges[run_end]);
      run_begin = run_end;
    }
  } else if (divide >= 1 && std::abs(ratio - static_cast<double>(divide)) < 1e-9) {
    for (int e = first; e < zone.end_edge; ++e)
      for (long i = 1; i <= divide; ++i) nodes.push_back(edges[e] + (edges[e + 1] - edges[e]) * i / divide);
  } else {
    throw_bad_input(
        ratio_where, "contact_mesh.ratio", given.text,
        fmt::format("T_h is not uniform on a zone of Γ_C ({} edges): the ratio must be 1/k with k <= {}, or a whole "
                    "number",
                    n, n));
  }
  return nodes;
}

/// The scene's explicit breakpoints, with every zone's end added (a segment cannot span two zones).
std::vector<double> given_breakpoints(const Scene& scene, const mesh::ContactBoundary& contact) {
  auto given = scene.breakpoints;
  if (std::abs(given.back() - contact.length()) > 1e-10 * contact.length())
    throw_bad_input(scene.file, "contact_mesh.breakpoints", fmt::format("last = {}", given.back()),
                    fmt::format("must run from 0 to the length of Γ_C, {}", contact.length()));
  given.back() = contact.length();
  given.insert(given.begin(), 0.0);
  std::vector<double> zone_ends{0.0};
  for (const auto& zone : contact.zones()) zone_ends.push_back(zone.s_end);
  return mesh::common_refinement(given, zone_ends);
}

}  // namespace

mesh::BoundaryMesh build_scene_boundary_mesh(const Scene& scene, const mesh::ContactBoundary& contact) {
  int split = 1 << scene.refinements;  // segments per given segment after the scene's refinements
  std::vector<double> coarse{0.0};
  std::string origin;
  if (!scene.breakpoints.empty()) {
    coarse = given_breakpoints(scene, contact);
    origin = scene.file + ": key 'contact_mesh.breakpoints'";
  } else {
    const int n_zones = static_cast<int>(contact.zones().size());
    for (int z = 0; z < n_zones; ++z) {
      const auto& zone = contact.zones()[static_cast<std::size_t>(z)];
      if (!scene.ratio.empty()) {
        for (double s : zone_nodes_by_ratio(scene, contact, z)) coarse.push_back(s);
        continue;
      }
      // m segments per zone (m · 2^refinements after refinements), graded towards its ends.
      const int m = scene.of_zone(scene.m, z, n_zones, "contact_mesh.m");
      const auto graded = mesh::BoundaryMesh::graded(zone.length(), m * split, scene.grading).nodes();
      for (std::size_t k = 1; k < graded.size(); ++k) coarse.push_back(zone.s_begin + graded[k]);
    }
    split = 1;  // the ratio follows the refined T_h; m was multiplied above
    origin = !scene.ratio.empty() ? scene.where("contact_mesh.ratio") + ": key 'contact_mesh.ratio'"
                                  : scene.file + ": key 'contact_mesh.m'";
  }
  std::vector<double> nodes{0.0};
  for (std::size_t k = 0; k + 1 < coarse.size(); ++k)
    for (int i = 1; i <= split; ++i) nodes.push_back(coarse[k] + (coarse[k + 1] - coarse[k]) * i / split);
  nodes.back() = contact.length();
  mesh::BoundaryMesh boundary_mesh(nodes, origin);
  boundary_mesh.set_zones(contact.boundary_zones(), origin);
  return boundary_mesh;
}

}  // namespace hpcontact::scene
