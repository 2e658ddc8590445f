// What an elastic scene defines beyond the scalar model: its materials, its operators on T_h and
// its contact problems (frictionless, Tresca, Coulomb), read from the scene's keys.
#pragma once

#include <memory>
#include <vector>

#include "assembly/elastic_system.hpp"
#include "contact/elastic_contact.hpp"
#include "contact/elastic_trace_solver.hpp"
#include "driver/scene_discretization.hpp"
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

/// The body of the scene on `operators`: its body force, traction and Dirichlet data.
/// @throws InputError for Dirichlet data of a component that no edge fixes.
contact::ElasticBody elastic_body_of(const scene::Scene& scene, const operators::ElasticOperators& operators);

/// The elastic contact problem `problem` of the scene on `d` (data from the scene's expressions,
/// s ≥ 0 checked where evaluated); `operators` must belong to the discretization.
contact::ElasticContactSetup elastic_setup_of(const scene::Scene& scene, const SceneDiscretization& d,
                                              contact::ElasticContactProblem problem,
                                              const operators::ElasticOperators& operators);

}  // namespace hpcontact::driver
