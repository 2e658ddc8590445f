// The keys of a box: its cells or nodes along z, its z extent, node lists per axis, its z grading.
#include "scene/box_keys.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstdlib>

#include "core/error.hpp"

namespace hpcontact::scene {
namespace {

using io::TomlTable;

/// Finite numbers from a key's list; each larger than the one before when `increasing`.
std::vector<double> numbers_of(const TomlTable& table, const char* name, bool increasing, const char* allowed) {
  std::vector<double> values;
  for (const auto& text : table.string_list(name, std::vector<std::string>{})) {
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(value) ||
        (increasing && !values.empty() && !(value > values.back())))
      throw_bad_input(table.origin(name), table.qualified(name), text, allowed);
    values.push_back(value);
  }
  return values;
}

}  // namespace

void add_box_keys(std::vector<SceneKey>& keys) {
  keys.push_back({"domain", "n_z", "integer", "", "[1, 100000]",
                  "box (3-D): cells along z; given, Ω is the box [x_min, x_max] × [y_min, y_max] × [z_min, z_max] "
                  "cut into n_x × n_y × n_z hexahedra, and expressions take x, y, z",
                  "", [](const TomlTable& table, Scene& scene) {
                    if (table.has("n_z")) scene.n_z = static_cast<int>(table.integer("n_z", 1, 100000));
                  }});
  static const std::array<const char*, 3> names{"x_nodes", "y_nodes", "z_nodes"};
  for (int axis = 0; axis < 3; ++axis)
    keys.push_back(
        {"domain", names[axis], "list of numbers", "", "finite, strictly increasing, at least two",
         axis == 2 ? "box: its nodes along z one by one (a 3-D domain; replaces z_min, z_max, n_z, grading_z)"
                   : "box: its nodes along this axis one by one (replaces that axis's min, max, n and grading)",
         "", [axis](const TomlTable& table, Scene& scene) {
           const char* name = names[axis];
           if (!table.has(name)) return;
           std::vector<double> nodes = numbers_of(table, name, true, "finite numbers, each larger than the one before");
           if (nodes.size() < 2)
             throw_bad_input(table.origin(name), table.qualified(name), fmt::format("{} numbers", nodes.size()),
                             "at least two nodes");
           scene.box_nodes[axis] = std::move(nodes);
         }});
  keys.push_back({"domain", "z_min", "number", "0", "finite, < z_max", "box: bottom end along z", "",
                  [](const TomlTable& table, Scene& scene) {
                    scene.z_min = table.number("z_min", 0.0);
                    scene.z_max = table.number("z_max", 1.0);
                    for (const char* key : {"z_min", "z_max"}) {
                      const double value = std::string(key) == "z_min" ? scene.z_min : scene.z_max;
                      if (!std::isfinite(value))
                        throw_bad_input(table.origin(key), table.qualified(key), fmt::format("{}", value),
                                        "a finite number");
                      if (table.has(key) && scene.dimension() == 2)
                        throw_bad_input(table.origin(key), table.qualified(key), fmt::format("{}", value),
                                        "only with domain.n_z (a box)");
                    }
                    if (!(scene.z_max > scene.z_min))
                      throw_bad_input(table.origin("z_max"), table.qualified("z_max"), fmt::format("{}", scene.z_max),
                                      fmt::format("a number > z_min = {}", scene.z_min));
                  }});
  keys.push_back({"domain", "z_max", "number", "1", "finite, > z_min", "box: top end along z (read with z_min)", "",
                  [](const TomlTable&, Scene&) {}});
  keys.push_back({"domain", "grading_z", "list of numbers", "", "z coordinates (numbers) inside the box",
                  "box: planes z = c the mesh is graded towards (grading_x, grading_y: planes x = c, y = c)", "",
                  [](const TomlTable& table, Scene& scene) {
                    scene.grading_z = numbers_of(table, "grading_z", false, "z coordinates (numbers) inside the box");
                  }});
}

}  // namespace hpcontact::scene
