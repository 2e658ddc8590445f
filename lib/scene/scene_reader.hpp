// Reading a scene: the TOML text (a file or the built-in §7 scene), overrides of single keys from
// the command line or a study (each checked exactly like the file's own value and named by its
// origin in messages), then the rules that relate keys to each other. The one place where a scene
// becomes a checked, typed Scene.
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "scene/scene.hpp"

namespace hpcontact::scene {

/// A value replacing one key of a scene: `key` is dotted ("discretization.p"), `origin` names
/// where it came from ("hpcontact solve --p"). Setting a key of an exclusive group
/// (contact_mesh.m, .ratio, .breakpoints) removes the others.
struct SceneOverride {
  /// A scalar, a list of one kind, or a list of number lists (domain.grading_points = [[x, y], ...]).
  using Value = std::variant<long long, double, bool, std::string, std::vector<std::string>, std::vector<long long>,
                             std::vector<double>, std::vector<std::vector<double>>>;
  std::string key;
  Value value;
  std::string origin;
};

/// The scene file with the overrides applied. @throws InputError naming the file or the
/// override's origin, the key, the value and the allowed range.
Scene read_scene(const std::string& path, const std::vector<SceneOverride>& overrides = {});

/// The same from the text of a scene; `path` names it in messages and anchors relative mesh paths.
Scene parse_scene(const std::string& text, const std::string& path, const std::vector<SceneOverride>& overrides = {});

/// The paper's §7 scene: Ω = (-1, 1)², n × n cells (n = 8), Γ_C the bottom edge, Γ_D the top edge
/// and the upper half of the right edge, T_{C,H} with ratio 1, p = 1, p_C = 0, f = -1,
/// s = (1 - x)². `hpcontact infsup` runs on it unless given a scene.
std::string paper_scene_text();
/// The name of the built-in §7 scene in messages.
inline constexpr const char* paper_scene_name = "built-in §7 scene";

/// Checks the effects against the data (g for signorini, s for friction problems, a contact
/// problem for convergence) and the outputs against the effects. @throws InputError.
void check_effects(const Scene& scene);

}  // namespace hpcontact::scene
