// Reading and running a convergence study.
#include "studies/convergence_study.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/error.hpp"
#include "core/expression.hpp"
#include "core/timer.hpp"
#include "io/toml_reader.hpp"
#include "operators/poisson_problem.hpp"
#include "postprocess/error_norms.hpp"
#include "scene/scene_mesh.hpp"
#include "scene/scene_reader.hpp"

namespace hpcontact::studies {
namespace {

struct SolutionExpressions {
  Expression u, ux, uy, f;
};

SolutionExpressions parse_solution(const ConvergenceStudy& study) {
  auto origin = [&](const char* key) { return study.file + ": key 'solution." + key + "'"; };
  return {Expression(study.u, origin("u")), Expression(study.ux, origin("ux")), Expression(study.uy, origin("uy")),
          Expression(study.f, origin("f"))};
}

// A wrong derivative in a study file would show up as a convergence failure far from its cause;
// catch it here with central differences at a few interior points.
void check_solution_consistency(const ConvergenceStudy& study, const SolutionExpressions& s) {
  const double d = 1e-3;
  for (const auto& point : {std::pair{-0.63, -0.41}, {0.27, 0.55}, {0.71, -0.83}, {-0.12, 0.08}}) {
    const double x = point.first, y = point.second;  // not a structured binding: the lambda captures them
    const double ux = (s.u(x + d, y) - s.u(x - d, y)) / (2 * d);
    const double uy = (s.u(x, y + d) - s.u(x, y - d)) / (2 * d);
    const double laplacian = (s.u(x + d, y) + s.u(x - d, y) + s.u(x, y + d) + s.u(x, y - d) - 4 * s.u(x, y)) / (d * d);
    auto check = [&](const char* key, double given, double numeric) {
      if (std::abs(given - numeric) > 1e-4 * (1.0 + std::abs(numeric)))
        throw_bad_input(study.file, std::string("solution.") + key, std::to_string(given),
                        "disagrees with the finite-difference value " + std::to_string(numeric) +
                            " computed from solution.u at (" + std::to_string(x) + ", " + std::to_string(y) + ")");
    };
    check("ux", s.ux(x, y), ux);
    check("uy", s.uy(x, y), uy);
    check("f", s.f(x, y), -laplacian);
  }
}

}  // namespace

namespace {

// The runs of the study: p × n on the square, p × refinements × geometry on a scene's mesh.
void read_runs(const io::TomlTable& root, ConvergenceStudy& study) {
  const bool square = study.scene_file.empty();
  for (const auto& run : root.table_array("runs", true)) {
    const auto degrees = run.integer_list("p", 1, 20);
    std::vector<ConvergencePoint> grid;
    if (square) {
      for (const char* key : {"refinements", "geometry"})
        if (run.has(key))
          throw_bad_input(study.file, run.qualified(key), run.value_text(key), "only with [mesh] scene");
      for (long long n : run.integer_list("n", 2, 4096)) {
        if (n % 2 != 0)
          throw_bad_input(study.file, run.qualified("n"), std::to_string(n),
                          "must be even so that (1,0), where Γ_D ends, is a mesh vertex");
        grid.push_back({0, static_cast<int>(n), 0, "square"});
      }
    } else {
      if (run.has("n"))
        throw_bad_input(study.file, run.qualified("n"), run.value_text("n"), "only without [mesh] scene");
      const auto geometries = run.string_list("geometry", std::vector<std::string>{"curved"});
      for (const auto& geometry : geometries)
        if (geometry != "curved" && geometry != "polygonal")
          throw_bad_input(study.file, run.qualified("geometry"), geometry, "\"curved\" or \"polygonal\"");
      for (long long r : run.integer_list("refinements", 0, 8))
        for (const auto& geometry : geometries) grid.push_back({0, 0, static_cast<int>(r), geometry});
    }
    run.reject_unknown_keys();
    for (long long p : degrees)
      for (ConvergencePoint point : grid) {
        point.p = static_cast<int>(p);
        if (std::find(study.points.begin(), study.points.end(), point) == study.points.end())
          study.points.push_back(point);
      }
  }
}

}  // namespace

ConvergenceStudy read_convergence_study(const std::string& path) {
  const io::TomlTable root = io::parse_toml_file(path);
  ConvergenceStudy study;
  study.file = path;
  const auto solution = root.table("solution", true);
  study.u = solution.string("u");
  study.ux = solution.string("ux");
  study.uy = solution.string("uy");
  study.f = solution.string("f");
  study.u_d = solution.string("u_D", study.u);
  solution.reject_unknown_keys();
  const auto mesh = root.table("mesh");
  if (mesh.has("scene")) {
    for (const char* key : {"perturb", "seed"})
      if (mesh.has(key))
        throw_bad_input(path, mesh.qualified(key), mesh.value_text(key), "only on the §7 square (without mesh.scene)");
    const std::string scene = mesh.string("scene");
    study.scene_file = (std::filesystem::path(path).parent_path() / scene).string();
    if (!std::filesystem::exists(study.scene_file))
      throw_bad_input(path, mesh.qualified("scene"), scene, "an existing scene file (relative to the study file)");
  }
  study.perturb = mesh.number_in("perturb", 0.0, 0.24, 0.0);
  study.seed = static_cast<std::uint32_t>(mesh.integer("seed", 0, 1u << 30, 1));
  mesh.reject_unknown_keys();
  read_runs(root, study);
  root.reject_unknown_keys();
  check_solution_consistency(study, parse_solution(study));
  Expression(study.u_d, path + ": key 'solution.u_D'");
  return study;
}

namespace {

// The mesh of one point: the §7 scene's n × n square (perturbed as the study asks), or the study's
// scene refined and with its curves or without.
mesh::Mesh point_mesh(const ConvergenceStudy& study, const ConvergencePoint& point) {
  if (study.scene_file.empty()) {
    const std::string where = study.file + ": [[runs]] n = " + std::to_string(point.n);
    return scene::build_scene_mesh(
        scene::parse_scene(scene::paper_scene_text(), scene::paper_scene_name,
                           {{"domain.n_x", static_cast<long long>(point.n), where},
                            {"domain.n_y", static_cast<long long>(point.n), where},
                            {"domain.perturb", study.perturb, study.file + ": key 'mesh.perturb'"},
                            {"domain.seed", static_cast<long long>(study.seed), study.file + ": key 'mesh.seed'"}}));
  }
  const std::string where = study.file + ": [[runs]]";
  return scene::build_scene_mesh(
      scene::read_scene(study.scene_file, {{"domain.refinements", static_cast<long long>(point.refinements), where},
                                           {"domain.geometry", point.geometry, where}}));
}

}  // namespace

std::vector<ConvergenceRow> run_convergence_study(const ConvergenceStudy& study,
                                                  const std::function<void(const ConvergenceRow&)>& on_row) {
  const SolutionExpressions s = parse_solution(study);
  const Expression u_d(study.u_d, study.file + ": key 'solution.u_D'");
  operators::PoissonData data;
  data.f = [&](const mesh::Point& x) { return s.f(x.x(), x.y()); };
  data.neumann = [&](const mesh::Point& x, const mesh::Point& normal) {
    return s.ux(x.x(), x.y()) * normal.x() + s.uy(x.x(), x.y()) * normal.y();
  };
  data.dirichlet = [&](const mesh::Point& x) { return u_d(x.x(), x.y()); };
  const postprocess::ExactSolution exact{
      [&](const mesh::Point& x) { return s.u(x.x(), x.y()); },
      [&](const mesh::Point& x) { return Eigen::Vector2d(s.ux(x.x(), x.y()), s.uy(x.x(), x.y())); }};

  std::vector<ConvergenceRow> rows;
  for (const auto& point : study.points) {
    Stopwatch clock;
    const mesh::Mesh mesh = point_mesh(study, point);
    const space::H1Space space(mesh, point.p);
    const auto solution = operators::solve_poisson(space, data);
    ConvergenceRow row;
    row.seconds = clock.seconds();
    const auto u = assembly::total_field(solution.lift.get(), space, solution.coefficients);
    const auto errors = postprocess::compute_errors(u.space, u.coefficients, exact);
    row.point = point;
    row.cells = mesh.n_cells();
    row.ndofs = space.n_dofs();
    row.h = mesh.longest_edge();
    row.error_h1 = errors.h1;
    row.error_l2 = errors.l2;
    row.error_energy = errors.energy;
    rows.push_back(row);
    if (on_row) on_row(row);
  }
  return rows;
}

io::CsvTable convergence_table(const std::vector<ConvergenceRow>& rows) {
  io::CsvTable table({"p", "n", "refinements", "cells", "ndofs", "h", "error_h1", "error_l2", "seconds", "geometry"});
  for (const auto& r : rows)
    table.add_row({static_cast<long long>(r.point.p), static_cast<long long>(r.point.n),
                   static_cast<long long>(r.point.refinements), static_cast<long long>(r.cells),
                   static_cast<long long>(r.ndofs), r.h, r.error_h1, r.error_l2, r.seconds, r.point.geometry});
  return table;
}

}  // namespace hpcontact::studies
