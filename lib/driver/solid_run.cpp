// The 3-D run: box mesh, boundary parts from the scene's predicates, Γ_C and T_{C,H}, the contact
// problems, their samples and files.
#include "driver/solid_run.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <set>

#include "assembly/surface_coupling.hpp"
#include "basis/quadrature.hpp"
#include "contact/solid_contact.hpp"
#include "core/error.hpp"
#include "core/expression.hpp"
#include "core/interrupt.hpp"
#include "core/petsc_session.hpp"
#include "core/timer.hpp"
#include "driver/run_outputs.hpp"
#include "driver/summary_json.hpp"
#include "io/atomic_file.hpp"
#include "mesh/contact_surface.hpp"
#include "postprocess/solid_field.hpp"
#include "space/solid_space.hpp"
#include "space/surface_multiplier_space.hpp"

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
                                          "boundary.contact",
                                          "boundary.dirichlet",
                                          "contact_mesh.m",
                                          "contact_mesh.ratio",
                                          "discretization.p",
                                          "discretization.pC",
                                          "data.f",
                                          "data.g",
                                          "data.s",
                                          "run.effects",
                                          "run.outputs"};
  return keys;
}

void check_solid_scene(const scene::Scene& scene, const SceneRunOptions& options) {
  for (const auto& key : scene.given)
    if (!solid_scene_keys().contains(key))
      throw_bad_input(scene.where(key), key, "(given)",
                      fmt::format("a key of planar scenes; a 3-D scene (domain.n_z given) takes {}",
                                  fmt::join(solid_scene_keys(), ", ")));
  for (const auto effect : scene.effects)
    if (effect != scene::Effect::signorini && effect != scene::Effect::friction && effect != scene::Effect::friction_s)
      throw_bad_input(scene.where("run.effects"), "run.effects", scene::to_string(effect),
                      "signorini, friction or friction_s in a 3-D scene");
  if (scene.effects.empty())
    throw_bad_input(scene.where("run.effects"), "run.effects", "(none)",
                    "at least one of signorini, friction, friction_s");
  if (options.distribution.distributed())
    throw InputError(scene.file + ": 3-D scenes run on one process: run `hpcontact solve` without mpirun");
  if (scene.contact_predicate.empty())
    throw_bad_input(scene.where("boundary.contact"), "boundary.contact", "(missing)", "a predicate in x, y, z");
}

/// The box with its boundary faces labelled "contact" and "dirichlet" by the scene's predicates at
/// their centres (Γ_D wins where both hold, as in planar scenes).
mesh::SolidMesh scene_box(const scene::Scene& scene) {
  const auto& r = scene.rectangle;
  mesh::SolidMesh mesh =
      mesh::make_box_mesh(Eigen::Vector3d(r.x_min, r.y_min, scene.z_min),
                          Eigen::Vector3d(r.x_max, r.y_max, scene.z_max), {scene.n_x, scene.n_y, scene.n_z});
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

/// The cells of T_{C,H} along Γ_C's two in-plane axes: contact_mesh.m (one value for both axes,
/// or two), or the trace faces along each axis times contact_mesh.ratio (h/H), which must give
/// whole numbers.
std::array<int, 2> multiplier_cells(const scene::Scene& scene, const mesh::FlatContactSurface& surface) {
  if (scene.given.contains("contact_mesh.m")) {
    if (scene.m.size() > 2)
      throw_bad_input(scene.where("contact_mesh.m"), "contact_mesh.m", fmt::format("{}", fmt::join(scene.m, ", ")),
                      "one or two integers in a 3-D scene: the cells of T_{C,H} along Γ_C's two axes");
    return {scene.m.front(), scene.m.back()};
  }
  if (scene.ratio.size() != 1)
    throw_bad_input(scene.where("contact_mesh.ratio"), "contact_mesh.ratio", "(a list)",
                    "one ratio h/H in a 3-D scene");
  // Trace faces along each axis: Γ_C is a grid of the box's faces, so its width over a face's.
  const mesh::BoundaryFace& face = surface.faces().front();
  const mesh::SolidMesh& mesh = surface.mesh();
  Eigen::Vector2d low = Eigen::Vector2d::Constant(INFINITY), high = -low;
  for (int v : mesh::kHexFaceVertices[face.local_face]) {
    const Eigen::Vector2d a = surface.to_plane(mesh.vertex(mesh.cell(face.cell)[v]));
    low = low.cwiseMin(a);
    high = high.cwiseMax(a);
  }
  std::array<int, 2> cells{};
  for (int k = 0; k < 2; ++k) {
    const double faces = (surface.bounds()[1](k) - surface.bounds()[0](k)) / (high(k) - low(k));
    const double wanted = std::round(faces) * scene.ratio.front().value;
    if (std::abs(wanted - std::round(wanted)) > 1e-9 || std::round(wanted) < 1)
      throw_bad_input(scene.where("contact_mesh.ratio"), "contact_mesh.ratio", scene.ratio.front().text,
                      fmt::format("a ratio h/H that makes whole cells of T_{{C,H}}: Γ_C has {} trace faces along its "
                                  "axis {}",
                                  std::lround(faces), k + 1));
    cells[k] = static_cast<int>(std::lround(wanted));
  }
  return cells;
}

contact::ContactProblem problem_of(scene::Effect effect) {
  if (effect == scene::Effect::friction) return contact::ContactProblem::friction;
  if (effect == scene::Effect::friction_s) return contact::ContactProblem::friction_s;
  return contact::ContactProblem::signorini;
}

/// λ, u and the data sampled on Γ_C at the collapsed Gauss points (p_C + 2 per direction) of the
/// overlaps' triangles, with their weights; and the contact area (the weights where λ ≠ 0).
std::pair<io::CsvTable, double> contact_samples(const space::SolidH1Space& space,
                                                const space::SurfaceMultiplierSpace& multipliers,
                                                const contact::SolidContactSolution& solution, scene::Effect effect,
                                                const assembly::SolidFunction& data) {
  const bool signorini = effect == scene::Effect::signorini;
  io::CsvTable table({"x", "y", "z", "w", "u", signorini ? "obstacle" : "s", "lambda"});
  const mesh::SurfaceMultiplierMesh& multiplier_mesh = multipliers.mesh();
  const mesh::FlatContactSurface& surface = multiplier_mesh.surface();
  const basis::QuadratureRule2D& rule = basis::collapsed_triangle_rule(multipliers.degree() + 2);
  const double scale = solution.lambda.lpNorm<Eigen::Infinity>();
  double area = 0.0;
  for (const auto& overlap : multiplier_mesh.overlaps()) {
    const auto& polygon = overlap.polygon;
    const Eigen::VectorXd coefficients =
        solution.lambda.segment(multipliers.first_dof(overlap.cell), multipliers.per_cell());
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
      const Eigen::Vector2d e1 = polygon[k] - polygon[0], e2 = polygon[k + 1] - polygon[0];
      const double area_factor = std::abs(e1(0) * e2(1) - e1(1) * e2(0)) / 4.0;
      for (std::size_t q = 0; q < rule.weights.size(); ++q) {
        const Eigen::Vector2d a = polygon[0] + 0.5 * (rule.xi[q] + 1.0) * e1 + 0.5 * (rule.eta[q] + 1.0) * e2;
        const mesh::SolidPoint x = surface.from_plane(a);
        const double w = rule.weights[q] * area_factor;
        const double lambda = multipliers.values(overlap.cell, a).dot(coefficients);
        const mesh::BoundaryFace& face = surface.faces()[overlap.face];
        const double u =
            postprocess::solid_value(space, solution.u, face.cell, assembly::face_point_in_cell(surface, face, a));
        table.add_row({x(0), x(1), x(2), w, u, data ? data(x) : 0.0, lambda});
        // (where λ departs from 0 by more than round-off: the contact, or the slip, set)
        if (std::abs(lambda) > 1e-10 * scale) area += w;
      }
    }
  }
  return {std::move(table), area};
}

}  // namespace

RunResult run_solid_scene(const scene::Scene& scene, const SceneRunOptions& options) {
  Stopwatch total;
  check_solid_scene(scene, options);
  const auto say = [&](const std::string& line) {
    if (options.progress) options.progress(line);
  };
  // 1. The box, its boundary parts, S^p(T_h) with Γ_D eliminated.
  say("meshing the box");
  const mesh::SolidMesh mesh = scene_box(scene);
  const std::vector<char> dirichlet = space::faces_labelled(mesh, {"dirichlet"});
  if (std::count(dirichlet.begin(), dirichlet.end(), 1) == 0)
    throw_bad_input(scene.where("boundary.dirichlet"), "boundary.dirichlet",
                    scene.dirichlet_predicate.empty() ? "(missing)" : "\"" + scene.dirichlet_predicate + "\"",
                    "a predicate in x, y, z that holds at the centre of some boundary face: without Γ_D the "
                    "problem has no unique solution");
  const space::SolidH1Space space(mesh, std::vector<int>(mesh.n_cells(), scene.p.value), dirichlet);
  // 2. Γ_C (flat), T_{C,H} and M^{p_C}(T_{C,H}).
  const std::string contact_origin = scene.where("boundary.contact") + ": key 'boundary.contact'";
  const mesh::FlatContactSurface surface(mesh, {"contact"}, contact_origin);
  const mesh::SurfaceMultiplierMesh multiplier_mesh(surface, multiplier_cells(scene, surface), contact_origin);
  const space::SurfaceMultiplierSpace multipliers(multiplier_mesh, scene.pc.value);
  const auto function = [&](const std::string& text, const char* key) -> assembly::SolidFunction {
    if (text.empty()) return {};
    const Expression expression(text, scene.where(key) + ": key '" + key + "'", 3);
    return [expression](const mesh::SolidPoint& x) { return expression(x(0), x(1), x(2)); };
  };
  RunResult result;
  result.scene = scene.file;
  for (const auto effect : scene.effects) result.effects.push_back(scene::to_string(effect));
  result.p = scene.p.label();
  result.pc = scene.pc.label();
  result.family = space::to_string(scene.family);
  result.dimension = 3;
  result.faces_on_contact = static_cast<long long>(surface.faces().size());
  result.m = multiplier_mesh.n_cells();
  result.n_dofs = space.n_dofs();
  result.nmult = multipliers.n_dofs();
  result.ranks = 1;
  // 3. The contact problems.
  std::vector<std::pair<std::string, io::CsvTable>> samples;
  std::vector<std::pair<std::string, Eigen::VectorXd>> solutions;
  for (const auto effect : scene.effects) {
    const std::string name = scene::to_string(effect);
    say("solving " + name);
    Stopwatch clock;
    contact::SolidContactSetup setup;
    setup.space = &space;
    setup.multipliers = &multipliers;
    setup.problem = problem_of(effect);
    setup.f = function(scene.load, "data.f");
    setup.obstacle = function(scene.obstacle, "data.g");
    setup.bound = function(scene.friction_bound, "data.s");
    const contact::SolidContactSolution solution = contact::solve_solid_contact(setup);
    ContactResult contact;
    contact.problem = name;
    contact.energy = solution.energy;
    contact.n_dofs = space.n_dofs();
    contact.nmult = multipliers.n_dofs();
    contact.n_trace = solution.n_trace;
    contact.solver = solution.qp;
    contact.seconds = {solution.seconds.assembly, solution.seconds.factorization, solution.seconds.condensation,
                       solution.seconds.qp,       solution.seconds.recovery,      clock.seconds()};
    auto [table, area] = contact_samples(space, multipliers, solution, effect,
                                         effect == scene::Effect::signorini ? setup.obstacle : setup.bound);
    contact.contact_area = area;
    result.contacts.push_back(std::move(contact));
    samples.emplace_back(name, std::move(table));
    solutions.emplace_back(name, solution.u);
    throw_if_cancelled();
  }
  result.seconds_total = total.seconds();
  if (options.tables)
    for (const auto& [name, table] : samples) options.tables->insert_or_assign("boundary_" + name, table);
  if (options.fields && scene.wants_output(scene::Output::vtu))
    for (const auto& [name, u] : solutions)
      options.fields->insert_or_assign(name, postprocess::solid_vtu_grid(space, u));
  if (!options.write_files) return result;
  // 4. The files, as one set.
  std::vector<SolutionFile> files;
  if (scene.wants_output(scene::Output::vtu))
    for (const auto& [name, u] : solutions)
      files.push_back(
          {"solution_" + name, {{"u", 1}}, [&space, &u = u] { return postprocess::solid_vtu_grid(space, u); }});
  write_run_outputs(options.out, options.distribution, files, [&](const std::filesystem::path& out) {
    if (scene.wants_output(scene::Output::boundary))
      for (const auto& [name, table] : samples) table.write(out / ("boundary_" + name + ".csv"));
    if (scene.wants_output(scene::Output::summary))
      io::write_file_atomically(out / "summary.json", summary_json(result));
  });
  return result;
}

}  // namespace hpcontact::driver
