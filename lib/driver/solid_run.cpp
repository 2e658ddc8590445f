// The 3-D run: the scene's discretization (solid_scene.hpp), its contact problems (scalar, or
// elastic: frictionless, Tresca, Coulomb), their samples on Γ_C and their files.
#include "driver/solid_run.hpp"

#include <fmt/format.h>

#include <functional>

#include "assembly/surface_coupling.hpp"
#include "basis/quadrature.hpp"
#include "contact/solid_contact.hpp"
#include "contact/solid_elastic_contact.hpp"
#include "core/error.hpp"
#include "core/expression.hpp"
#include "core/interrupt.hpp"
#include "core/petsc_session.hpp"
#include "core/timer.hpp"
#include "driver/run_outputs.hpp"
#include "driver/solid_pairing.hpp"
#include "driver/solid_scene.hpp"
#include "driver/summary_json.hpp"
#include "io/atomic_file.hpp"
#include "postprocess/solid_field.hpp"
#include "postprocess/surface_multiplier_vtu.hpp"

namespace hpcontact::driver {
namespace {

/// A contact problem solved on a 3-D scene, with what its outputs need.
struct SolvedSolid {
  ContactResult result;
  io::CsvTable samples;                       ///< boundary_<problem>.csv
  postprocess::SolidPointField field;         ///< the solution's VTU field (it holds the coefficients)
  std::vector<std::string> multiplier_names;  ///< "lambda", or "pressure" (and the Tresca tractions)
  Eigen::VectorXd multiplier;                 ///< their nodal coefficients on T_{C,H}, one after the other
};

/// visit(face, cell of T_{C,H}, plane point, point, weight) at the collapsed Gauss points of
/// p_C + 2 per direction of the triangles of every overlap of a trace face and a cell of T_{C,H}:
/// Σ w = |Γ_C| and Σ w μ = ∫ μ for every multiplier μ.
void for_each_contact_sample(const space::SurfaceMultiplierSpace& multipliers,
                             const std::function<void(const mesh::BoundaryFace&, int, const Eigen::Vector2d&,
                                                      const mesh::SolidPoint&, double)>& visit) {
  const mesh::SurfaceMultiplierMesh& multiplier_mesh = multipliers.mesh();
  const mesh::FlatContactSurface& surface = multiplier_mesh.surface();
  for (const auto& overlap : multiplier_mesh.overlaps()) {
    const auto& polygon = overlap.polygon;
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
      for (const auto& [a, w] :
           basis::plane_triangle_rule(polygon[0], polygon[k], polygon[k + 1], multipliers.degree() + 2))
        visit(surface.faces()[overlap.face], overlap.cell, a, surface.from_plane(a), w);
  }
}

/// The multiplier of T_{C,H} cell `cell` at plane point a.
double multiplier_at(const space::SurfaceMultiplierSpace& multipliers, const Eigen::VectorXd& coefficients, int cell,
                     const Eigen::Vector2d& a) {
  return multipliers.values(cell, a).dot(coefficients.segment(multipliers.first_dof(cell), multipliers.per_cell()));
}

/// What every 3-D contact result holds of its solution (beside the samples' area and force).
template <class Solution>
ContactResult solid_result(scene::Effect effect, const Solution& solution, long long n_dofs, long long nmult,
                           double area, double total_seconds) {
  ContactResult r;
  r.problem = scene::to_string(effect);
  r.energy = solution.energy;
  r.n_dofs = n_dofs;
  r.nmult = nmult;
  r.n_trace = solution.n_trace;
  r.solver = solution.qp;
  r.contact_area = area;
  const auto& s = solution.seconds;
  r.seconds = {s.assembly, s.factorization, s.condensation, s.qp, s.recovery, total_seconds};
  return r;
}

/// (9), (13) or (15) on the scalar space: samples x,y,z,w,u,obstacle|s,lambda.
SolvedSolid solve_scalar(const scene::Scene& scene, const SolidDiscretization& d, scene::Effect effect,
                         const linalg::Distribution& distribution) {
  Stopwatch clock;
  contact::SolidContactSetup setup;
  setup.space = d.space.get();
  setup.multipliers = d.multipliers.get();
  setup.problem = effect == scene::Effect::friction     ? contact::ContactProblem::friction
                  : effect == scene::Effect::friction_s ? contact::ContactProblem::friction_s
                                                        : contact::ContactProblem::signorini;
  setup.f = solid_scene_function(scene, scene.load, "data.f");
  setup.obstacle = solid_scene_function(scene, scene.obstacle, "data.g");
  setup.bound = solid_scene_function(scene, scene.friction_bound, "data.s");
  setup.trace_solve = scene.trace_solve;
  setup.distribution = distribution;
  auto solution = std::make_shared<const contact::SolidContactSolution>(contact::solve_solid_contact(setup));
  const bool signorini = effect == scene::Effect::signorini;
  const assembly::SolidFunction& data = signorini ? setup.obstacle : setup.bound;
  SolvedSolid out{{},
                  io::CsvTable({"x", "y", "z", "w", "u", signorini ? "obstacle" : "s", "lambda"}),
                  {},
                  {"lambda"},
                  solution->lambda};
  const double scale = solution->lambda.lpNorm<Eigen::Infinity>();
  double area = 0.0;
  for_each_contact_sample(*d.multipliers, [&](const mesh::BoundaryFace& face, int cell, const Eigen::Vector2d& a,
                                              const mesh::SolidPoint& x, double w) {
    const double lambda = multiplier_at(*d.multipliers, solution->lambda, cell, a);
    const double u =
        postprocess::solid_value(*d.space, solution->u, face.cell, assembly::face_point_in_cell(*d.surface, face, a));
    out.samples.add_row({x(0), x(1), x(2), w, u, data ? data(x) : 0.0, lambda});
    // (where λ departs from 0 by more than round-off: the contact, or the slip, set)
    if (std::abs(lambda) > 1e-10 * scale) area += w;
  });
  out.result = solid_result(effect, *solution, d.space->n_dofs(), d.multipliers->n_dofs(), area, clock.seconds());
  out.field = {"u", 1, [space = d.space.get(), solution](int c, const Eigen::Vector3d& xi) {
                 return Eigen::VectorXd::Constant(1, postprocess::solid_value(*space, solution->u, c, xi));
               }};
  return out;
}

/// Frictionless, Tresca or Coulomb contact of the elastic box: samples x,y,z,w,gap,pressure,traction_1,
/// traction_2 (gap = g − u·n; the tangential tractions along Γ_C's axes e_1, e_2, zero without
/// friction), the total force P = Σ w · pressure.
SolvedSolid solve_elastic(const scene::Scene& scene, const SolidDiscretization& d, scene::Effect effect,
                          const linalg::Distribution& distribution) {
  Stopwatch clock;
  contact::SolidElasticSetup setup = solid_elastic_setup(scene, d, effect);
  setup.distribution = distribution;
  auto solution = std::make_shared<const contact::SolidElasticSolution>(contact::solve_solid_elastic_contact(setup));
  SolvedSolid out{{},
                  io::CsvTable({"x", "y", "z", "w", "gap", "pressure", "traction_1", "traction_2"}),
                  {},
                  {"pressure", "traction_1", "traction_2"},
                  Eigen::VectorXd(3 * solution->pressure.size())};
  out.multiplier << solution->pressure, solution->traction_1, solution->traction_2;
  const Eigen::Vector3d normal = d.surface->normal();
  const double scale = solution->pressure.lpNorm<Eigen::Infinity>();
  double area = 0.0, force = 0.0;
  for_each_contact_sample(*d.multipliers, [&](const mesh::BoundaryFace& face, int cell, const Eigen::Vector2d& a,
                                              const mesh::SolidPoint& x, double w) {
    const double pressure = multiplier_at(*d.multipliers, solution->pressure, cell, a);
    const Eigen::Vector3d u = postprocess::solid_displacement(*d.vector_space, solution->u, face.cell,
                                                              assembly::face_point_in_cell(*d.surface, face, a));
    out.samples.add_row({x(0), x(1), x(2), w, setup.gap(x) - u.dot(normal), pressure,
                         multiplier_at(*d.multipliers, solution->traction_1, cell, a),
                         multiplier_at(*d.multipliers, solution->traction_2, cell, a)});
    force += w * pressure;
    if (std::abs(pressure) > 1e-10 * scale) area += w;
  });
  out.result =
      solid_result(effect, *solution, d.vector_space->n_dofs(), d.multipliers->n_dofs(), area, clock.seconds());
  out.result.total_force = force;
  out.result.fixed_point_changes = solution->fixed_point_changes;
  out.result.friction_coefficient = setup.friction_coefficient;
  out.field = {"displacement", 3, [space = d.vector_space.get(), solution](int c, const Eigen::Vector3d& xi) {
                 return Eigen::VectorXd(postprocess::solid_displacement(*space, solution->u, c, xi));
               }};
  return out;
}

/// solve.trace_operator = "saddle_point" takes frictionless contact on an iterative K only: refused
/// before any work, naming the key.
void check_saddle_point_run(const scene::Scene& scene, const linalg::Distribution& distribution) {
  if (scene.trace_solve != contact::SchurPath::saddle_point) return;
  for (const auto effect : scene.effects)
    if (effect != scene::Effect::frictionless && effect != scene::Effect::infsup)
      throw_bad_input(scene.where("solve.trace_operator"), "solve.trace_operator", "saddle_point",
                      fmt::format("dense, products or auto with the effect {} (saddle_point solves elastic "
                                  "frictionless contact only)",
                                  scene::to_string(effect)));
  const linalg::DistributedSolver k = distribution.solver;
  if (k != linalg::DistributedSolver::gamg && k != linalg::DistributedSolver::bddc)
    throw_bad_input(scene.where("solve.trace_operator"), "solve.trace_operator", "saddle_point",
                    fmt::format("dense, products or auto on the {} solver; saddle_point needs an iterative K "
                                "(--distributed-solver gamg or bddc)",
                                linalg::to_string(k)));
}

}  // namespace

RunResult run_solid_scene(const scene::Scene& scene, const SceneRunOptions& options) {
  Stopwatch total;
  check_solid_scene(scene);
  check_saddle_point_run(scene, options.distribution);
  const auto say = [&](const std::string& line) {
    if (options.progress) options.progress(line);
  };
  // 1. The box, its boundary parts, the spaces, Γ_C and T_{C,H}.
  say(scene.is_rectangle() ? "meshing the box" : "reading the cells of " + scene.mesh_file);
  const auto d = discretize_solid_scene(scene);
  RunResult result;
  result.scene = scene.file;
  for (const auto effect : scene.effects) result.effects.push_back(scene::to_string(effect));
  result.p = scene.p.label();
  result.pc = scene.pc.label();
  result.family = space::to_string(scene.family);
  result.dimension = 3;
  result.faces_on_contact = static_cast<long long>(d->surface->faces().size());
  result.m = d->multiplier_mesh->n_cells();
  result.n_dofs = d->vector_space ? d->vector_space->n_dofs() : d->space->n_dofs();
  result.nmult = d->multipliers->n_dofs();
  result.ranks = mpi_rank_and_size().second;
  result.distributed_solver = linalg::to_string(options.distribution.solver);
  // 2. α of the pairing (effect infsup), then the contact problems.
  if (scene.has_effect(scene::Effect::infsup)) {
    say("inf-sup constant");
    result.infsup = solid_scene_alpha(scene, *d, infsup::EigenBackend::slepc, nullptr, 1, options.distribution).summary;
  }
  std::vector<SolvedSolid> solved;
  for (const auto effect : scene.effects) {
    if (effect == scene::Effect::infsup) continue;
    say("solving " + scene::to_string(effect));
    const bool elastic =
        effect == scene::Effect::frictionless || effect == scene::Effect::tresca || effect == scene::Effect::coulomb;
    solved.push_back(elastic ? solve_elastic(scene, *d, effect, options.distribution)
                             : solve_scalar(scene, *d, effect, options.distribution));
    result.contacts.push_back(solved.back().result);
    throw_if_cancelled();
  }
  result.seconds_total = total.seconds();
  const bool vtu = scene.wants_output(scene::Output::vtu);
  for (const auto& s : solved) {
    if (options.tables) options.tables->insert_or_assign("boundary_" + s.result.problem, s.samples);
    if (options.fields && vtu)
      options.fields->insert_or_assign(s.result.problem, postprocess::solid_vtu_grid(*d->space, s.field));
  }
  if (!options.write_files) return result;
  // 3. The files, as one set.
  std::vector<SolutionFile> files;
  if (vtu)
    for (const auto& s : solved) {
      files.push_back({"solution_" + s.result.problem,
                       {{s.field.name, s.field.components}},
                       [&space = *d->space, &field = s.field] { return postprocess::solid_vtu_grid(space, field); }});
      files.push_back({"multiplier_" + s.result.problem, {}, [&multipliers = *d->multipliers, &s] {
                         return postprocess::surface_multiplier_vtu_grid(multipliers, s.multiplier, s.multiplier_names);
                       }});
      for (const auto& name : s.multiplier_names) files.back().fields.push_back({name, 1});
    }
  // (every rank holds the whole box and solution: rank 0 writes one VTU, not a piece per rank)
  write_run_outputs(options.out, linalg::Distribution{}, files, [&](const std::filesystem::path& out) {
    if (scene.wants_output(scene::Output::boundary))
      for (const auto& s : solved) s.samples.write(out / ("boundary_" + s.result.problem + ".csv"));
    if (scene.wants_output(scene::Output::summary))
      io::write_file_atomically(out / "summary.json", summary_json(result));
  });
  return result;
}

}  // namespace hpcontact::driver
