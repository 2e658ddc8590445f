// The [obstacle] keys and their rules: which keys each obstacle type takes.
#include "scene/obstacle_keys.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>

#include "core/error.hpp"
#include "core/expression.hpp"

namespace hpcontact::scene {
namespace {

using contact::ObstacleType;
using io::TomlTable;

const std::map<ObstacleType, std::vector<std::string>>& keys_of_type() {
  static const std::map<ObstacleType, std::vector<std::string>> keys{
      {ObstacleType::plane, {"point", "normal"}},
      {ObstacleType::circle, {"point", "radius"}},
      {ObstacleType::parabola, {"point", "normal", "radius"}},
      {ObstacleType::distance, {"distance"}}};
  return keys;
}

// [x, y]: two finite numbers.
mesh::Point point_of(const TomlTable& table, const std::string& name) {
  const auto texts = table.string_list(name);
  std::vector<double> values;
  for (const auto& text : texts) {
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(value)) break;
    values.push_back(value);
  }
  if (values.size() != 2 || texts.size() != 2)
    throw_bad_input(table.origin(name), table.qualified(name), fmt::format("[{}]", fmt::join(texts, ", ")),
                    "a pair of finite numbers [x, y]");
  return {values[0], values[1]};
}

}  // namespace

void add_obstacle_keys(std::vector<SceneKey>& keys) {
  std::vector<std::string> types;
  for (const auto& [type, names] : keys_of_type()) types.push_back(contact::to_string(type));
  keys.push_back({"obstacle", "type", "choice", "", fmt::format("{}", fmt::join(types, ", ")),
                  "the obstacle's shape: plane (point, normal), circle (point = centre, radius; the body outside), "
                  "parabola (point = vertex, normal, radius = curvature radius at the vertex), distance (an "
                  "expression φ, > 0 on the body's side); the gap is measured along Γ_C's outward normal",
                  "", [types](const TomlTable& table, Scene& scene) {
                    if (!table.has("type")) return;
                    const std::string name = table.choice("type", types);
                    for (const auto& [type, names] : keys_of_type())
                      if (name == contact::to_string(type)) scene.rigid_obstacle.type = type;
                    scene.rigid_obstacle.origin = table.origin("type");
                  }});
  keys.push_back({"obstacle", "point", "pair [x, y]", "", "finite numbers",
                  "plane: a point on it; circle: its centre; parabola: its vertex", "",
                  [](const TomlTable& table, Scene& scene) {
                    if (table.has("point")) scene.rigid_obstacle.point = point_of(table, "point");
                  }});
  keys.push_back({"obstacle", "normal", "pair [x, y]", "", "not zero (scaled to unit length)",
                  "plane, parabola: the obstacle's normal, pointing towards the body", "",
                  [](const TomlTable& table, Scene& scene) {
                    if (!table.has("normal")) return;
                    const mesh::Point normal = point_of(table, "normal");
                    if (!(normal.norm() > 0.0))
                      throw_bad_input(table.origin("normal"), table.qualified("normal"), "[0, 0]",
                                      "a non-zero vector [x, y]");
                    scene.rigid_obstacle.normal = normal.normalized();
                  }});
  keys.push_back({"obstacle", "radius", "number", "", "> 0 (finite)",
                  "circle: its radius; parabola: the curvature radius at its vertex", "",
                  [](const TomlTable& table, Scene& scene) {
                    if (!table.has("radius")) return;
                    const double radius = table.number("radius");
                    if (!(radius > 0.0 && std::isfinite(radius)))
                      throw_bad_input(table.origin("radius"), table.qualified("radius"), fmt::format("{}", radius),
                                      "a finite number > 0");
                    scene.rigid_obstacle.radius = radius;
                  }});
  keys.push_back({"obstacle", "distance", "expression in x, y", "", "muparser syntax",
                  "distance: φ(x, y), > 0 on the body's side and 0 on the obstacle's surface (a signed distance or "
                  "any function the normal crosses once); the gap is its root along the normal (Newton)",
                  "", [](const TomlTable& table, Scene& scene) {
                    if (!table.has("distance")) return;
                    scene.rigid_obstacle.distance = table.expression("distance");
                    Expression(scene.rigid_obstacle.distance,
                               table.origin("distance") + ": key '" + table.qualified("distance") + "'");
                  }});
}

void check_obstacle(const Scene& scene) {
  const std::vector<std::string> all{"point", "normal", "radius", "distance"};
  if (!scene.has_rigid_obstacle()) {
    for (const auto& name : all)
      if (scene.given.contains("obstacle." + name))
        throw_bad_input(scene.where("obstacle." + name), "obstacle.type", "(missing)",
                        "the obstacle's shape (plane, circle, parabola, distance) for obstacle." + name);
    return;
  }
  const auto type = scene.rigid_obstacle.type;
  if (scene.given.contains("data.g"))
    throw_bad_input(scene.where("data.g"), "data.g", scene.obstacle,
                    fmt::format("absent beside [obstacle] (type \"{}\"): give the obstacle by one of them",
                                contact::to_string(type)));
  const auto& needed = keys_of_type().at(type);
  for (const auto& name : all) {
    const bool wanted = std::find(needed.begin(), needed.end(), name) != needed.end();
    const std::string key = "obstacle." + name;
    if (wanted && !scene.given.contains(key))
      throw_bad_input(
          scene.where("obstacle.type"), key, "(missing)",
          fmt::format("the obstacle type \"{}\" needs {}", contact::to_string(type), fmt::join(needed, ", ")));
    if (!wanted && scene.given.contains(key))
      throw_bad_input(scene.where(key), key, "(given)",
                      fmt::format("absent for the obstacle type \"{}\" (it takes {})", contact::to_string(type),
                                  fmt::join(needed, ", ")));
  }
}

}  // namespace hpcontact::scene
