// The discretization of 3-D scenes: keys, the graded box, boundary parts, rollers, materials, Γ_C and
// T_{C,H}.
#include "driver/solid_scene.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <optional>
#include <set>
#include <tuple>

#include "core/error.hpp"
#include "core/expression.hpp"
#include "driver/solid_pairing.hpp"
#include "mesh/gmsh_surface.hpp"
#include "mesh/rectangle_mesh.hpp"

namespace hpcontact::driver {
namespace {

/// The keys a 3-D scene takes; any other given key is refused rather than ignored.
const std::set<std::string>& solid_scene_keys() {
  static const std::set<std::string> keys{"domain.x_min",
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
                                          "boundary.contact",
                                          "boundary.dirichlet",
                                          "boundary.fixed_x",
                                          "boundary.fixed_y",
                                          "boundary.fixed_z",
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

/// The box, its nodes graded as the rectangle's (towards the planes of grading_x, _y, _z), its
/// boundary faces labelled "contact" and "dirichlet" by the scene's predicates at their centres (Γ_D
/// wins where both hold, as in planar scenes).
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
  mesh::SolidMesh mesh = mesh::make_tensor_box_mesh(nodes, scene.file + ": box");
  const auto label = [&](const std::string& text, const char* key) {
    if (text.empty()) return;
    const Expression predicate(text, scene.where(key) + ": key '" + key + "'", 3);
    mesh.label_boundary_faces([&](const mesh::SolidPoint& x) { return predicate(x(0), x(1), x(2)) != 0.0; },
                              std::string(key) == "boundary.contact" ? "contact" : "dirichlet");
  };
  label(scene.contact_predicate, "boundary.contact");
  label(scene.dirichlet_predicate, "boundary.dirichlet");
  return mesh;
}

/// Per component, the boundary faces whose centre satisfies boundary.fixed_x, _y, _z (rollers).
std::array<std::vector<char>, 3> scene_rollers(const scene::Scene& scene, const mesh::SolidMesh& mesh) {
  std::array<std::vector<char>, 3> held;
  const std::array<std::pair<const std::string*, const char*>, 3> keys{
      {{&scene.fixed_x_predicate, "boundary.fixed_x"},
       {&scene.fixed_y_predicate, "boundary.fixed_y"},
       {&scene.fixed_z_predicate, "boundary.fixed_z"}}};
  for (int c = 0; c < 3; ++c) {
    const auto& [text, key] = keys[c];
    if (text->empty()) continue;
    const Expression predicate(*text, scene.where(key) + ": key '" + key + "'", 3);
    held[c].assign(mesh.n_faces(), 0);
    int flagged = 0;
    for (const auto& face : mesh.boundary_faces()) {
      const int f = mesh.cell_face(face.cell, face.local_face);
      const mesh::SolidPoint x = mesh.face_centre(f);
      held[c][f] = predicate(x(0), x(1), x(2)) != 0.0;
      flagged += held[c][f];
    }
    if (flagged == 0)
      throw_bad_input(scene.where(key), key, "\"" + *text + "\"",
                      "a predicate in x, y, z that holds at the centre of some boundary face");
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
    const mesh::SolidPoint x = mesh.map(c, Eigen::Vector3d::Zero());
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
    for (int v : mesh::kHexFaceVertices[face.local_face]) {
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
      throw_bad_input(scene.where("contact_mesh.ratio"), "contact_mesh.ratio", scene.ratio.front().text,
                      fmt::format("a ratio h/H that makes whole cells of T_{{C,H}} on a uniform Γ_C: Γ_C is {:.6g} "
                                  "trace faces wide along its axis {} (give contact_mesh.m on graded meshes)",
                                  faces, k + 1));
    cells[k] = static_cast<int>(std::lround(wanted));
  }
  return cells;
}

}  // namespace

void check_solid_scene(const scene::Scene& scene, bool needs_effects) {
  for (const auto& key : scene.given)
    if (!solid_scene_keys().contains(key))
      throw_bad_input(scene.where(key), key, "(given)",
                      fmt::format("a key of planar scenes; a 3-D scene (domain.n_z given) takes {}",
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
  if (scene.pair || scene.is_master)
    throw_bad_input(scene.where(scene.n_z > 0 ? "domain.n_z" : "domain.z_nodes"),
                    scene.n_z > 0 ? "domain.n_z" : "domain.z_nodes", "(given)",
                    "a one-body scene: two bodies in contact are planar");
  if (scene.has_effect(scene::Effect::infsup)) check_solid_pairing(scene);  // (before any work)
  if (!scene.contact_mesh_file.empty() && scene.pc.value > 1)
    throw_bad_input(scene.where("discretization.pC"), "discretization.pC", std::to_string(scene.pc.value),
                    "0 or 1 with the triangles of contact_mesh.mesh (P_0 at the centroid, P_1 at the vertices: the "
                    "Lagrange bases whose functions all have positive integrals); higher p_C needs m or ratio");
  if (scene.contact_predicate.empty())
    throw_bad_input(scene.where("boundary.contact"), "boundary.contact", "(missing)", "a predicate in x, y, z");
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
  d->mesh = std::make_unique<mesh::SolidMesh>(scene_box(scene));
  const std::vector<char> dirichlet = space::faces_labelled(*d->mesh, {"dirichlet"});
  const auto rollers = scene.is_elastic() ? scene_rollers(scene, *d->mesh) : std::array<std::vector<char>, 3>{};
  bool held = std::count(dirichlet.begin(), dirichlet.end(), 1) > 0;
  // (an elastic body is held by Γ_D, or by rollers along all three axes)
  held = held || (!rollers[0].empty() && !rollers[1].empty() && !rollers[2].empty());
  if (!held)
    throw_bad_input(scene.where("boundary.dirichlet"), "boundary.dirichlet",
                    scene.dirichlet_predicate.empty() ? "(missing)" : "\"" + scene.dirichlet_predicate + "\"",
                    "a predicate in x, y, z that holds at the centre of some boundary face: without Γ_D the "
                    "problem has no unique solution");
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
