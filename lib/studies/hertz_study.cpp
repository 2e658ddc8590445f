// The Hertz study: reading, running the sequences, the table.
#include "studies/hertz_study.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "core/error.hpp"
#include "core/expression.hpp"
#include "core/timer.hpp"
#include "driver/elastic_scene.hpp"
#include "io/toml_reader.hpp"
#include "postprocess/hertz_comparison.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::studies {

HertzStudy read_hertz_study(const std::string& path) {
  const io::TomlTable root = io::parse_toml_file(path);
  const auto table = root.table("hertz", true);
  HertzStudy study;
  study.file = path;
  const std::string base = (std::filesystem::path(path).parent_path() / table.string("scene")).string();
  if (!std::filesystem::is_regular_file(base))
    throw_bad_input(path, "hertz.scene", table.string("scene"),
                    "a scene file, relative to the study file (" + base + " does not exist)");
  study.radius = table.number_in("radius", 1e-12, 1e12);
  study.centre = table.number("centre", 0.0);
  for (const auto& sequence : table.table_array("sequence", true)) {
    const std::string name = sequence.string("name");
    sequence.has("set");
    sequence.has("vary");
    auto levels = scene::scene_variants(base, sequence.table("set"), sequence.table("vary"),
                                        fmt::format("{}: sequence '{}'", path, name));
    sequence.reject_unknown_keys();
    for (const auto& level : levels) {
      const auto& effects = level.scene.effects;
      const std::string where =
          fmt::format("sequence '{}', {}", name, level.label.empty() ? "base scene" : level.label);
      if (effects.size() != 1 || effects.front() != scene::Effect::frictionless)
        throw_bad_input(path, "hertz.scene", table.string("scene"),
                        fmt::format("a scene with run.effects = [\"frictionless\"] ({})", where));
      // A half model carries half the force: Hertz's a of that P would be 1/√2 of the true one.
      const auto& s = level.scene;
      if (!s.fixed_x_predicate.empty() || !s.fixed_y_predicate.empty() || !s.fixed_x_groups.empty() ||
          !s.fixed_y_groups.empty())
        throw_bad_input(path, "hertz.scene", table.string("scene"),
                        fmt::format("a scene of the whole contact zone, without rollers (a symmetric half model "
                                    "carries half the force; {})",
                                    where));
    }
    study.sequences.push_back({name, std::move(levels)});
  }
  table.reject_unknown_keys();
  root.reject_unknown_keys();
  return study;
}

namespace {

// E* = E / (1 − ν²) in plane strain (E in plane stress), from the scene's material at the
// centre of Γ_C.
double contact_modulus(const scene::Scene& scene, const mesh::Point& x) {
  const double e = Expression(scene.young, scene.where("material.E"))(x.x(), x.y());
  const double nu = Expression(scene.poisson, scene.where("material.nu"))(x.x(), x.y());
  return scene.plane_model == assembly::PlaneModel::strain ? e / (1.0 - nu * nu) : e;
}

HertzRow run_level(const HertzStudy& study, const std::string& sequence, int level, const scene::SceneVariant& variant,
                   io::CsvTable* profile) {
  Stopwatch clock;
  const auto& scene = variant.scene;
  const auto d = driver::discretize_scene(scene);
  const auto owned = driver::scene_elastic_operators(scene, d->mesh.get(), d->cell_degrees);
  const operators::ElasticOperators& operators = *owned;
  const auto setup = driver::elastic_setup_of(scene, *d, contact::ElasticContactProblem::frictionless, operators);
  const auto solution = contact::solve_elastic_contact(setup);
  const double seconds = clock.seconds();
  const double modulus = contact_modulus(scene, d->contact->point_at(0.5 * d->contact->length()));
  const auto hertz = postprocess::compare_with_hertz(setup, solution, study.radius, modulus, study.centre);
  HertzRow row{sequence,
               variant.label,
               level,
               *std::max_element(d->cell_degrees.begin(), d->cell_degrees.end()),
               *std::max_element(d->segment_degrees.begin(), d->segment_degrees.end()),
               operators.n_dofs(),
               static_cast<int>(solution.lambda.size()),
               hertz.total_force,
               hertz.hertz_half_width,
               hertz.half_width,
               std::abs(hertz.half_width - hertz.hertz_half_width) / hertz.hertz_half_width,
               hertz.profile_error,
               seconds};
  if (profile) {  // the pressure against Hertz on [x_c − 2a, x_c + 2a]
    const double a = hertz.hertz_half_width;
    const double x0 = d->contact->point_at(0.0).x();
    const space::MultiplierSpace& multipliers = *d->multipliers;
    for (int j = 0; j <= 400; ++j) {
      const double x = study.centre - 2 * a + 4 * a * j / 400.0, s = x - x0;
      if (s < 0 || s > d->contact->length()) continue;
      const double r = a * a - (x - study.centre) * (x - study.centre);
      const double exact = r > 0 ? 2 * hertz.total_force / (std::numbers::pi * a * a) * std::sqrt(r) : 0.0;
      profile->add_row({sequence, x, multipliers.evaluate(solution.pressure, s), exact});
    }
  }
  return row;
}

}  // namespace

HertzResults run_hertz_study(const HertzStudy& study, const std::function<void(const HertzRow&)>& on_row) {
  HertzResults results;
  for (const auto& sequence : study.sequences)
    for (std::size_t k = 0; k < sequence.levels.size(); ++k) {
      const bool last = k + 1 == sequence.levels.size();
      results.rows.push_back(
          run_level(study, sequence.name, static_cast<int>(k), sequence.levels[k], last ? &results.profiles : nullptr));
      if (on_row) on_row(results.rows.back());
    }
  return results;
}

io::CsvTable hertz_table(const std::vector<HertzRow>& rows) {
  io::CsvTable table({"sequence", "level", "label", "p", "pC", "ndofs", "nmult", "P", "a_hertz", "a", "a_error",
                      "profile_error", "seconds"});
  for (const auto& r : rows)
    table.add_row({r.sequence, static_cast<long long>(r.level), r.label, static_cast<long long>(r.p),
                   static_cast<long long>(r.pc), static_cast<long long>(r.ndofs), static_cast<long long>(r.nmult),
                   r.total_force, r.hertz_half_width, r.half_width, r.half_width_error, r.profile_error, r.seconds});
  return table;
}

}  // namespace hpcontact::studies
