// The performance benchmark: per level, assemble once, time the baselines, then the contact
// solves and α, each as a ratio to the baseline of its matrix.
#include "studies/performance_benchmark.hpp"

#include <fmt/format.h>
#include <sys/resource.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include "assembly/condensed_factor.hpp"
#include "assembly/elastic_load.hpp"
#include "assembly/poisson_assembly.hpp"
#include "contact/contact_problem.hpp"
#include "contact/elastic_contact.hpp"
#include "core/error.hpp"
#include "core/timer.hpp"
#include "driver/elastic_scene.hpp"
#include "driver/pairing_stability.hpp"
#include "driver/scene_discretization.hpp"
#include "infsup/infsup_analysis.hpp"
#include "io/toml_reader.hpp"
#include "linalg/sparse_cholesky.hpp"
#include "operators/primal_operators.hpp"
#include "scene/ratio.hpp"
#include "scene/scene_reader.hpp"
#include "studies/solid_benchmark.hpp"
#include "studies/startup_benchmark.hpp"
#include "studies/two_body_benchmark.hpp"

namespace hpcontact::studies {

PerformanceBenchmark read_performance_benchmark(const std::string& path) {
  const auto root = io::parse_toml_file(path);
  PerformanceBenchmark out;
  out.file = path;
  const auto table = root.table("benchmark", true);
  out.p = static_cast<int>(table.integer("p", 1, 20));
  out.pc = static_cast<int>(table.integer("pC", 0, 19));
  out.ratio = table.string_list("ratio", std::vector<std::string>{"1/2"}).front();
  const double ratio = scene::parse_ratio(out.ratio, path, "benchmark.ratio").value;
  // (no levels: a benchmark of kinds that run once, "three_d_scene" and "startup")
  for (long long n : table.integer_list("n", 2, 4096, std::vector<long long>{})) {
    const double m = n * ratio;
    if (n % 2 != 0 || std::abs(m - std::round(m)) > 1e-9 || m < 1)
      throw_bad_input(path, "benchmark.n", std::to_string(n), "even, with n · ratio a whole number >= 1");
    out.levels.push_back(static_cast<int>(n));
  }
  const std::vector<std::string> allowed{"signorini",
                                         "friction",
                                         "friction_s",
                                         "alpha",
                                         "alpha_predicted",
                                         "alpha_extension",
                                         "assembled",
                                         "elastic",
                                         "two_body",
                                         "three_d",
                                         "three_d_alpha",
                                         "three_d_scene",
                                         "three_d_scene_saddle_point",
                                         "startup"};
  out.kinds = table.string_list("kinds", allowed);
  for (const auto& kind : out.kinds)
    if (std::find(allowed.begin(), allowed.end(), kind) == allowed.end())
      throw_bad_input(path, "benchmark.kinds", kind,
                      "any of signorini, friction, friction_s, alpha, alpha_predicted, alpha_extension, assembled, "
                      "elastic, two_body, three_d, three_d_alpha, three_d_scene, three_d_scene_saddle_point, startup");
  auto is_scene_kind = [](const std::string& kind) {
    return kind == "three_d_scene" || kind == "three_d_scene_saddle_point";
  };
  const bool scene_kind = std::any_of(out.kinds.begin(), out.kinds.end(), is_scene_kind);
  if (scene_kind || table.has("scene")) {
    const std::string scene = table.string("scene", std::string("(missing)"));
    out.scene = (std::filesystem::path(path).parent_path() / scene).string();
    if (!scene_kind || !std::filesystem::exists(out.scene))
      throw_bad_input(path, "benchmark.scene", scene,
                      scene_kind ? "an existing 3-D scene file (relative to the benchmark file)"
                                 : "only with kind three_d_scene or three_d_scene_saddle_point");
  }
  const bool levels_needed = std::any_of(out.kinds.begin(), out.kinds.end(), [&](const std::string& kind) {
    return !is_scene_kind(kind) && kind != "startup";
  });
  if (levels_needed && out.levels.empty())
    throw_bad_input(path, "benchmark.n", "(missing)", "the levels (cells per side) of kinds other than three_d_scene");
  table.reject_unknown_keys();
  root.reject_unknown_keys();
  return out;
}

// Peak resident memory since the last reset_peak_rss (VmHWM; writing 5 to clear_refs resets it,
// Linux ≥ 4.0), so that each row reports its own peak, not an earlier row's.
void reset_peak_rss() { std::ofstream("/proc/self/clear_refs") << "5"; }

double peak_rss_mb() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // kB
  rusage usage{};                                                                 // no /proc: the process's peak
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

namespace {

// One linear solve: Factor(arguments...) factorizes, then one solve with `rhs`. The baselines use
// CondensedFactor (the solver the contact problems and α use: static condensation, CHOLMOD with
// AMD on the skeleton, nothing assembled) and, for comparison, SparseCholesky on an assembled matrix.
template <class Factor, class... Arguments>
double time_linear_solve(const Eigen::VectorXd& rhs, const Arguments&... arguments) {
  Stopwatch clock;
  const Factor factor(arguments...);
  const Eigen::VectorXd x = factor.solve(rhs);
  HPC_VERIFY(x.allFinite(), "baseline solve gave a non-finite result");
  return clock.seconds();
}

// One contact problem (9), (13) or (15) of the level's scene: the solve after assembly, against
// one linear solve with K. Its own operators, so that no row reuses another's factorization.
BenchmarkRow contact_row(const std::string& kind, const scene::Scene& scene, const driver::SceneDiscretization& d,
                         const BenchmarkRow& base, const BenchmarkRow& linear_k) {
  const operators::PrimalOperators primal(*d.mesh, d.cell_degrees);
  const auto problem = *scene::contact_problem_of(*scene::effect_named(kind));  // checked when read
  const auto solution = contact::solve_contact(driver::contact_setup_of(scene, d, problem, primal));
  BenchmarkRow row = base;
  row.kind = kind;
  row.n_trace = solution.n_trace;
  row.seconds_assembly = solution.seconds.assembly;
  row.seconds_baseline = linear_k.seconds_baseline;
  row.seconds =
      solution.seconds.factorization + solution.seconds.condensation + solution.seconds.qp + solution.seconds.recovery;
  return row;
}

// α of the scene's pairing (Signorini; kind "alpha": interpolation norm, "alpha_extension":
// extension norm, its graded references included), against one linear solve with A_G.
BenchmarkRow alpha_row(const driver::SceneDiscretization& d, const scene::Scene& scene, const BenchmarkRow& base,
                       const BenchmarkRow& linear_ag, infsup::GramNorm norm) {
  const operators::PrimalOperators primal(*d.mesh, d.cell_degrees);
  auto setup =
      driver::infsup_setup_of(scene, d.mesh.get(), d.cell_degrees, *d.boundary_mesh, d.segment_degrees, primal);
  setup.norm = norm;
  const auto result = infsup::analyse_infsup(setup, infsup::EigenBackend::slepc);
  BenchmarkRow row = base;
  row.kind = norm == infsup::GramNorm::extension ? "alpha_extension" : "alpha";
  row.seconds_assembly = result.seconds_assembly;
  row.seconds_baseline = linear_ag.seconds_baseline;
  row.seconds = result.seconds - result.seconds_assembly;
  return row;
}

// The local α predictor of a solve's stability report (kind "alpha_predicted") against the
// global α of the same pairing (interpolation norm), its operators included: what the report costs.
BenchmarkRow predictor_row(const driver::SceneDiscretization& d, const scene::Scene& scene, const BenchmarkRow& base,
                           const BenchmarkRow& alpha) {
  BenchmarkRow row = base;
  row.kind = "alpha_predicted";
  Stopwatch clock;
  const auto pairing =
      driver::trace_pairing_of(scene, *d.contact, d.held_zone_ends, *d.boundary_mesh, d.segment_degrees);
  infsup::predict_alpha(pairing);
  row.seconds = clock.seconds();
  row.seconds_baseline = alpha.seconds_assembly + alpha.seconds;
  return row;
}

// The same solve on the assembled K (mass: A_G), as a ratio to the condensed one: what static
// condensation saves in time, and (peak_rss_mb) in memory.
BenchmarkRow assembled_row(bool mass, const space::H1Space& space, const Eigen::VectorXd& load,
                           const BenchmarkRow& base, const BenchmarkRow& condensed) {
  BenchmarkRow row = base;
  row.kind = mass ? "linear_AG_assembled" : "linear_K_assembled";
  Stopwatch assembly_clock;
  const auto matrices = assembly::assemble_volume_matrices(space, {.stiffness = true, .mass = mass});
  const Eigen::SparseMatrix<double> matrix =
      mass ? Eigen::SparseMatrix<double>(matrices.stiffness + matrices.mass) : matrices.stiffness;
  row.seconds_assembly = assembly_clock.seconds();
  row.seconds_baseline = condensed.seconds;
  row.seconds = time_linear_solve<linalg::SparseCholesky>(load, matrix);
  return row;
}

// The elastic body of kind "elastic" on the level's mesh: the §7 square clamped on Γ_D (E = 1,
// ν = 0.3, plane strain), pulled down by f = (0, −1) onto an obstacle below Γ_C at the gap
// g = 0.05 + 0.2 x²: one linear solve with A ("linear_A"), then the frictionless and the Coulomb
// (F = 0.3) contact solves against it, each with its own operators.
void add_elastic_rows(const PerformanceBenchmark& benchmark, const scene::Scene& scalar_scene, BenchmarkRow base,
                      const std::function<void(BenchmarkRow)>& add) {
  const std::string origin = benchmark.file + ": kind 'elastic'";
  const auto scene = scene::parse_scene(scene::paper_scene_text(), scene::paper_scene_name,
                                        {{"domain.n_x", static_cast<long long>(scalar_scene.n_x), origin},
                                         {"domain.n_y", static_cast<long long>(scalar_scene.n_y), origin},
                                         {"contact_mesh.ratio", benchmark.ratio, origin},
                                         {"discretization.p", static_cast<long long>(benchmark.p), origin},
                                         {"discretization.pC", static_cast<long long>(benchmark.pc), origin},
                                         {"run.effects", std::vector<std::string>{"frictionless", "coulomb"}, origin},
                                         {"data.f_y", std::string("-1"), origin},
                                         {"data.g", std::string("0.05 + 0.2 * x^2"), origin},
                                         {"data.friction_coefficient", 0.3, origin}});
  const auto d = driver::discretize_scene(scene);
  const auto materials = driver::scene_materials(scene, *d->mesh);
  const space::H1Space scalar_space(*d->mesh, d->cell_degrees);
  const space::VectorSpace space(scalar_space);
  base.ndofs = space.n_dofs();
  const Eigen::VectorXd load =
      assembly::assemble_elastic_load(space, [](const mesh::Point&) { return Eigen::Vector2d(0.0, -1.0); }, {}, {});
  BenchmarkRow linear_a = base;
  linear_a.kind = "linear_A";
  {
    Stopwatch clock;
    const assembly::CondensedFactor factor(std::make_unique<assembly::ElasticCellSystem>(space, materials));
    HPC_VERIFY(factor.solve(load).allFinite(), "baseline solve gave a non-finite result");
    linear_a.seconds_baseline = linear_a.seconds = clock.seconds();
  }
  add(linear_a);
  for (const auto problem : scene.elastic_effects()) {
    const operators::ElasticOperators operators(*d->mesh, d->cell_degrees, materials);
    const auto solution = contact::solve_elastic_contact(driver::elastic_setup_of(scene, *d, problem, operators));
    BenchmarkRow row = base;
    row.kind = "elastic_" + contact::to_string(problem);
    row.nmult = static_cast<int>(solution.lambda.size());
    row.n_trace = solution.n_trace;
    row.seconds_assembly = solution.seconds.assembly;
    row.seconds_baseline = linear_a.seconds_baseline;
    row.seconds = solution.seconds.factorization + solution.seconds.condensation + solution.seconds.qp +
                  solution.seconds.recovery;
    add(row);
  }
}

}  // namespace

std::vector<BenchmarkRow> run_performance_benchmark(const PerformanceBenchmark& benchmark,
                                                    const std::function<void(const BenchmarkRow&)>& on_row) {
  std::vector<BenchmarkRow> rows;
  auto add = [&](BenchmarkRow row) {
    row.ratio = row.seconds / row.seconds_baseline;
    if (row.peak_rss_mb == 0.0) row.peak_rss_mb = peak_rss_mb();  // (unless the row measured its own)
    rows.push_back(row);
    if (on_row) on_row(rows.back());
    reset_peak_rss();
  };
  reset_peak_rss();
  auto has = [&](const char* kind) {
    return std::find(benchmark.kinds.begin(), benchmark.kinds.end(), kind) != benchmark.kinds.end();
  };
  if (has("startup")) {
    if (benchmark.executable.empty())
      throw InputError(benchmark.file + ": kind startup needs the hpcontact executable");
    add(startup_row(benchmark.executable));
  }
  if (has("three_d_scene")) add_solid_scene_rows(benchmark, add);
  if (has("three_d_scene_saddle_point")) add_solid_saddle_point_rows(benchmark, add);
  for (int n : benchmark.levels) {
    // The built-in §7 scene at this level: n × n cells, T_{C,H} with the benchmark's h/H.
    const std::string where = benchmark.file + ": key 'benchmark.n' = " + std::to_string(n);
    const auto scene = scene::parse_scene(
        scene::paper_scene_text(), scene::paper_scene_name,
        {{"domain.n_x", static_cast<long long>(n), where},
         {"domain.n_y", static_cast<long long>(n), where},
         {"contact_mesh.ratio", benchmark.ratio, benchmark.file + ": key 'benchmark.ratio'"},
         {"discretization.p", static_cast<long long>(benchmark.p), benchmark.file + ": key 'benchmark.p'"},
         {"discretization.pC", static_cast<long long>(benchmark.pc), benchmark.file + ": key 'benchmark.pC'"},
         {"data.g", std::string("-x^2"), "benchmark"}});
    const auto discretization = driver::discretize_scene(scene);
    const auto& mesh = *discretization->mesh;
    const auto& boundary = *discretization->boundary_mesh;
    const int m = boundary.n_segments();
    const space::H1Space space(mesh, benchmark.p);
    BenchmarkRow base;
    base.p = benchmark.p;
    base.pc = benchmark.pc;
    base.n = n;
    base.m = m;
    base.ndofs = space.n_dofs();
    base.nmult = m * (benchmark.pc + 1);

    const Eigen::VectorXd load = assembly::assemble_volume_load(space, [](const mesh::Point&) { return -1.0; });
    BenchmarkRow linear_k = base;
    linear_k.kind = "linear_K";
    linear_k.seconds_baseline = linear_k.seconds = time_linear_solve<assembly::CondensedFactor>(load, space, 1.0, 0.0);
    add(linear_k);

    for (const auto& kind : benchmark.kinds)
      if (kind != "alpha" && kind != "alpha_predicted" && kind != "alpha_extension" && kind != "assembled" &&
          kind != "elastic" && kind != "two_body" && kind != "three_d" && kind != "three_d_alpha" &&
          kind != "three_d_scene" && kind != "three_d_scene_saddle_point" && kind != "startup")
        add(contact_row(kind, scene, *discretization, base, linear_k));
    BenchmarkRow linear_ag = base;
    linear_ag.kind = "linear_AG";
    if (has("alpha") || has("alpha_predicted") || has("alpha_extension") || has("assembled")) {
      linear_ag.seconds_baseline = linear_ag.seconds =
          time_linear_solve<assembly::CondensedFactor>(load, space, 1.0, 1.0);
      add(linear_ag);
    }
    if (has("alpha") || has("alpha_predicted")) {
      const auto alpha = alpha_row(*discretization, scene, base, linear_ag, infsup::GramNorm::interpolation);
      if (has("alpha")) add(alpha);
      if (has("alpha_predicted")) add(predictor_row(*discretization, scene, base, alpha));
    }
    if (has("alpha_extension")) add(alpha_row(*discretization, scene, base, linear_ag, infsup::GramNorm::extension));
    // The same solves on the assembled K and A_G, as ratios to the condensed ones: what static
    // condensation saves in time, and (peak_rss_mb) in memory.
    if (has("assembled"))
      for (const bool mass : {false, true}) add(assembled_row(mass, space, load, base, mass ? linear_ag : linear_k));
    if (has("elastic")) add_elastic_rows(benchmark, scene, base, add);
    if (has("two_body")) add_two_body_rows(benchmark, base, add);
    if (has("three_d")) add_solid_rows(benchmark, base, add);
    if (has("three_d_alpha")) add_solid_alpha_rows(benchmark, base, add);
  }
  return rows;
}

io::CsvTable benchmark_table(const std::vector<BenchmarkRow>& rows) {
  io::CsvTable table({"kind", "p", "pC", "n", "m", "ndofs", "nmult", "n_trace", "seconds_assembly", "seconds_baseline",
                      "seconds", "ratio", "peak_rss_mb", "products"});
  for (const auto& r : rows)
    table.add_row({r.kind, (long long)r.p, (long long)r.pc, (long long)r.n, (long long)r.m, (long long)r.ndofs,
                   (long long)r.nmult, (long long)r.n_trace, r.seconds_assembly, r.seconds_baseline, r.seconds, r.ratio,
                   r.peak_rss_mb, (long long)r.products});
  return table;
}

io::CsvTable scaling_exponents(const std::vector<BenchmarkRow>& rows) {
  std::map<std::string, std::vector<std::pair<double, double>>> points;
  for (const auto& r : rows)
    if (r.seconds > 0) points[r.kind].emplace_back(std::log(r.ndofs), std::log(r.seconds));
  io::CsvTable table({"kind", "exponent", "rows"});
  for (const auto& [kind, xy] : points) {
    if (xy.size() < 2) continue;
    double mx = 0, my = 0;
    for (const auto& [x, y] : xy) mx += x / xy.size(), my += y / xy.size();
    double sxy = 0, sxx = 0;
    for (const auto& [x, y] : xy) sxy += (x - mx) * (y - my), sxx += (x - mx) * (x - mx);
    table.add_row({kind, sxx > 0 ? sxy / sxx : 0.0, (long long)xy.size()});
  }
  return table;
}

}  // namespace hpcontact::studies
