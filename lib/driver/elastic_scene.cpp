// An elastic scene's materials, operators and contact problems.
#include "driver/elastic_scene.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/expression.hpp"
#include "core/rank_agreement.hpp"
#include "mesh/cell_map.hpp"
#include "scene/scene_mesh.hpp"

namespace hpcontact::driver {

std::vector<assembly::Material> scene_materials(const scene::Scene& scene, const mesh::Mesh& mesh) {
  const Expression young(scene.young, scene.where("material.E") + ": key 'material.E'");
  const Expression poisson(scene.poisson, scene.where("material.nu") + ": key 'material.nu'");
  std::vector<assembly::Material> materials(mesh.n_cells());
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const mesh::Point x = mesh::CellMap(mesh, c).map(0.0, 0.0);
    const double e = young(x.x(), x.y()), nu = poisson(x.x(), x.y());
    const auto at = fmt::format(" at the cell centre (x, y) = ({:g}, {:g})", x.x(), x.y());
    if (!(e > 0.0) || !std::isfinite(e))
      throw_bad_input(scene.where("material.E"), "material.E", fmt::format("\"{}\" = {}{}", scene.young, e, at),
                      "a finite number > 0");
    if (!(nu > -1.0 && nu < 0.5))
      throw_bad_input(scene.where("material.nu"), "material.nu", fmt::format("\"{}\" = {}{}", scene.poisson, nu, at),
                      "a number in (-1, 0.5)");
    materials[c] = assembly::lame_parameters(e, nu, scene.plane_model);
  }
  return materials;
}

std::unique_ptr<operators::ElasticOperators> scene_elastic_operators(const scene::Scene& scene, const mesh::Mesh* mesh,
                                                                     const std::vector<int>& cell_degrees,
                                                                     OperatorLog* log,
                                                                     linalg::Distribution distribution) {
  // Evaluated where the mesh is (distributed: on the first rank at least); a bad material there
  // fails every rank alike.
  std::vector<assembly::Material> materials;
  std::array<std::vector<char>, space::kComponents> fixed;
  const auto evaluate = [&] {
    if (!mesh) return;
    materials = scene_materials(scene, *mesh);
    fixed = scene::scene_fixed_components(scene, *mesh);
  };
  if (distribution.distributed())
    run_on_all_ranks_agreeing(evaluate, distribution.ranks);
  else
    evaluate();
  return std::make_unique<operators::ElasticOperators>(mesh, cell_degrees, std::move(materials), log, fixed,
                                                       distribution);
}

namespace {

// Dirichlet data of a component need edges that fix it (Γ_D, or its rollers) to act on.
void check_dirichlet_data(const scene::Scene& scene, const operators::ElasticOperators& operators) {
  const auto& space = operators.vector_space();
  const std::array<std::pair<const char*, const std::string*>, 2> data{
      {{"boundary.u_D_x", &scene.dirichlet_x}, {"boundary.u_D_y", &scene.dirichlet_y}}};
  for (int c = 0; c < space::kComponents; ++c) {
    if (data[c].second->empty() || operators.whole_mesh().has_dirichlet()) continue;
    bool fixed = false;
    for (int d = 0; d < space.scalar().n_dofs() && !fixed; ++d) fixed = space.dof(d, c) < 0;
    if (!fixed)
      throw_bad_input(scene.where(data[c].first), data[c].first, *data[c].second,
                      fmt::format("absent: no edge fixes u_{} (neither Γ_D, boundary.dirichlet, nor a roller, "
                                  "boundary.fixed_{})",
                                  c == 0 ? 'x' : 'y', c == 0 ? 'x' : 'y'));
  }
}

}  // namespace

contact::ElasticBody elastic_body_of(const scene::Scene& scene, const operators::ElasticOperators& operators) {
  contact::ElasticBody body;
  body.operators = &operators;
  const auto fx = scene_function(scene, "data.f_x", scene.body_force_x);
  const auto fy = scene_function(scene, "data.f_y", scene.body_force_y);
  body.body_force = [fx, fy](const mesh::Point& x) { return Eigen::Vector2d(fx(x), fy(x)); };
  const auto tx = scene_function(scene, "data.t_x", scene.traction_x);
  const auto ty = scene_function(scene, "data.t_y", scene.traction_y);
  body.traction = [tx, ty](const mesh::Point& x, const mesh::Point&) { return Eigen::Vector2d(tx(x), ty(x)); };
  body.dirichlet = {scene_function(scene, "boundary.u_D_x", scene.dirichlet_x),
                    scene_function(scene, "boundary.u_D_y", scene.dirichlet_y)};
  check_dirichlet_data(scene, operators);
  return body;
}

contact::ElasticContactSetup elastic_setup_of(const scene::Scene& scene, const SceneDiscretization& d,
                                              contact::ElasticContactProblem problem,
                                              const operators::ElasticOperators& operators) {
  check_scene_has_dirichlet(scene, operators.whole_mesh().has_dirichlet() || operators.vector_space().has_rollers(),
                            "the elastic contact problems");
  contact::ElasticContactSetup setup;
  setup.operators = &operators;
  setup.boundary_mesh = d.boundary_mesh.get();
  setup.segment_degrees = d.segment_degrees;
  scene::check_family_fits(scene, *d.boundary_mesh, d.segment_degrees);
  setup.family = scene.family;
  setup.problem = problem;
  // The tangential multiplier's box (friction) is where Remark 3 asks the most points.
  setup.constraint_points = checked_constraint_points(scene, d,
                                                      problem == contact::ElasticContactProblem::frictionless
                                                          ? contact::ContactProblem::signorini
                                                          : contact::ContactProblem::friction_s);
  const auto body = elastic_body_of(scene, operators);
  setup.body_force = body.body_force;
  setup.traction = body.traction;
  setup.dirichlet = body.dirichlet;
  setup.gap = scene_gap(scene, operators.contact());
  if (problem == contact::ElasticContactProblem::tresca) {
    const auto bound = scene_function(scene, "data.s", scene.friction_bound);
    setup.threshold = [bound, file = scene.where("data.s"), text = scene.friction_bound](const mesh::Point& x) {
      const double value = bound(x);
      if (value < 0)
        throw_bad_input(file, "data.s", fmt::format("\"{}\" = {} at (x, y) = ({}, {})", text, value, x.x(), x.y()),
                        "Tresca's threshold must be >= 0 on Γ_C");
      return value;
    };
  }
  setup.friction_coefficient = scene.friction_coefficient;
  return setup;
}

}  // namespace hpcontact::driver
