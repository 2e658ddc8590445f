// Running a scene of an elastic body: its contact problems (frictionless, Tresca, Coulomb) on one
// set of operators, and their outputs. run_scene hands elastic scenes to run_elastic_scene.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "assembly/elastic_system.hpp"
#include "contact/elastic_contact.hpp"
#include "driver/scene_discretization.hpp"
#include "driver/scene_run.hpp"
#include "operators/elastic_operators.hpp"

namespace hpcontact::driver {

/// (E, ν) of the scene evaluated at each cell's centre, as Lamé parameters of its plane model.
/// @throws InputError naming the key, the value and the cell centre where E ≤ 0 or ν ∉ (−1, ½).
std::vector<assembly::Material> scene_materials(const scene::Scene& scene, const mesh::Mesh& mesh);

/// The elastic operators of the scene on T_h (`mesh`, `cell_degrees`): its materials and rollers,
/// factorized over the ranks of `distribution`. Distributed, `mesh` and the degrees are read on the
/// first rank only (the others may pass null and nothing: operators::ElasticOperators).
std::unique_ptr<operators::ElasticOperators> scene_elastic_operators(const scene::Scene& scene, const mesh::Mesh* mesh,
                                                                     const std::vector<int>& cell_degrees,
                                                                     OperatorLog* log = nullptr,
                                                                     linalg::Distribution distribution = {});

/// The elastic contact problem `problem` of the scene on `d` (data from the scene's expressions,
/// s ≥ 0 checked where evaluated); `operators` must belong to the discretization.
contact::ElasticContactSetup elastic_setup_of(const scene::Scene& scene, const SceneDiscretization& d,
                                              contact::ElasticContactProblem problem,
                                              const operators::ElasticOperators& operators);

/// Runs the elastic effects of `scene` and writes into `options.out`:
///   summary.json              (output "summary") every effect's results, the operators, timings
///   boundary_<effect>.csv     (output "boundary") x,y,s_arc,u_n,u_t,gap,pressure,traction_t,zone on Γ_C
///   solution_<effect>.vtu     (output "vtu") the displacement and the von Mises stress, VTK
///                              Lagrange cells of the largest p (under mpirun a .pvtu naming
///                              one piece per rank, as run_scene)
///   contact_<effect>.vtp      (output "vtu") the boundary samples on Γ_C, one polyline per zone
/// Nothing is written unless every effect succeeded. Returns the summary.
nlohmann::json run_elastic_scene(const scene::Scene& scene, const SceneRunOptions& options);

}  // namespace hpcontact::driver
