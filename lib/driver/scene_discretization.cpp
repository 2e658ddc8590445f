// Building a scene's discretization and contact problem.
#include "driver/scene_discretization.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <set>

#include "core/byte_buffer.hpp"
#include "core/error.hpp"
#include "core/expression.hpp"
#include "core/timer.hpp"
#include "scene/scene_mesh.hpp"

namespace hpcontact::driver {

namespace {

// Γ_C's cells of `mesh` as a part of it (@throws InputError as mesh::ContactBoundary does).
std::unique_ptr<mesh::Mesh> contact_cells_of(const mesh::Mesh& mesh) {
  const mesh::ContactBoundary contact(mesh);
  std::vector<int> cells;
  for (const auto& edge : contact.edges()) cells.push_back(edge.cell);
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  return std::make_unique<mesh::Mesh>(mesh.extract(cells));
}

// Per zone of Γ_C, whether a Dirichlet edge of `mesh` touches its start and its end (closed
// zones: never), by vertex.
std::vector<std::array<bool, 2>> held_zone_ends_of(const mesh::Mesh& mesh) {
  const mesh::ContactBoundary contact(mesh);
  std::set<int> dirichlet_vertices;
  for (const int e : mesh.boundary_edges())
    if (mesh.edge_part(e) == mesh::BoundaryPart::dirichlet)
      dirichlet_vertices.insert(mesh.edge(e).begin(), mesh.edge(e).end());
  // The vertex of trace edge k at its end of arc length s (the nearer of its two).
  const auto vertex_at = [&](int k, double s) {
    const auto& ends = mesh.edge(contact.edges()[k].edge);
    const mesh::Point x = contact.point_on_edge(k, s);
    return (mesh.vertex(ends[0]) - x).norm() <= (mesh.vertex(ends[1]) - x).norm() ? ends[0] : ends[1];
  };
  std::vector<std::array<bool, 2>> out;
  for (const auto& zone : contact.zones())
    out.push_back(zone.closed
                      ? std::array<bool, 2>{false, false}
                      : std::array<bool, 2>{dirichlet_vertices.count(vertex_at(zone.first_edge, zone.s_begin)) > 0,
                                            dirichlet_vertices.count(vertex_at(zone.end_edge - 1, zone.s_end)) > 0});
  return out;
}

}  // namespace

SceneMesh build_scene_mesh_on_first_rank(const scene::Scene& scene, const linalg::Distribution& distribution) {
  SceneMesh out;
  const auto build_whole = [&] {
    out.mesh = std::make_unique<mesh::Mesh>(scene::build_scene_mesh(scene));
    out.cell_degrees = scene::scene_cell_degrees(scene, *out.mesh);
  };
  if (!distribution.distributed()) {
    build_whole();
    out.contact_cells = contact_cells_of(*out.mesh);
    out.held_zone_ends = held_zone_ends_of(*out.mesh);
    return out;
  }
  // The first rank builds T_h and its degrees, and sends Γ_C's cells: the operators (and the
  // extension norm's references) take their parts from it (operators/rank_space.hpp).
  const std::vector<char> bytes = bytes_made_by_first_rank(
      [&] {
        build_whole();
        ByteWriter bytes_out;
        contact_cells_of(*out.mesh)->pack(bytes_out);
        std::vector<unsigned char> held;
        for (const auto& ends : held_zone_ends_of(*out.mesh)) held.insert(held.end(), ends.begin(), ends.end());
        bytes_out.put(held);
        return bytes_out.take();
      },
      distribution.ranks);
  ByteReader in(bytes);
  out.contact_cells = std::make_unique<mesh::Mesh>(mesh::Mesh::unpack(in));
  const auto held = in.get_vector<unsigned char>();
  for (std::size_t z = 0; z + 1 < held.size(); z += 2) out.held_zone_ends.push_back({held[z] != 0, held[z + 1] != 0});
  return out;
}

std::unique_ptr<SceneDiscretization> discretize_scene(const scene::Scene& scene,
                                                      const linalg::Distribution& distribution) {
  auto d = std::make_unique<SceneDiscretization>();
  SceneMesh built = build_scene_mesh_on_first_rank(scene, distribution);
  d->mesh = std::move(built.mesh);
  d->cell_degrees = std::move(built.cell_degrees);
  d->contact_cells = std::move(built.contact_cells);
  d->held_zone_ends = std::move(built.held_zone_ends);
  d->contact = std::make_unique<mesh::ContactBoundary>(*d->contact_cells);
  d->boundary_mesh = std::make_unique<mesh::BoundaryMesh>(scene::build_scene_boundary_mesh(scene, *d->contact));
  std::array<int, 2> extremes{};  // the smallest and largest degree, from the first rank
  if (d->mesh) {
    const auto [smallest, largest] = std::minmax_element(d->cell_degrees.begin(), d->cell_degrees.end());
    extremes = {*smallest, *largest};
  }
  if (distribution.distributed())
    HPC_VERIFY(MPI_Bcast(extremes.data(), 2, MPI_INT, 0, distribution.ranks) == MPI_SUCCESS,
               "broadcast of the degrees' extremes");
  d->smallest_cell_degree = extremes[0], d->largest_cell_degree = extremes[1];
  d->segment_degrees = scene::scene_segment_degrees(scene, *d->contact, *d->boundary_mesh);
  d->multipliers = std::make_unique<space::MultiplierSpace>(*d->boundary_mesh, d->segment_degrees);
  return d;
}

std::unique_ptr<SceneDiscretization> discretize_adapted(const scene::Scene& scene, mesh::Mesh mesh,
                                                        std::vector<int> cell_degrees, int degree_drop) {
  auto d = std::make_unique<SceneDiscretization>();
  d->mesh = std::make_unique<mesh::Mesh>(std::move(mesh));
  d->cell_degrees = std::move(cell_degrees);
  d->contact_cells = contact_cells_of(*d->mesh);
  d->held_zone_ends = held_zone_ends_of(*d->mesh);
  d->contact = std::make_unique<mesh::ContactBoundary>(*d->contact_cells);
  d->boundary_mesh = std::make_unique<mesh::BoundaryMesh>(d->contact->edge_mesh());
  const auto [smallest, largest] = std::minmax_element(d->cell_degrees.begin(), d->cell_degrees.end());
  d->smallest_cell_degree = *smallest, d->largest_cell_degree = *largest;
  for (const auto& edge : d->contact->edges()) {
    const int p = d->cell_degrees[static_cast<std::size_t>(d->contact_cells->global_cell(edge.cell))];
    d->trace_degrees.push_back(p);
    d->segment_degrees.push_back(std::max(p - degree_drop, 0));
  }
  scene::check_family_fits(scene, *d->boundary_mesh, d->segment_degrees);
  d->multipliers = std::make_unique<space::MultiplierSpace>(*d->boundary_mesh, d->segment_degrees);
  return d;
}

void release_whole_mesh(SceneDiscretization& d, const mesh::Mesh& operators_mesh) {
  if (&operators_mesh == d.mesh.get()) return;
  d.mesh.reset();
  d.cell_degrees = {};
}

bool reads_whole_mesh_after_operators(const scene::Scene& scene) {
  return scene.has_effect(scene::Effect::infsup) && scene.norm == infsup::GramNorm::extension;
}

std::function<double(const mesh::Point&)> scene_function(const scene::Scene& scene, const std::string& key,
                                                         const std::string& text) {
  if (text.empty()) return {};
  const Expression expression(text, scene.where(key) + ": key '" + key + "'");
  return [expression](const mesh::Point& x) { return expression(x.x(), x.y()); };
}

std::function<double(const mesh::Point&)> scene_gap(const scene::Scene& scene, const mesh::ContactBoundary& contact) {
  if (scene.has_rigid_obstacle()) return contact::obstacle_gap(scene.rigid_obstacle, contact);
  return scene_function(scene, "data.g", scene.obstacle);
}

namespace {

// The scene's s as the weight of B^s, keyed by its text so that the contact solve and α share B^s;
// s ≥ 0 is part of the data's contract, reported against the scene's key.
assembly::CouplingWeight scene_friction_bound(const scene::Scene& scene) {
  auto bound = scene_function(scene, "data.s", scene.friction_bound);
  if (!bound) return {};
  return {[bound, file = scene.where("data.s"), text = scene.friction_bound](const mesh::Point& x) {
            const double value = bound(x);
            if (value < 0)
              throw_bad_input(file, "data.s",
                              fmt::format("\"{}\" = {} at (x, y) = ({}, {})", text, value, x.x(), x.y()),
                              "the friction bound must be >= 0 on Γ_C");
            return value;
          },
          fmt::format("{}: key 'data.s' = \"{}\"", scene.where("data.s"), scene.friction_bound)};
}

}  // namespace

std::vector<int> checked_constraint_points(const scene::Scene& scene, const SceneDiscretization& d,
                                           contact::ContactProblem problem) {
  const auto& boundary_mesh = *d.boundary_mesh;
  if (scene.family.kind != space::MultiplierFamilyKind::discontinuous && !scene.constraint_points.empty())
    throw_bad_input(scene.where("solve.constraint_points"), "solve.constraint_points",
                    fmt::format("{}", fmt::join(scene.constraint_points, ", ")),
                    fmt::format("absent with contact_mesh.family = \"{}\", whose constraints act on its coefficients "
                                "at its nodes",
                                space::to_string(scene.family)));
  const int n_zones = static_cast<int>(boundary_mesh.zones().size());
  for (int k = 0; k < boundary_mesh.n_segments(); ++k) {
    if (scene.constraint_points.empty()) break;
    const int zone = boundary_mesh.zone_of_segment(k);
    const int requested = scene.of_zone(scene.constraint_points, zone, n_zones, "solve.constraint_points");
    const int pc = d.segment_degrees[static_cast<std::size_t>(k)];
    try {
      contact::segment_constraint_points(problem, pc, requested);
    } catch (const InputError&) {
      throw_bad_input(scene.where("solve.constraint_points"), "solve.constraint_points", std::to_string(requested),
                      fmt::format("at least p_C + 1 = {} (a segment of {} has p_C = {})", pc + 1,
                                  n_zones > 1 ? fmt::format("zone {}", zone) : std::string("Γ_C"), pc));
    }
  }
  return scene.constraint_points;
}

contact::ContactSetup contact_setup_of(const scene::Scene& scene, const SceneDiscretization& d,
                                       contact::ContactProblem problem, const operators::PrimalOperators& primal) {
  // The setup takes T_h through `primal` alone: a stored setup then names no mesh that a
  // distributed run frees, and holds no copy of the cells' degrees (a whole-mesh-length array).
  HPC_VERIFY(!d.mesh || primal.built_on(*d.mesh, d.cell_degrees), "primal operators of another discretization");
  contact::ContactSetup setup;
  setup.boundary_mesh = d.boundary_mesh.get();
  setup.segment_degrees = d.segment_degrees;
  scene::check_family_fits(scene, *d.boundary_mesh, d.segment_degrees);
  setup.family = scene.family;
  setup.problem = problem;
  setup.constraint_points = checked_constraint_points(scene, d, problem);
  setup.f = scene_function(scene, "data.f", scene.load);
  setup.load_key = "f = " + scene.load;
  setup.dirichlet = scene_function(scene, "boundary.u_D", scene.dirichlet_value);
  if (setup.dirichlet && !primal.whole_mesh().has_dirichlet())
    throw_bad_input(scene.where("boundary.u_D"), "boundary.u_D", scene.dirichlet_value,
                    "absent: the scene has no Γ_D (boundary.dirichlet) for the data to act on");
  check_scene_has_dirichlet(scene, primal.whole_mesh().has_dirichlet(), "the contact problems (9), (13), (15)");
  if (problem == contact::ContactProblem::signorini)
    setup.obstacle = scene_gap(scene, primal.contact());
  else
    setup.bound = scene_friction_bound(scene);
  setup.primal = &primal;
  return setup;
}

void check_scene_has_dirichlet(const scene::Scene& scene, bool held, const std::string& needed_by) {
  if (held) return;
  const bool groups = !scene.dirichlet_groups.empty();
  const std::string key = groups ? "boundary.dirichlet_groups" : "boundary.dirichlet";
  const std::string value = groups ? fmt::format("[{}]", fmt::join(scene.dirichlet_groups, ", "))
                            : scene.dirichlet_predicate.empty() ? "(missing)"
                                                                : "\"" + scene.dirichlet_predicate + "\"";
  throw_bad_input(
      scene.where(key), key, value,
      fmt::format("no boundary edge is in Γ_D{}, but {} need the body held there: u + c (a rigid "
                  "motion, for a body) has the energy of u, so the stiffness is singular",
                  scene.is_elastic() ? " (nor on a roller: boundary.fixed_x, boundary.fixed_y)" : "", needed_by));
}

std::function<double(double)> multiplier_error_weight(const scene::Scene& scene, const SceneDiscretization& d,
                                                      contact::ContactProblem problem) {
  if (problem != contact::ContactProblem::friction) return {};
  const Expression bound(scene.friction_bound, scene.file + ": key 'data.s'");
  const mesh::ContactBoundary* contact = d.contact.get();
  return [bound, contact](double s) {
    const mesh::Point x = contact->point_at(s);
    return bound(x.x(), x.y());
  };
}

namespace {

infsup::InfSupSetup common_infsup_setup(const scene::Scene& scene, const mesh::Mesh* mesh,
                                        std::vector<int> cell_degrees, const mesh::BoundaryMesh& boundary_mesh,
                                        std::vector<int> segment_degrees) {
  infsup::InfSupSetup setup;
  setup.mesh = mesh;
  setup.cell_degrees = std::move(cell_degrees);
  setup.boundary_mesh = &boundary_mesh;
  scene::check_family_fits(scene, boundary_mesh, segment_degrees);
  setup.segment_degrees = std::move(segment_degrees);
  setup.family = scene.family;
  setup.problem = scene.problem;
  setup.norm = scene.norm;
  setup.alpha_tolerance = scene.alpha_tolerance;
  return setup;
}

}  // namespace

infsup::InfSupSetup infsup_setup_of(const scene::Scene& scene, const mesh::Mesh* mesh, std::vector<int> cell_degrees,
                                    const mesh::BoundaryMesh& boundary_mesh, std::vector<int> segment_degrees,
                                    const operators::PrimalOperators& primal) {
  auto setup = common_infsup_setup(scene, mesh, std::move(cell_degrees), boundary_mesh, std::move(segment_degrees));
  setup.primal = &primal;
  if (setup.problem == infsup::PairingProblem::friction) {
    if (scene.friction_bound.empty())
      throw_bad_input(scene.where("infsup.problem"), "data.s", "(missing)",
                      "the friction pairing (22) needs the friction bound s");
    setup.friction_bound = scene_friction_bound(scene);
  }
  return setup;
}

infsup::InfSupSetup infsup_setup_of(const scene::Scene& scene, const mesh::Mesh* mesh, std::vector<int> cell_degrees,
                                    const mesh::BoundaryMesh& boundary_mesh, std::vector<int> segment_degrees,
                                    const operators::ElasticOperators& elastic) {
  auto setup = common_infsup_setup(scene, mesh, std::move(cell_degrees), boundary_mesh, std::move(segment_degrees));
  setup.elastic = &elastic;
  setup.primal_norm = scene.primal_norm;
  return setup;
}

SceneContactRun solve_scene_contact(const scene::Scene& scene, contact::ContactProblem problem, OperatorLog* log) {
  Stopwatch clock;
  SceneContactRun run;
  run.discretization = discretize_scene(scene);
  const operators::PrimalOperators primal(*run.discretization->mesh, run.discretization->cell_degrees, log);
  run.solution = contact::solve_contact(contact_setup_of(scene, *run.discretization, problem, primal));
  run.seconds = clock.seconds();
  return run;
}

}  // namespace hpcontact::driver
