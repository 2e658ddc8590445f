// The Hertz validation of the elastic contact solver: a frictionless scene whose obstacle is the
// parabolic approximation of a rigid cylinder, g = (x − x_c)²/(2R) − d, solved along refinement
// sequences; each run's contact pressure is compared with the 2-D Hertz solution for its own total
// force (postprocess/hertz_comparison.hpp).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "io/csv_writer.hpp"
#include "scene/scene_variants.hpp"

namespace hpcontact::studies {

/// A study file (TOML), e.g. studies/elasticity/hertz_study.toml:
///   [hertz]               scene (relative to the study file), radius R > 0, centre x_c (default 0)
///   [[hertz.sequence]]    name, set, vary: the scene variants of one refinement sequence
///                         (scene/scene_variants.hpp), run in order
struct HertzStudy {
  std::string file;
  double radius = 1.0, centre = 0.0;
  struct Sequence {
    std::string name;
    std::vector<scene::SceneVariant> levels;
  };
  std::vector<Sequence> sequences;
};

/// @throws InputError naming the file, key and value; every level is checked to be a scene with
/// the single effect frictionless and a straight Γ_C on a line y = const.
HertzStudy read_hertz_study(const std::string& path);

struct HertzRow {
  std::string sequence, label;
  int level = 0, p = 0, pc = 0, ndofs = 0, nmult = 0;
  double total_force = 0.0, hertz_half_width = 0.0, half_width = 0.0, half_width_error = 0.0, profile_error = 0.0,
         seconds = 0.0;
};

struct HertzResults {
  std::vector<HertzRow> rows;
  /// The last level of each sequence sampled on Γ_C: sequence,x,pressure,hertz.
  io::CsvTable profiles{{"sequence", "x", "pressure", "hertz"}};
};

/// Runs every level; `on_row` after each (progress).
HertzResults run_hertz_study(const HertzStudy& study, const std::function<void(const HertzRow&)>& on_row = {});

/// Columns sequence,level,label,p,pC,ndofs,nmult,P,a_hertz,a,a_error,profile_error,seconds.
io::CsvTable hertz_table(const std::vector<HertzRow>& rows);

}  // namespace hpcontact::studies
