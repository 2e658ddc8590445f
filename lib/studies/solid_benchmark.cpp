// add_solid_rows: the elastic cube at level n, the baseline and the contact solve on both paths.
#include "studies/solid_benchmark.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "assembly/condensed_factor.hpp"
#include "assembly/solid_elastic_system.hpp"
#include "contact/solid_elastic_contact.hpp"
#include "core/error.hpp"
#include "core/timer.hpp"
#include "driver/solid_scene.hpp"
#include "scene/scene_reader.hpp"

namespace hpcontact::studies {
namespace {

// The cube (−1, 1)³ clamped on top, pulled down by f_z = −0.1 onto a paraboloid below its bottom
// face (gap 0.02 + 0.1 (x² + y²)): a contact patch inside Γ_C, its free boundary a circle.
const char* const kCube = R"toml(
[domain]
x_min = -1.0
x_max = 1.0
y_min = -1.0
y_max = 1.0
z_min = -1.0
z_max = 1.0
n_x = 4
n_y = 4
n_z = 4
[boundary]
contact = "abs(z + 1) < 1e-9"
dirichlet = "abs(z - 1) < 1e-9"
[contact_mesh]
ratio = "1/2"
[discretization]
p = 2
pC = 1
[material]
E = "1"
nu = "0.3"
[data]
f_z = "-0.1"
g = "0.02 + 0.1 * (x^2 + y^2)"
[run]
effects = ["frictionless"]
)toml";

}  // namespace

void add_solid_rows(const PerformanceBenchmark& benchmark, BenchmarkRow base,
                    const std::function<void(BenchmarkRow)>& add) {
  const std::string origin = benchmark.file + ": kind 'three_d'";
  const long long n = base.n;
  const auto scene = scene::parse_scene(kCube, "3-D benchmark scene",
                                        {{"domain.n_x", n, origin},
                                         {"domain.n_y", n, origin},
                                         {"domain.n_z", n, origin},
                                         {"contact_mesh.ratio", benchmark.ratio, origin},
                                         {"discretization.p", static_cast<long long>(benchmark.p), origin},
                                         {"discretization.pC", static_cast<long long>(benchmark.pc), origin}});
  const auto d = driver::discretize_solid_scene(scene);
  base.ndofs = d->vector_space->n_dofs();
  base.m = d->multiplier_mesh->n_cells();
  base.nmult = d->multipliers->n_dofs();

  BenchmarkRow linear = base;
  linear.kind = "linear_A_3d";
  {
    Stopwatch clock;
    const assembly::CondensedFactor factor(
        std::make_unique<assembly::SolidElasticCellSystem>(*d->vector_space, d->materials));
    HPC_VERIFY(factor.solve(Eigen::VectorXd(Eigen::VectorXd::Ones(factor.size()))).allFinite(),
               "baseline solve gave a non-finite result");
    linear.seconds_baseline = linear.seconds = clock.seconds();
  }
  add(linear);
  contact::SolidElasticSetup setup;
  setup.space = d->vector_space.get();
  setup.multipliers = d->multipliers.get();
  setup.materials = d->materials;
  setup.body_force[2] = driver::solid_scene_function(scene, scene.body_force_z, "data.f_z");
  setup.gap = driver::solid_scene_function(scene, scene.obstacle, "data.g");
  double dense_energy = 0.0;
  for (const auto path : {contact::SchurPath::dense, contact::SchurPath::products}) {
    setup.trace_solve = path;
    const auto solution = contact::solve_solid_elastic_contact(setup);
    // (the two paths solve one problem: a benchmark of a wrong answer measures nothing)
    if (path == contact::SchurPath::dense) dense_energy = solution.energy;
    if (!(std::abs(solution.energy - dense_energy) <= 1e-8 * std::abs(dense_energy)))
      throw NumericalError(
          fmt::format("3-D benchmark at n = {}: the products path's energy {} differs from the dense "
                      "path's {}",
                      n, solution.energy, dense_energy));
    BenchmarkRow row = linear;
    row.kind = path == contact::SchurPath::dense ? "three_d_frictionless_dense" : "three_d_frictionless_products";
    row.n_trace = solution.n_trace;
    row.seconds_assembly = solution.seconds.assembly;
    row.seconds = solution.seconds.factorization + solution.seconds.condensation + solution.seconds.qp +
                  solution.seconds.recovery;
    add(row);
  }
}

}  // namespace hpcontact::studies
