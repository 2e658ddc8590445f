// The work–precision study: reading, solving, comparing with the reference, choosing the cheapest.
#include "studies/work_precision.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "contact/multiplier_distance.hpp"
#include "core/error.hpp"
#include "driver/adaptive_run.hpp"
#include "driver/free_boundary_fit.hpp"
#include "driver/scene_discretization.hpp"
#include "io/atomic_file.hpp"
#include "io/csv_writer.hpp"
#include "io/toml_reader.hpp"

namespace hpcontact::studies {
namespace {

const std::vector<std::string> kProblems{"signorini", "friction", "friction_s"};

std::vector<std::string> problem_list(const io::TomlTable& table, const std::string& key,
                                      const std::vector<std::string>& fallback) {
  auto problems = table.string_list(key, fallback);
  for (const auto& problem : problems)
    if (std::find(kProblems.begin(), kProblems.end(), problem) == kProblems.end())
      throw_bad_input(table.file(), table.qualified(key), problem, "any of signorini, friction, friction_s");
  return problems;
}

/// The problem's effect only, so that parse-time checks ask for the data this problem needs.
scene::Scene for_problem(scene::Scene scene, const std::string& problem) {
  scene.effects = {*scene::effect_named(problem)};  // the name is checked when the study is read
  return scene;
}

/// The scene rules between effects and data, reported against the study.
void check_effects(const scene::Scene& scene, const std::string& where) {
  try {
    scene::check_effects(scene);
  } catch (const InputError& error) {
    throw InputError(fmt::format("{}: {}", where, error.what()));
  }
}

contact::ContactProblem problem_named(const std::string& problem) {
  return *scene::contact_problem_of(*scene::effect_named(problem));
}

/// One solve, timed as the fastest of `repeats` when it is short (timer noise), kept with its
/// discretization for the λ comparison.
driver::SceneContactRun timed_solve(const scene::Scene& scene, const std::string& problem, int repeats) {
  auto run = driver::solve_scene_contact(scene, problem_named(problem));
  for (int k = 1; k < repeats && run.seconds < 1.0; ++k)
    run.seconds = std::min(run.seconds, driver::solve_scene_contact(scene, problem_named(problem)).seconds);
  return run;
}

}  // namespace

WorkPrecisionStudy read_work_precision_study(const std::string& path) {
  const auto root = io::parse_toml_file(path);
  WorkPrecisionStudy study;
  study.file = path;
  for (const char* section : {"study", "reference", "family"}) root.has(section);
  root.reject_unknown_keys();
  const auto head = root.table("study", true);
  const std::string base = (std::filesystem::path(path).parent_path() / head.string("scene")).string();
  study.problems = problem_list(head, "problems", kProblems);
  for (const auto& text : head.string_list("tolerances", std::vector<std::string>{"1e-3", "1e-6", "1e-9"})) {
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (*end != '\0' || !(value > 0 && value < 1)) throw_bad_input(path, "study.tolerances", text, "numbers in (0, 1)");
    study.tolerances.push_back(value);
  }
  study.repeats = static_cast<int>(head.integer("repeats", 1, 20, 3));
  head.reject_unknown_keys();

  for (const auto& reference : root.table_array("reference", true)) {
    const std::string problem = reference.choice("problem", kProblems);
    const std::string where = fmt::format("{}: reference for {}", path, problem);
    reference.has("set");
    reference.has("vary");
    const bool fit = reference.boolean("fit_free_boundary", false);
    reference.reject_unknown_keys();
    // With `vary`, the last variant is the reference and the one before it the comparison for its
    // accuracy; without, the comparison is the reference one uniform refinement coarser.
    auto variants = scene::scene_variants(base, reference.table("set"), reference.table("vary"), where);
    for (auto& variant : variants) {
      variant.scene = for_problem(variant.scene, problem);
      check_effects(variant.scene, where);
    }
    const auto scene = variants.back().scene;
    if (fit && !scene.is_rectangle())
      throw_bad_input(path, "reference.fit_free_boundary", "true",
                      "a rectangle domain: the located points become vertices by moving the nearest nodes, "
                      "which a Gmsh mesh does not allow");
    auto coarser = scene;
    if (variants.size() >= 2) {
      coarser = variants[variants.size() - 2].scene;
    } else if (scene.refinements >= 1) {
      coarser.refinements -= 1;
    } else {
      throw_bad_input(path, "reference.set.domain.refinements", std::to_string(scene.refinements),
                      ">= 1, or a reference.vary with at least two variants: the reference's accuracy is estimated "
                      "against it one refinement coarser or against the variant before it");
    }
    study.references.push_back({problem, scene, coarser, fit});
  }
  for (const auto& problem : study.problems)
    if (std::none_of(study.references.begin(), study.references.end(),
                     [&](const auto& r) { return r.problem == problem; }))
      throw_bad_input(path, "reference", "(none for " + problem + ")",
                      "one [[reference]] per problem of study.problems");

  int index = 0;
  for (const auto& family : root.table_array("family", true)) {
    ++index;
    WorkPrecisionStudy::Family f;
    f.name = family.string("name");
    f.problems = problem_list(family, "problems", study.problems);
    family.has("set");
    family.has("vary");
    family.reject_unknown_keys();
    const std::string where = fmt::format("{}: family '{}'", path, f.name);
    f.variants = scene::scene_variants(base, family.table("set"), family.table("vary"), where);
    for (const auto& problem : f.problems)
      for (const auto& variant : f.variants) check_effects(for_problem(variant.scene, problem), where);
    study.families.push_back(std::move(f));
  }
  return study;
}

namespace {

// A problem's reference (fitted to its free boundary when asked) and its accuracy: the difference
// to the comparison one refinement coarser (or the variant before it).
struct Reference {
  driver::SceneContactRun fine;
  double accuracy_energy = 0.0;
  std::function<double(double)> weight;  ///< of the multiplier error norm
};

Reference solve_reference(const WorkPrecisionStudy::Reference& reference, const std::string& problem,
                          const std::function<void(const std::string&)>& say, io::CsvTable& references) {
  say(problem + ": reference");
  scene::Scene fine_scene = reference.scene, coarse_scene = reference.coarser;
  std::string free_boundary;
  double free_boundary_moved = 0.0;
  if (reference.fit_free_boundary) {
    const auto fit = driver::fit_free_boundary(fine_scene, {problem_named(problem)});
    fine_scene = fit.scene;
    coarse_scene.grading_points.insert(coarse_scene.grading_points.end(), fit.points.begin(), fit.points.end());
    for (const auto& point : fit.points)
      free_boundary += fmt::format("{}{:.12g} {:.12g}", free_boundary.empty() ? "" : ";", point.x(), point.y());
    free_boundary_moved = fit.moved;
  }
  Reference out{timed_solve(fine_scene, problem, 1), 0.0, {}};
  const auto& fine = out.fine;
  say(problem + ": reference, coarser");
  const auto coarse = timed_solve(coarse_scene, problem, 1);
  out.accuracy_energy = std::abs(fine.solution.energy - coarse.solution.energy);
  out.weight = driver::multiplier_error_weight(reference.scene, *fine.discretization, problem_named(problem));
  const double accuracy_lambda =
      contact::multiplier_l2_distance(*coarse.discretization->multipliers, coarse.solution.lambda_legendre,
                                      *fine.discretization->multipliers, fine.solution.lambda_legendre, out.weight);
  references.add_row({problem, fine.solution.energy, coarse.solution.energy, out.accuracy_energy, accuracy_lambda,
                      static_cast<long long>(fine.solution.n_dofs), fine.seconds, free_boundary, free_boundary_moved});
  return out;
}

// An adaptive family's run: one row per step, its seconds the adaptivity's so far (every solve
// and estimate before it included: what the step's accuracy cost), p the step's largest and p_C
// the largest p_C. `consider` offers each step to the cheapest choice.
void add_adaptive_rows(const scene::Scene& scene, const std::string& problem, const std::string& family,
                       const Reference& reference, io::CsvTable& rows,
                       const std::function<void(const std::vector<io::CsvCell>&, double, double)>& consider) {
  const auto& fine = reference.fine;
  driver::adapt_level(scene, {}, [&](const driver::AdaptStep& step, const driver::Level& level) {
    const auto& d = *level.d;
    const auto& solved = level.solved.front();
    const double error_energy = std::abs(solved.result.energy - fine.solution.energy);
    const double error_lambda =
        contact::multiplier_l2_distance(*d.multipliers, solved.error_multiplier, *fine.discretization->multipliers,
                                        fine.solution.lambda_legendre, reference.weight);
    const std::string p = std::to_string(step.largest_degree),
                      pc = std::to_string(*std::max_element(d.segment_degrees.begin(), d.segment_degrees.end()));
    const auto n = static_cast<long long>(d.contact->edges().size());
    rows.add_row({problem, p, pc, n, static_cast<long long>(d.boundary_mesh->n_segments()), step.unknowns,
                  step.multipliers, error_energy, error_lambda, step.seconds, family, solved.result.energy});
    consider({family, p, pc, n, step.unknowns, error_energy, step.seconds}, error_energy, step.seconds);
  });
}

// The cheapest run per tolerance, where the reference can decide it.
void add_cheapest_rows(const std::string& problem, const std::vector<double>& tolerances, double accuracy_energy,
                       const std::vector<std::vector<io::CsvCell>>& best, io::CsvTable& cheapest) {
  for (std::size_t t = 0; t < tolerances.size(); ++t) {
    std::vector<io::CsvCell> row{problem, fmt::format("{:g}", tolerances[t])};
    if (tolerances[t] < accuracy_energy) {
      row.insert(row.end(), {std::string("below reference accuracy"), "", "", "", "", "", "", ""});
    } else if (best[t].empty()) {
      row.insert(row.end(), {std::string("not reached"), "", "", "", "", "", "", ""});
    } else {
      row.push_back(std::string("reached"));
      row.insert(row.end(), best[t].begin(), best[t].end());
    }
    cheapest.add_row(row);
  }
}

}  // namespace

void run_work_precision_study(const WorkPrecisionStudy& study, const std::filesystem::path& out,
                              const std::function<void(int, int, const std::string&)>& progress) {
  int total = 2 * static_cast<int>(study.problems.size()), done = 0;
  for (const auto& family : study.families)
    for (const auto& problem : family.problems)
      total +=
          std::count(study.problems.begin(), study.problems.end(), problem) * static_cast<int>(family.variants.size());
  auto say = [&](const std::string& label) {
    if (progress) progress(done, total, label);
    ++done;
  };

  io::CsvTable rows({"problem", "p", "pC", "n", "m", "ndofs", "nmult", "error_energy", "error_lambda", "seconds",
                     "family", "energy"});
  io::CsvTable references({"problem", "energy", "energy_coarser", "accuracy_energy", "accuracy_lambda", "ndofs",
                           "seconds", "free_boundary", "free_boundary_moved"});
  io::CsvTable cheapest(
      {"problem", "tolerance", "verdict", "family", "p", "pC", "n", "ndofs", "error_energy", "seconds"});
  for (const auto& problem : study.problems) {
    // 1. The reference and its accuracy.
    const auto& given = *std::find_if(study.references.begin(), study.references.end(),
                                      [&](const auto& r) { return r.problem == problem; });
    const Reference reference = solve_reference(given, problem, say, references);
    const auto& fine = reference.fine;

    // 2. Every family's runs against it, keeping the fastest per tolerance.
    std::vector<double> best_seconds(study.tolerances.size(), std::numeric_limits<double>::infinity());
    std::vector<std::vector<io::CsvCell>> best(study.tolerances.size());
    auto consider = [&](const std::vector<io::CsvCell>& cheapest_row, double error_energy, double seconds) {
      for (std::size_t t = 0; t < study.tolerances.size(); ++t)
        if (error_energy + reference.accuracy_energy <= study.tolerances[t] && seconds < best_seconds[t]) {
          best_seconds[t] = seconds;
          best[t] = cheapest_row;
        }
    };
    for (const auto& family : study.families) {
      if (std::find(family.problems.begin(), family.problems.end(), problem) == family.problems.end()) continue;
      for (const auto& variant : family.variants) {
        say(fmt::format("{}: {} {}", problem, family.name, variant.label));
        const auto& scene = variant.scene;
        if (scene.is_adaptive()) {
          add_adaptive_rows(for_problem(scene, problem), problem, family.name, reference, rows, consider);
          continue;
        }
        const auto run = timed_solve(for_problem(scene, problem), problem, study.repeats);
        const auto& d = *run.discretization;
        const double error_energy = std::abs(run.solution.energy - fine.solution.energy);
        const double error_lambda = contact::multiplier_l2_distance(*d.multipliers, run.solution.lambda_legendre,
                                                                    *fine.discretization->multipliers,
                                                                    fine.solution.lambda_legendre, reference.weight);
        const auto p = scene.p.label(), pc = scene.pc.label();
        const auto n = static_cast<long long>(d.contact->edges().size());
        const auto ndofs = static_cast<long long>(run.solution.n_dofs);
        rows.add_row({problem, p, pc, n, static_cast<long long>(d.boundary_mesh->n_segments()), ndofs,
                      static_cast<long long>(run.solution.lambda.size()), error_energy, error_lambda, run.seconds,
                      family.name, run.solution.energy});
        consider({family.name, p, pc, n, ndofs, error_energy, run.seconds}, error_energy, run.seconds);
      }
    }
    // 3. The cheapest run per tolerance.
    add_cheapest_rows(problem, study.tolerances, reference.accuracy_energy, best, cheapest);
  }
  io::ensure_writable_directory(out);
  rows.write(out / "work_precision.csv");
  references.write(out / "reference.csv");
  cheapest.write(out / "cheapest.csv");
}

}  // namespace hpcontact::studies
