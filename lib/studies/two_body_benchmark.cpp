// add_two_body_rows: the two-block scene at level n, the baseline and the contact solve.
#include "studies/two_body_benchmark.hpp"

#include <string>

#include "contact/two_body_contact.hpp"
#include "core/error.hpp"
#include "core/timer.hpp"
#include "driver/elastic_scene.hpp"
#include "driver/scene_discretization.hpp"
#include "scene/scene_reader.hpp"

namespace hpcontact::studies {
namespace {

// Two blocks as in studies/two_bodies/patch.toml: the slave 0.01 above the master, its top moved
// down by 0.05 (uniform compression, every constraint active), rollers elsewhere.
const char* const kTwoBlocks = R"toml(
[[body]]
name = "slave"
[body.domain]
x_min = -1
x_max = 1
y_min = 0.01
y_max = 1.01
n_x = 4
n_y = 2
[body.boundary]
contact = "abs(y - 0.01) < 1e-9"
fixed_x = "abs(x + 1) < 1e-9"
fixed_y = "abs(y - 1.01) < 1e-9"
u_D_y = "-0.05"
[body.material]
E = "1"
[[body]]
name = "master"
[body.domain]
x_min = -1
x_max = 1
y_min = -1
y_max = 0
n_x = 6
n_y = 3
[body.boundary]
contact = "abs(y) < 1e-9"
fixed_x = "abs(x + 1) < 1e-9"
fixed_y = "abs(y + 1) < 1e-9"
[body.material]
E = "3"
[[pair]]
slave = "slave"
master = "master"
[contact_mesh]
ratio = 1
[discretization]
p = 1
pC = 0
[run]
effects = ["frictionless"]
)toml";

// One factorization and one solve of a body's A (fresh operators, so nothing is cached).
double linear_solve_seconds(const scene::Scene& scene, const mesh::Mesh& mesh, const std::vector<int>& cell_degrees) {
  Stopwatch clock;
  const auto operators = driver::scene_elastic_operators(scene, &mesh, cell_degrees);
  const auto& factor = operators->stiffness_factor();
  const Eigen::VectorXd u =
      factor.solve_local(Eigen::MatrixXd::Ones(static_cast<Eigen::Index>(factor.local_dofs().size()), 1)).col(0);
  HPC_VERIFY(u.allFinite(), "baseline solve gave a non-finite result");
  return clock.seconds();
}

}  // namespace

void add_two_body_rows(const PerformanceBenchmark& benchmark, BenchmarkRow base,
                       const std::function<void(BenchmarkRow)>& add) {
  const std::string origin = benchmark.file + ": kind 'two_body'";
  const long long n = base.n;
  const auto scene = scene::parse_scene(kTwoBlocks, "two-body benchmark scene",
                                        {{"body.slave.domain.n_x", n, origin},
                                         {"body.slave.domain.n_y", n / 2, origin},
                                         {"body.master.domain.n_x", n + 2, origin},
                                         {"body.master.domain.n_y", n / 2 + 1, origin},
                                         {"contact_mesh.ratio", benchmark.ratio, origin},
                                         {"discretization.p", static_cast<long long>(benchmark.p), origin},
                                         {"discretization.pC", static_cast<long long>(benchmark.pc), origin}});
  const auto slave_d = driver::discretize_scene(scene);
  const auto master_mesh = driver::build_scene_mesh_on_first_rank(scene.pair->master, {});

  BenchmarkRow linear = base;
  linear.kind = "linear_A_two_body";
  linear.seconds_baseline = linear.seconds =
      linear_solve_seconds(scene, *slave_d->mesh, slave_d->cell_degrees) +
      linear_solve_seconds(scene.pair->master, *master_mesh.mesh, master_mesh.cell_degrees);

  const auto slave = driver::scene_elastic_operators(scene, slave_d->mesh.get(), slave_d->cell_degrees);
  const auto master =
      driver::scene_elastic_operators(scene.pair->master, master_mesh.mesh.get(), master_mesh.cell_degrees);
  linear.ndofs = slave->n_dofs() + master->n_dofs();
  add(linear);
  contact::TwoBodyContactSetup setup;
  setup.slave = driver::elastic_setup_of(scene, *slave_d, contact::ElasticContactProblem::frictionless, *slave);
  setup.master = driver::elastic_body_of(scene.pair->master, *master);
  const auto solution = contact::solve_two_body_contact(setup);
  BenchmarkRow row = linear;
  row.kind = "two_body_frictionless";
  row.m = slave_d->boundary_mesh->n_segments();
  row.nmult = static_cast<int>(solution.contact.lambda.size());
  row.n_trace = solution.contact.n_trace;
  row.seconds_assembly = solution.contact.seconds.assembly;
  row.seconds = solution.contact.seconds.factorization + solution.contact.seconds.condensation +
                solution.contact.seconds.qp + solution.contact.seconds.recovery;
  add(row);
}

}  // namespace hpcontact::studies
