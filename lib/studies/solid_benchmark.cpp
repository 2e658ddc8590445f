// add_solid_rows: the elastic cube at level n, the baseline and the contact solve on both paths;
// add_solid_alpha_rows: the scalar slab, the baseline and α on both paths; add_solid_scene_rows:
// a scene file's baseline and contact solve by products; add_solid_saddle_point_rows: its
// frictionless contact on the saddle point against one GAMG solve.
#include "studies/solid_benchmark.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include "assembly/condensed_factor.hpp"
#include "assembly/solid_cell_system.hpp"
#include "assembly/solid_elastic_system.hpp"
#include "contact/solid_elastic_contact.hpp"
#include "core/error.hpp"
#include "core/timer.hpp"
#include "driver/solid_scene.hpp"
#include "infsup/solid_infsup.hpp"
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

// The scalar slab (−1, 1)² × (−1, −1 + 2 n_z / n) of cubes, clamped on top, Γ_C its bottom: the
// pairing (11) of the stability study on a box whose trace carries many multipliers.
const char* const kSlab = R"toml(
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
dirichlet = "z > -1 + 1e-9 && abs(z - z_top) < 1e-9"
[contact_mesh]
ratio = "1/2"
[discretization]
p = 2
pC = 1
[data]
f = "-1"
g = "0"
[run]
effects = ["infsup"]
)toml";

/// The baseline of a row: the factorization of `system` and one solve, in seconds.
double seconds_of_one_solve(std::unique_ptr<const assembly::CellSystem> system) {
  Stopwatch clock;
  const assembly::CondensedFactor factor(std::move(system));
  HPC_VERIFY(factor.solve(Eigen::VectorXd(Eigen::VectorXd::Ones(factor.size()))).allFinite(),
             "baseline solve gave a non-finite result");
  return clock.seconds();
}

// The scene file of kinds three_d_scene*, at the benchmark's p and p_C.
scene::Scene benchmark_scene(const PerformanceBenchmark& benchmark) {
  return scene::read_scene(
      benchmark.scene,
      {{"discretization.p", static_cast<long long>(benchmark.p), benchmark.file + ": key 'benchmark.p'"},
       {"discretization.pC", static_cast<long long>(benchmark.pc), benchmark.file + ": key 'benchmark.pC'"}});
}

// A row of a scene's discretization: p, p_C, unknowns, cells and functions of T_{C,H}.
BenchmarkRow scene_row(const PerformanceBenchmark& benchmark, const driver::SolidDiscretization& d) {
  BenchmarkRow row;
  row.p = benchmark.p;
  row.pc = benchmark.pc;
  row.ndofs = d.vector_space->n_dofs();
  row.m = d.multiplier_mesh->n_cells();
  row.nmult = d.multipliers->n_dofs();
  return row;
}

}  // namespace

void add_solid_alpha_rows(const PerformanceBenchmark& benchmark, BenchmarkRow base,
                          const std::function<void(BenchmarkRow)>& add) {
  const std::string origin = benchmark.file + ": kind 'three_d_alpha'";
  const long long n = base.n, n_z = std::max(2LL, n / 16);
  const double z_top = -1.0 + 2.0 * static_cast<double>(n_z) / static_cast<double>(n);
  std::string text = kSlab;
  text.replace(text.find("z_top"), 5, fmt::format("({:.17g})", z_top));
  const auto scene = scene::parse_scene(text, "3-D α benchmark scene",
                                        {{"domain.n_x", n, origin},
                                         {"domain.n_y", n, origin},
                                         {"domain.n_z", n_z, origin},
                                         {"domain.z_max", z_top, origin},
                                         {"contact_mesh.ratio", benchmark.ratio, origin},
                                         {"discretization.p", static_cast<long long>(benchmark.p), origin},
                                         {"discretization.pC", static_cast<long long>(benchmark.pc), origin}});
  const auto d = driver::discretize_solid_scene(scene);
  base.ndofs = d->space->n_dofs();
  base.m = d->multiplier_mesh->n_cells();
  base.nmult = d->multipliers->n_dofs();

  BenchmarkRow linear = base;
  linear.kind = "linear_AG_3d";
  linear.seconds_baseline = linear.seconds =
      seconds_of_one_solve(std::make_unique<assembly::SolidScalarCellSystem>(*d->space, 1.0, 1.0));
  add(linear);
  infsup::SolidInfSupSetup setup;
  setup.space = d->space.get();
  setup.multipliers = d->multipliers.get();
  double products_alpha = 0.0;
  // (the dense path up to kDenseAlphaUpTo multipliers: its n² memory and n³ time are what the
  // products avoid)
  for (const auto path : {contact::SchurPath::products, contact::SchurPath::dense}) {
    if (path == contact::SchurPath::dense && base.nmult > kDenseAlphaUpTo) continue;
    setup.path = path;
    Stopwatch clock;
    const infsup::InfSupResult result = infsup::analyse_solid_infsup(setup, infsup::EigenBackend::slepc);
    BenchmarkRow row = linear;
    row.kind = path == contact::SchurPath::dense ? "alpha_3d_dense" : "alpha_3d_products";
    row.seconds = clock.seconds();
    if (path == contact::SchurPath::products) products_alpha = result.alpha;
    // (one α on both paths: a benchmark of a wrong answer measures nothing)
    // (relative 1e-7, or 1e-9 of √λ_max for an α of zero)
    if (!(std::abs(result.alpha - products_alpha) <=
          1e-7 * std::max(products_alpha, 1e-2 * std::sqrt(result.lambda_max))))
      throw NumericalError(fmt::format("3-D α benchmark at n = {}: the dense path's α {} differs from the products' {}",
                                       n, result.alpha, products_alpha));
    add(row);
  }
}

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
  linear.seconds_baseline = linear.seconds =
      seconds_of_one_solve(std::make_unique<assembly::SolidElasticCellSystem>(*d->vector_space, d->materials));
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
    row.products = solution.qp.products;
    row.seconds_assembly = solution.seconds.assembly;
    row.seconds = solution.seconds.factorization + solution.seconds.condensation + solution.seconds.qp +
                  solution.seconds.recovery;
    add(row);
  }
}

void add_solid_scene_rows(const PerformanceBenchmark& benchmark, const std::function<void(BenchmarkRow)>& add) {
  auto scene = benchmark_scene(benchmark);
  const auto effects = scene.elastic_effects();
  if (scene.dimension() != 3 || effects.empty() || !scene.is_elastic())
    throw_bad_input(benchmark.file, "benchmark.scene", benchmark.scene,
                    "a 3-D elastic scene (domain.n_z or z_nodes, [material], a contact effect)");
  scene.trace_solve = contact::SchurPath::products;  // (the path whose cost the kind measures)
  driver::check_solid_scene(scene);
  const auto d = driver::discretize_solid_scene(scene);
  BenchmarkRow linear = scene_row(benchmark, *d);
  linear.kind = "linear_A_3d_scene";
  linear.seconds_baseline = linear.seconds =
      seconds_of_one_solve(std::make_unique<assembly::SolidElasticCellSystem>(*d->vector_space, d->materials));
  add(linear);
  const auto solution =
      contact::solve_solid_elastic_contact(driver::solid_elastic_setup(scene, *d, scene::effect_of(effects.front())));
  BenchmarkRow row = linear;
  row.kind = "three_d_scene_products";
  row.n_trace = solution.n_trace;
  row.products = solution.qp.products;
  row.seconds_assembly = solution.seconds.assembly;
  row.seconds =
      solution.seconds.factorization + solution.seconds.condensation + solution.seconds.qp + solution.seconds.recovery;
  add(row);
}

}  // namespace hpcontact::studies

namespace hpcontact::studies {

void add_solid_saddle_point_rows(const PerformanceBenchmark& benchmark, const std::function<void(BenchmarkRow)>& add) {
  auto scene = benchmark_scene(benchmark);
  if (scene.dimension() != 3 || !scene.is_elastic() || !scene.has_effect(scene::Effect::frictionless))
    throw_bad_input(benchmark.file, "benchmark.scene", benchmark.scene,
                    "a 3-D elastic scene with the effect frictionless (kind three_d_scene_saddle_point)");
  scene.trace_solve = contact::SchurPath::saddle_point;
  driver::check_solid_scene(scene);
  const auto d = driver::discretize_solid_scene(scene);
  const BenchmarkRow base = scene_row(benchmark, *d);
  contact::SolidElasticSetup setup = driver::solid_elastic_setup(scene, *d, scene::Effect::frictionless);
  setup.distribution = linalg::distribution_named(MPI_COMM_WORLD, "gamg", benchmark.file, "benchmark.kinds");

  // The contact solve, its peak memory its own.
  reset_peak_rss();
  const auto solution = contact::solve_solid_elastic_contact(setup);
  BenchmarkRow contact_row = base;
  contact_row.kind = "three_d_scene_saddle_point";
  contact_row.n_trace = solution.n_trace;
  contact_row.products = solution.qp.products;
  contact_row.seconds_assembly = solution.seconds.assembly;
  contact_row.seconds = solution.seconds.factorization + solution.seconds.qp + solution.seconds.recovery;
  contact_row.peak_rss_mb = peak_rss_mb();
  reset_peak_rss();

  // One solve of K u = F − B_nᵀ P from zero, GAMG's set-up included.
  const Eigen::VectorXd rhs =
      contact::solid_body_load(setup) -
      contact::stacked_coupling(*setup.space, *setup.multipliers, 1).transpose() * solution.pressure;
  Stopwatch clock;
  const assembly::CondensedFactor factor(
      std::make_unique<assembly::SolidElasticCellSystem>(*setup.space, setup.materials), {}, setup.distribution);
  const Eigen::VectorXd u = factor.solve(rhs);
  BenchmarkRow linear = base;
  linear.kind = "linear_A_3d_scene_gamg";
  linear.seconds_baseline = linear.seconds = clock.seconds();
  linear.products = factor.iterations() ? factor.iterations()->total : 0;
  // (the same u: a benchmark of a wrong answer measures nothing)
  const double largest = solution.u.lpNorm<Eigen::Infinity>();
  if (!((u - solution.u).lpNorm<Eigen::Infinity>() <= 1e-6 * largest))
    throw NumericalError(
        fmt::format("3-D saddle-point benchmark: the linear solve's u differs from the contact's by "
                    "{:.3e} of the largest",
                    (u - solution.u).lpNorm<Eigen::Infinity>() / largest));
  add(linear);
  contact_row.seconds_baseline = linear.seconds;
  add(contact_row);
}

}  // namespace hpcontact::studies
