// The stages of a run (scene_run.cpp's run_scene is these in order): discretize, build the
// model's operators, solve the contact problems, analyse the inf-sup constant, refine and repeat
// for convergence. Shared by the run and its convergence levels; not part of the library's API.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/operator_log.hpp"
#include "driver/model.hpp"
#include "driver/run_outputs.hpp"
#include "driver/run_result.hpp"
#include "driver/scene_discretization.hpp"
#include "infsup/infsup_analysis.hpp"
#include "io/csv_writer.hpp"
#include "linalg/distribution.hpp"

namespace hpcontact::driver {

/// One discretization of a run and what was solved on it: the scene's own (level 0) or a
/// uniformly refined one (convergence). Held by pointer: the model refers to `scene` and `d`.
struct Level {
  scene::Scene scene;  ///< refined for convergence levels
  std::unique_ptr<SceneDiscretization> d;
  OperatorLog log;  ///< a convergence level's own operators (the base level records into the run's)
  std::unique_ptr<Model> model;
  std::vector<SolvedProblem> solved;  ///< in the order of model->problems()
};

/// What a run's stages hand on to the files.
struct RunFiles {
  std::vector<SolutionFile> solutions;  ///< ParaView files (the convergence levels' built already)
  std::vector<OutputText> texts;        ///< the convergence levels' PVD collections
  std::optional<io::CsvTable> mode;     ///< the eigenvector of α sampled along Γ_C
};

/// How the stages report and distribute: the run's options in what stages need of them.
struct StageContext {
  linalg::Distribution distribution;
  std::function<void(const std::string&)> progress;  ///< may be empty
  bool writes_level_files = false;                   ///< each convergence level's u as a ParaView file
  void say(const std::string& line) const {
    if (progress) progress(line);
  }
};

/// 1. T_h, Γ_C, T_{C,H} and the degrees of `scene`.
std::unique_ptr<Level> discretize(const scene::Scene& scene, const StageContext& context);

/// 2. The model's operators on the level (recorded into `log`); the whole mesh released unless
/// `keep_whole_mesh` (the extension norm's references refine it later).
void build_operators(Level& level, OperatorLog* log, const StageContext& context, bool keep_whole_mesh);

/// 3. Every contact problem of the scene on the level's operators; `where` ends the progress lines.
void solve_contact_problems(Level& level, const StageContext& context, const std::string& where);

/// 4. α of the scene's pairing on the level's operators (and its mode with output "mode").
InfSupSummary analyse_infsup(Level& level, const StageContext& context, std::optional<io::CsvTable>& mode);

/// α of `setup` on the level as reported: the record of its pairing (a single run is level 1; h/H
/// the scene's when it gives one) and the eigensolver's diagnostics. Used by analyse_infsup and
/// `hpcontact infsup`.
InfSupSummary infsup_summary(const Level& level, const infsup::InfSupSetup& setup, const infsup::InfSupResult& alpha);

/// 5. The contact problems on scene.convergence_refinements uniform refinements beyond `base`,
/// each level with its own operators (recorded into `log` under the level's name, its factors freed
/// once solved); errors against the finest level. With `context.writes_level_files` every level's
/// solution goes into `files` with one PVD per problem.
std::vector<ConvergenceRow> refine_and_repeat(const Level& base, const StageContext& context, OperatorLog& log,
                                              RunFiles& files);

}  // namespace hpcontact::driver
