// `hpcontact scene-keys`: the reference of every scene key (docs/scene_keys.md), generated from
// the declarations the scene reader parses with.
#include <fmt/format.h>

#include "commands.hpp"
#include "scene/scene_keys.hpp"

namespace hpcontact::tools {

void add_scene_keys_command(CLI::App& app, CommandAction& action) {
  auto* command = app.add_subcommand("scene-keys", "Print the reference of the scene keys (Markdown)");
  command->callback([&action] {
    action = [] {
      fmt::print("{}", scene::scene_key_reference());
      return 0;
    };
  });
}

}  // namespace hpcontact::tools
