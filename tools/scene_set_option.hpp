// `--set KEY=VALUE`, the one override of any scene key that every scene-taking command offers
// beside its short options (--p, --pc, --n, ...): VALUE is read as a TOML value (128, 0.5, true,
// [1, 2], "1/2"; bare text that is no TOML value is a string), then checked by the scene reader
// exactly like the file's own value, and messages name the option.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "scene/scene_reader.hpp"

namespace hpcontact::tools {

/// Adds the repeatable `--set KEY=VALUE` to `command`, collecting the texts into `texts`.
void add_set_option(CLI::App& command, std::vector<std::string>& texts);

/// The overrides the `--set` texts give, in order (a later one wins); `where` is the command,
/// e.g. "hpcontact solve". @throws InputError for a text without '=' or without a key.
std::vector<scene::SceneOverride> set_overrides(const std::vector<std::string>& texts, const std::string& where);

}  // namespace hpcontact::tools
