// The scene key builders that are not templates.
#include "scene/key_builders.hpp"

#include <cmath>
#include <cstdlib>

#include "core/expression.hpp"

namespace hpcontact::scene {

using io::TomlTable;

SceneKey number_key(const char* section, const char* name, double low, double high, double fallback,
                    double Scene::*member, const char* doc) {
  return {section,
          name,
          "number",
          fmt::format("{:g}", fallback),
          fmt::format("[{:g}, {:g}]", low, high),
          doc,
          "",
          [=](const TomlTable& table, Scene& scene) { scene.*member = table.number_in(name, low, high, fallback); }};
}

SceneKey any_number_key(const char* section, const char* name, double fallback, double mesh::Rectangle::*member,
                        const char* doc) {
  return {section,
          name,
          "number",
          fmt::format("{:g}", fallback),
          "finite",
          doc,
          "",
          [=](const TomlTable& table, Scene& scene) {
            const double value = table.number(name, fallback);
            if (!std::isfinite(value))
              throw_bad_input(table.origin(name), table.qualified(name), fmt::format("{}", value), "a finite number");
            scene.rectangle.*member = value;
          }};
}

SceneKey integer_key(const char* section, const char* name, long long low, long long high,
                     std::optional<long long> fallback, int Scene::*member, const char* doc) {
  return {section,
          name,
          "integer",
          fallback ? std::to_string(*fallback) : "",
          fmt::format("[{}, {}]", low, high),
          doc,
          "",
          [=](const TomlTable& table, Scene& scene) {
            if (fallback || table.has(name)) scene.*member = static_cast<int>(table.integer(name, low, high, fallback));
          }};
}

SceneKey expression_key(const char* section, const char* name, const char* fallback, std::string Scene::*member,
                        const char* doc) {
  return {section,
          name,
          "expression in x, y (x, y, z in 3-D) or a number",
          fallback[0] ? fmt::format("\"{}\"", fallback) : "",
          "muparser syntax",
          doc,
          "",
          [=](const TomlTable& table, Scene& scene) {
            scene.*member = table.expression(name, fallback);
            if (!(scene.*member).empty())
              Expression(scene.*member, table.origin(name) + ": key '" + table.qualified(name) + "'",
                         scene.dimension());
          }};
}

SceneKey names_key(const char* section, const char* name, std::vector<std::string> Scene::*member, const char* doc) {
  return {
      section, name, "list of strings", "", "Gmsh physical names", doc, "", [=](const TomlTable& table, Scene& scene) {
        scene.*member = table.string_list(name, std::vector<std::string>{});
      }};
}

SceneKey numbers_key(const char* section, const char* name, const char* allowed, std::vector<double> Scene::*member,
                     const char* doc, std::function<bool(double)> valid, const char* group) {
  return {section, name, "list of numbers", "", allowed, doc, group, [=](const TomlTable& table, Scene& scene) {
            std::vector<double> values;
            for (const auto& text : table.string_list(name, std::vector<std::string>{})) {
              char* end = nullptr;
              const double value = std::strtod(text.c_str(), &end);
              if (text.empty() || *end != '\0' || !std::isfinite(value) || (valid && !valid(value)))
                throw_bad_input(table.origin(name), table.qualified(name), text, allowed);
              values.push_back(value);
            }
            scene.*member = values;
          }};
}

}  // namespace hpcontact::scene
