// The discretization of 3-D scenes: keys, the graded box or the Gmsh mesh of hexahedra, boundary
// parts, rollers, materials, Γ_C and T_{C,H}.
#include "driver/solid_scene.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <tuple>

#include "core/error.hpp"
#include "core/expression.hpp"
#include "core/memory_limit.hpp"
#include "driver/solid_pairing.hpp"
#include "mesh/gmsh_solid_reader.hpp"
#include "mesh/gmsh_surface.hpp"
#include "mesh/rectangle_mesh.hpp"

namespace hpcontact::driver {
namespace {

/// The keys a 3-D scene takes; any other given key is refused rather than ignored.
const std::set<std::string>& solid_scene_keys() {
  static const std::set<std::string> keys{"domain.cells",
                                          "domain.x_min",
                                          "domain.x_max",
                                          "domain.y_min",
                                          "domain.y_max",
                                          "domain.z_min",
                                          "domain.z_max",
                                          "domain.n_x",
                                          "domain.n_y",
                                          "domain.n_z",
                                          "domain.grading_x",
                                          "domain.grading_y",
                                          "domain.grading_z",
                                          "domain.grading",
                                          "domain.grading_layers",
                                          "domain.x_nodes",
                                          "domain.y_nodes",
                                          "domain.z_nodes",
                                          "domain.mesh",
                                          "domain.mesh_size",
                                          "boundary.contact",
                                          "boundary.dirichlet",
                                          "boundary.contact_groups",
                                          "boundary.dirichlet_groups",
                                          "boundary.fixed_x",
                                          "boundary.fixed_y",
                                          "boundary.fixed_z",
                                          "boundary.fixed_x_groups",
                                          "boundary.fixed_y_groups",
                                          "boundary.fixed_z_groups",
                                          "contact_mesh.m",
                                          "contact_mesh.ratio",
                                          "contact_mesh.mesh",
                                          "contact_mesh.mesh_size",
                                          "discretization.p",
                                          "discretization.pC",
                                          "infsup.norm",
                                          "infsup.problem",
                                          "infsup.alpha_tol",
                                          "infsup.operator",
                                          "data.f",
                                          "data.g",
                                          "data.s",
                                          "data.friction_coefficient",
                                          "data.f_x",
                                          "data.f_y",
                                          "data.f_z",
                                          "material.E",
                                          "material.nu",
                                          "solve.trace_operator",
                                          "run.effects",
                                          "run.outputs"};
  return keys;
}

/// The box, its nodes graded as the rectangle's (towards the planes of grading_x, _y, _z), cut into
/// hexahedra or (domain.cells) tetrahedra, its boundary faces labelled by side.
mesh::SolidMesh scene_box(const scene::Scene& scene) {
  const auto& r = scene.rectangle;
  const std::array<std::tuple<double, double, int, const std::vector<double>*, const char*>, 3> axes{
      {{r.x_min, r.x_max, scene.n_x, &scene.grading_x, "domain.grading_x"},
       {r.y_min, r.y_max, scene.n_y, &scene.grading_y, "domain.grading_y"},
       {scene.z_min, scene.z_max, scene.n_z, &scene.grading_z, "domain.grading_z"}}};
  std::array<std::vector<double>, 3> nodes;
  for (int k = 0; k < 3; ++k) {
    const auto& [low, high, n, grading, key] = axes[k];
    nodes[k] = !scene.box_nodes[k].empty()
                   ? scene.box_nodes[k]
                   : mesh::graded_nodes(low, high, n, *grading, scene.domain_grading, scene.grading_layers,
                                        scene.where(key) + ": key '" + key + "'");
  }
  if (scene.cells == mesh::GeneratedCells::triangles)
    throw_bad_input(scene.where("domain.cells"), "domain.cells", "triangles",
                    "hexahedra (the default) or tetrahedra in a 3-D box");
  if (scene.cells == mesh::GeneratedCells::tetrahedra)
    return mesh::make_tetrahedral_box_mesh(nodes, scene.file + ": box");
  return mesh::make_tensor_box_mesh(nodes, scene.file + ": box");
}

/// The hexahedra or tetrahedra of domain.mesh, its boundary faces labelled by physical surface; a .geo meshed
/// with at most the cells that fit at the scene's degree (17.5 KB per unknown, as the box's size
/// check, three unknowns per node of an elastic body).
mesh::SolidMesh scene_gmsh_mesh(const scene::Scene& scene) {
  // (a 3-D .geo's cells are its own settings' business; a key that would not change them is refused)
  if (scene.cells != mesh::GeneratedCells::quadrilaterals)
    throw_bad_input(scene.where("domain.cells"), "domain.cells",
                    scene.cells == mesh::GeneratedCells::triangles ? "triangles" : "tetrahedra",
                    "no value with a 3-D Gmsh mesh: its own settings decide its cells (tetrahedra by default; "
                    "Recombine or Mesh.SubdivisionAlgorithm = 2 for hexahedra)");
  const MemoryLimit memory = memory_limit();
  const double per_cell = std::pow(scene.p.value, 3) * (scene.is_elastic() ? 3.0 : 1.0);
  mesh::GeoMeshing geo{scene.mesh_size,
                       mesh::GeneratedCells::quadrilaterals,
                       memory.bytes / (17.5e3 * per_cell),
                       scene.where("domain.mesh_size"),
                       "domain.mesh_size",
                       fmt::format("{}, 17.5 KB per unknown at p = {}", memory.describe(), scene.p.value)};
  try {
    return mesh::read_gmsh_solid_mesh(scene.mesh_file, geo);
  } catch (const InputError& error) {
    const std::string text = error.what();
    if (text.find("domain.mesh_size") != std::string::npos) throw;
    throw InputError(scene.where("domain.mesh") + ": key 'domain.mesh': " + text);
  }
}

/// A part of the boundary: the faces whose centre satisfies `predicate` (key `key`) or whose
/// label is one of `groups` (key `key`_groups), per boundary face (in boundary_faces() order).
/// @throws InputError naming the groups' key if none of them labels a face.
std::vector<char> boundary_part(const scene::Scene& scene, const mesh::SolidMesh& mesh, const std::string& predicate,
                                const std::vector<std::string>& groups, const std::string& key) {
  const auto& faces = mesh.boundary_faces();
  std::vector<char> in(faces.size(), 0);
  if (!predicate.empty()) {
    const Expression expression(predicate, scene.where(key) + ": key '" + key + "'", 3);
    for (std::size_t k = 0; k < faces.size(); ++k) {
      const mesh::SolidPoint x = mesh.face_centre(mesh.cell_face(faces[k].cell, faces[k].local_face));
      in[k] = expression(x(0), x(1), x(2)) != 0.0;
    }
  }
  if (groups.empty()) return in;
  std::set<std::string> labels, found;
  for (std::size_t k = 0; k < faces.size(); ++k) {
    const bool listed = std::find(groups.begin(), groups.end(), faces[k].label) != groups.end();
    if (listed) found.insert(faces[k].label);
    in[k] = in[k] || listed;
    if (!faces[k].label.empty()) labels.insert(faces[k].label);
  }
  // Each name must label a face: a misspelt one beside a right one would drop its faces unseen.
  for (const std::string& group : groups)
    if (!found.contains(group))
      throw_bad_input(scene.where(key + "_groups"), key + "_groups", "\"" + group + "\"",
                      labels.empty()
                          ? std::string("physical surfaces of the mesh, which has none: name them in the .geo "
                                        "(Physical Surface(\"contact\") = {...};)")
                          : fmt::format("physical surfaces of the mesh: {}", fmt::join(labels, ", ")));
  return in;
}

/// Labels Γ_C "contact" and Γ_D "dirichlet" by the scene's predicates and groups; other faces
/// keep their labels, except that a physical surface named "contact" or "dirichlet" is a part only
/// when the scene selects it. @throws InputError if Γ_C and Γ_D share a face (as planar scenes:
/// Γ_D would silently take part of Γ_C).
void label_contact_and_dirichlet(const scene::Scene& scene, mesh::SolidMesh& mesh) {
  const std::vector<char> contact =
      boundary_part(scene, mesh, scene.contact_predicate, scene.contact_groups, "boundary.contact");
  const std::vector<char> dirichlet =
      boundary_part(scene, mesh, scene.dirichlet_predicate, scene.dirichlet_groups, "boundary.dirichlet");
  for (std::size_t k = 0; k < contact.size(); ++k) {
    const auto& face = mesh.boundary_faces()[k];
    if (contact[k] && dirichlet[k]) {
      const mesh::SolidPoint x = mesh.face_centre(mesh.cell_face(face.cell, face.local_face));
      throw InputError(
          fmt::format("{}: Γ_C and Γ_D overlap at the face centred at ({}, {}, {}); boundary.dirichlet "
                      "(and dirichlet_groups) must exclude Γ_C",
                      scene.file, x(0), x(1), x(2)));
    }
    const bool reserved = face.label == "contact" || face.label == "dirichlet";
    mesh.set_boundary_face_label(k, dirichlet[k] ? "dirichlet" : contact[k] ? "contact" : reserved ? "" : face.label);
  }
}

/// Per component, the boundary faces on boundary.fixed_x, _y, _z or their groups (rollers), by
/// face number.
std::array<std::vector<char>, 3> scene_rollers(const scene::Scene& scene, const mesh::SolidMesh& mesh) {
  std::array<std::vector<char>, 3> held;
  const std::array<std::tuple<const std::string*, const std::vector<std::string>*, const char*>, 3> keys{
      {{&scene.fixed_x_predicate, &scene.fixed_x_groups, "boundary.fixed_x"},
       {&scene.fixed_y_predicate, &scene.fixed_y_groups, "boundary.fixed_y"},
       {&scene.fixed_z_predicate, &scene.fixed_z_groups, "boundary.fixed_z"}}};
  for (int c = 0; c < 3; ++c) {
    const auto& [text, groups, key] = keys[c];
    if (text->empty() && groups->empty()) continue;
    const std::vector<char> part = boundary_part(scene, mesh, *text, *groups, key);
    if (std::count(part.begin(), part.end(), 1) == 0)
      throw_bad_input(scene.where(key), key, "\"" + *text + "\"",
                      "a predicate in x, y, z that holds at the centre of some boundary face");
    held[c].assign(mesh.n_faces(), 0);
    for (std::size_t k = 0; k < part.size(); ++k) {
      const auto& face = mesh.boundary_faces()[k];
      held[c][mesh.cell_face(face.cell, face.local_face)] = part[k];
    }
  }
  return held;
}

/// Lamé parameters per cell from material.E and material.nu at the cell centres (the plane-strain
/// formulas are those of 3-D elasticity).
std::vector<assembly::Material> scene_materials(const scene::Scene& scene, const mesh::SolidMesh& mesh) {
  const Expression young(scene.young, scene.where("material.E") + ": key 'material.E'", 3);
  const Expression poisson(scene.poisson, scene.where("material.nu") + ": key 'material.nu'", 3);
  std::vector<assembly::Material> materials;
  materials.reserve(mesh.n_cells());
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const mesh::SolidPoint x = mesh.cell_centre(c);
    materials.push_back(
        assembly::lame_parameters(young(x(0), x(1), x(2)), poisson(x(0), x(1), x(2)), assembly::PlaneModel::strain));
  }
  return materials;
}

/// The cells of T_{C,H} along Γ_C's two in-plane axes: contact_mesh.m (one value for both axes,
/// or two), or the trace faces along each axis times contact_mesh.ratio (h/H), which must give
/// whole numbers (Γ_C uniform along the axis: its width over a face's).
std::array<int, 2> multiplier_cells(const scene::Scene& scene, const mesh::FlatContactSurface& surface) {
  if (scene.ratio.empty()) {  // (a scene gives one of m and ratio; a sweep's ratio replaces m)
    if (scene.m.empty() || scene.m.size() > 2)
      throw_bad_input(scene.where("contact_mesh.m"), "contact_mesh.m", fmt::format("{}", fmt::join(scene.m, ", ")),
                      "one or two integers in a 3-D scene: the cells of T_{C,H} along Γ_C's two axes");
    return {scene.m.front(), scene.m.back()};
  }
  if (scene.ratio.size() != 1)
    throw_bad_input(scene.where("contact_mesh.ratio"), "contact_mesh.ratio", "(a list)",
                    "one ratio h/H in a 3-D scene");
  // The faces' extents along Γ_C's axes: all equal on a uniform Γ_C, which the ratio needs.
  const mesh::SolidMesh& mesh = surface.mesh();
  std::optional<Eigen::Vector2d> extent;
  bool uniform = true;
  for (const auto& face : surface.faces()) {
    Eigen::Vector2d low = Eigen::Vector2d::Constant(INFINITY), high = -low;
    for (int v : mesh.local_face_vertices(face.local_face)) {
      const Eigen::Vector2d a = surface.to_plane(mesh.vertex(mesh.cell(face.cell)[v]));
      low = low.cwiseMin(a);
      high = high.cwiseMax(a);
    }
    if (!extent) extent = high - low;
    uniform = uniform && ((high - low) - *extent).lpNorm<Eigen::Infinity>() <= 1e-9 * extent->maxCoeff();
  }
  std::array<int, 2> cells{};
  for (int k = 0; k < 2; ++k) {
    const double faces = (surface.bounds()[1](k) - surface.bounds()[0](k)) / (*extent)(k);
    const double wanted = std::round(faces) * scene.ratio.front().value;
    if (!uniform || std::abs(faces - std::round(faces)) > 1e-6 || std::abs(wanted - std::round(wanted)) > 1e-9 ||
        std::round(wanted) < 1)
      throw_bad_input(
          scene.where("contact_mesh.ratio"), "contact_mesh.ratio", scene.ratio.front().text,
          fmt::format("a ratio h/H that makes whole cells of T_{{C,H}} on a uniform Γ_C: Γ_C is {:.6g} "
                      "trace faces wide along its axis {} (give contact_mesh.m on graded or unstructured meshes)",
                      faces, k + 1));
    cells[k] = static_cast<int>(std::lround(wanted));
  }
  return cells;
}

}  // namespace

void check_solid_scene(const scene::Scene& scene, bool needs_effects) {
  for (const auto& key : scene.given)
    if (!solid_scene_keys().contains(key))
      throw_bad_input(
          scene.where(key), key, "(given)",
          fmt::format("a key of planar scenes; a 3-D scene (a box, or a Gmsh mesh of hexahedra or tetrahedra) takes {}",
                      fmt::join(solid_scene_keys(), ", ")));
  for (const auto effect : scene.effects)
    if (effect != scene::Effect::signorini && effect != scene::Effect::friction &&
        effect != scene::Effect::friction_s && effect != scene::Effect::frictionless &&
        effect != scene::Effect::tresca && effect != scene::Effect::coulomb && effect != scene::Effect::infsup)
      throw_bad_input(scene.where("run.effects"), "run.effects", scene::to_string(effect),
                      "signorini, friction or friction_s (scalar), frictionless, tresca or coulomb (elastic), or "
                      "infsup (α of the pairing) in a 3-D scene");
  if (scene.effects.empty() && needs_effects)
    throw_bad_input(scene.where("run.effects"), "run.effects", "(none)",
                    "at least one of signorini, friction, friction_s, frictionless, tresca, coulomb, infsup");
  if (scene.pair || scene.is_master) {
    const std::string key = !scene.is_rectangle() ? "domain.mesh" : scene.n_z > 0 ? "domain.n_z" : "domain.z_nodes";
    throw_bad_input(scene.where(key), key, "(given)", "a one-body scene: two bodies in contact are planar");
  }
  if (scene.has_effect(scene::Effect::infsup)) check_solid_pairing(scene);  // (before any work)
  if (!scene.contact_mesh_file.empty() && scene.pc.value > 1)
    throw_bad_input(scene.where("discretization.pC"), "discretization.pC", std::to_string(scene.pc.value),
                    "0 or 1 with the triangles of contact_mesh.mesh (P_0 at the centroid, P_1 at the vertices: the "
                    "Lagrange bases whose functions all have positive integrals); higher p_C needs m or ratio");
  if (scene.contact_predicate.empty() && scene.contact_groups.empty())
    throw_bad_input(scene.where("boundary.contact"), "boundary.contact", "(missing)",
                    "a predicate in x, y, z, or boundary.contact_groups on a Gmsh mesh");
  if (!scene.p.rule.empty() || !scene.pc.rule.empty())
    throw_bad_input(scene.where(scene.p.rule.empty() ? "discretization.pC" : "discretization.p"),
                    scene.p.rule.empty() ? "discretization.pC" : "discretization.p",
                    scene.p.rule.empty() ? scene.pc.rule : scene.p.rule, "an integer in a 3-D scene");
}

assembly::SolidFunction solid_scene_function(const scene::Scene& scene, const std::string& text, const char* key) {
  if (text.empty()) return {};
  const Expression expression(text, scene.where(key) + ": key '" + key + "'", 3);
  return [expression](const mesh::SolidPoint& x) { return expression(x(0), x(1), x(2)); };
}

contact::SolidElasticSetup solid_elastic_setup(const scene::Scene& scene, const SolidDiscretization& d,
                                               scene::Effect effect) {
  contact::SolidElasticSetup setup;
  setup.space = d.vector_space.get();
  setup.multipliers = d.multipliers.get();
  setup.materials = d.materials;
  setup.trace_solve = scene.trace_solve;
  setup.body_force = {solid_scene_function(scene, scene.body_force_x, "data.f_x"),
                      solid_scene_function(scene, scene.body_force_y, "data.f_y"),
                      solid_scene_function(scene, scene.body_force_z, "data.f_z")};
  setup.gap = solid_scene_function(scene, scene.obstacle, "data.g");
  if (!setup.gap) throw_bad_input(scene.where("data.g"), "data.g", "(missing)", "the gap to the obstacle along n");
  if (effect == scene::Effect::tresca) {
    setup.threshold = solid_scene_function(scene, scene.friction_bound, "data.s");
    if (!setup.threshold)
      throw_bad_input(scene.where("data.s"), "data.s", "(missing)", "Tresca's threshold s ≥ 0 (effect tresca)");
  }
  if (effect == scene::Effect::coulomb) setup.friction_coefficient = scene.friction_coefficient;
  return setup;
}

std::unique_ptr<mesh::SurfaceMultiplierMesh> solid_multiplier_mesh(const scene::Scene& scene,
                                                                   const mesh::FlatContactSurface& surface) {
  if (!scene.contact_mesh_file.empty()) {
    // Gmsh meshes for minutes before it fails on a size that would not fit: refused before, at
    // about 2.3 triangles per size² (the planar meshes' measured density) and 1e6 triangles.
    const double estimate =
        scene.contact_mesh_size ? 2.3 * surface.area() / std::pow(*scene.contact_mesh_size, 2) : 0.0;
    if (estimate > 1e6)
      throw_bad_input(scene.where("contact_mesh.mesh_size"), "contact_mesh.mesh_size",
                      fmt::format("{}", *scene.contact_mesh_size),
                      fmt::format("a size that gives at most 1e6 triangles on Γ_C (area {:.6g}): at least {:.3g}",
                                  surface.area(), std::sqrt(2.3 * surface.area() / 1e6)));
    mesh::SurfaceTriangles read;
    try {
      read = mesh::read_gmsh_surface_triangles(scene.contact_mesh_file, scene.contact_mesh_size);
    } catch (const InputError& error) {
      throw InputError(scene.where("contact_mesh.mesh") + ": key 'contact_mesh.mesh': " + error.what());
    }
    const auto& [vertices, triangles] = read;
    return std::make_unique<mesh::SurfaceMultiplierMesh>(
        surface, vertices, triangles,
        scene.where("contact_mesh.mesh") + ": key 'contact_mesh.mesh' (" + scene.contact_mesh_file + ")");
  }
  return std::make_unique<mesh::SurfaceMultiplierMesh>(surface, multiplier_cells(scene, surface),
                                                       scene.where("boundary.contact") + ": key 'boundary.contact'");
}

std::unique_ptr<SolidDiscretization> discretize_solid_scene(const scene::Scene& scene, bool multipliers) {
  auto d = std::make_unique<SolidDiscretization>();
  d->mesh = std::make_unique<mesh::SolidMesh>(scene.is_rectangle() ? scene_box(scene) : scene_gmsh_mesh(scene));
  // (rollers first: their groups are physical surfaces, whose labels Γ_C and Γ_D replace)
  const auto rollers = scene.is_elastic() ? scene_rollers(scene, *d->mesh) : std::array<std::vector<char>, 3>{};
  label_contact_and_dirichlet(scene, *d->mesh);
  const std::vector<char> dirichlet = space::faces_labelled(*d->mesh, {"dirichlet"});
  bool held = std::count(dirichlet.begin(), dirichlet.end(), 1) > 0;
  // (an elastic body is held by Γ_D, or by rollers along all three axes)
  held = held || (!rollers[0].empty() && !rollers[1].empty() && !rollers[2].empty());
  if (!held)
    throw_bad_input(scene.where("boundary.dirichlet"), "boundary.dirichlet",
                    scene.dirichlet_predicate.empty() ? "(missing)" : "\"" + scene.dirichlet_predicate + "\"",
                    "a predicate in x, y, z that holds at the centre of some boundary face, or "
                    "boundary.dirichlet_groups: without Γ_D the problem has no unique solution");
  d->space =
      std::make_unique<space::SolidH1Space>(*d->mesh, std::vector<int>(d->mesh->n_cells(), scene.p.value), dirichlet);
  if (scene.is_elastic()) {
    d->vector_space = std::make_unique<space::SolidVectorSpace>(*d->space, rollers);
    d->materials = scene_materials(scene, *d->mesh);
  }
  const std::string origin = scene.where("boundary.contact") + ": key 'boundary.contact'";
  d->surface = std::make_unique<mesh::FlatContactSurface>(*d->mesh, std::vector<std::string>{"contact"}, origin);
  if (!multipliers) return d;
  d->multiplier_mesh = solid_multiplier_mesh(scene, *d->surface);
  d->multipliers = std::make_unique<space::SurfaceMultiplierSpace>(*d->multiplier_mesh, scene.pc.value);
  return d;
}

}  // namespace hpcontact::driver
