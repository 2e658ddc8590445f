// A two-body scene: [[body]] tables, each with the sections of a one-body scene that describe a
// body (domain, boundary, material, data, discretization, exact), and one [[pair]] naming the slave and
// the master. Every body is read as a one-body scene of its own sections and the shared ones
// (contact_mesh, discretization, infsup, solve, run, convergence), so that the keys, their ranges
// and their messages are those of one body; the slave's scene carries the pair.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <toml++/toml.h>

#include <algorithm>
#include <regex>
#include <set>
#include <utility>

#include "core/error.hpp"
#include "io/toml_reader.hpp"
#include "scene/scene_tree.hpp"

namespace hpcontact::scene {
namespace {

const std::vector<std::string>& body_sections() {
  static const std::vector<std::string> sections{"domain", "boundary", "material", "data", "discretization", "exact"};
  return sections;
}
const std::vector<std::string>& shared_sections() {
  static const std::vector<std::string> sections{"contact_mesh", "discretization", "infsup", "solve",
                                                 "run",          "convergence"};
  return sections;
}
bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// Top-level tables other than the shared ones and the bodies are a body's (or unknown): refused,
// naming the override that put them there if one did.
void check_top_level(const toml::table& root, const std::string& path,
                     const std::map<std::string, std::string>& origins) {
  for (const auto& [key_node, node] : root) {
    const std::string key(key_node.str());
    if (key == "body" || key == "pair" || contains(shared_sections(), key)) continue;
    if (!contains(body_sections(), key))
      throw_bad_input(path, key, "(a table)",
                      fmt::format("one of body, pair, {} in a two-body scene", fmt::join(shared_sections(), ", ")));
    std::string dotted = key, origin = path;
    if (const auto* table = node.as_table(); table && !table->empty()) {
      dotted = key + "." + std::string(table->cbegin()->first.str());
      if (const auto found = origins.find(dotted); found != origins.end()) origin = found->second;
    }
    throw_bad_input(origin, dotted, "(given for the whole scene)",
                    fmt::format("a key of one body: in a two-body scene [{}] belongs in each [[body]]", key));
  }
}

struct BodyTable {
  std::string name;
  io::TomlTable table;
};

std::vector<BodyTable> read_bodies(const io::TomlTable& root) {
  std::vector<BodyTable> bodies;
  for (const auto& table : root.table_array("body", true)) {
    const std::string name = table.string("name");
    if (!std::regex_match(name, std::regex("[A-Za-z0-9_-]+")))
      throw_bad_input(table.origin("name"), table.qualified("name"), "\"" + name + "\"",
                      "a name of letters, digits, '_' and '-' (it appears in file names)");
    for (const auto& other : bodies)
      if (other.name == name)
        throw_bad_input(table.origin("name"), table.qualified("name"), "\"" + name + "\"", "a name no other body has");
    for (const auto& section : body_sections()) table.has(section);
    table.reject_unknown_keys();
    bodies.push_back({name, table});
  }
  if (bodies.size() != 2)
    throw_bad_input(root.file(), "body", fmt::format("({} [[body]] blocks)", bodies.size()),
                    "exactly two bodies: one contact pair between two bodies per scene");
  return bodies;
}

struct PairNames {
  std::string name, slave, master;
};

PairNames read_pair(const io::TomlTable& root, const std::vector<BodyTable>& bodies) {
  const auto pairs = root.table_array("pair", true);
  if (pairs.size() != 1)
    throw_bad_input(root.file(), "pair", fmt::format("({} [[pair]] blocks)", pairs.size()),
                    "exactly one contact pair per scene");
  const auto& table = pairs.front();
  PairNames names{table.string("name", "contact"), table.string("slave"), table.string("master")};
  if (!std::regex_match(names.name, std::regex("[A-Za-z0-9_-]+")))
    throw_bad_input(table.origin("name"), table.qualified("name"), "\"" + names.name + "\"",
                    "a name of letters, digits, '_' and '-' (it appears in file names)");
  std::vector<std::string> body_names;
  for (const auto& body : bodies) body_names.push_back("'" + body.name + "'");
  for (const char* key : {"slave", "master"}) {
    const std::string& value = key == std::string("slave") ? names.slave : names.master;
    if (std::none_of(bodies.begin(), bodies.end(), [&](const BodyTable& b) { return b.name == value; }))
      throw_bad_input(table.origin(key), table.qualified(key), "\"" + value + "\"",
                      fmt::format("the name of a [[body]]: {}", fmt::join(body_names, ", ")));
  }
  if (names.slave == names.master)
    throw_bad_input(table.origin("master"), table.qualified("master"), "\"" + names.master + "\"",
                    "another body than the slave");
  table.reject_unknown_keys();
  return names;
}

// One body's scene tree: its own sections and the shared ones. [discretization] may be given in
// both places: a key set for the whole scene from the command line or a study replaces the body's,
// one given in both tables of the file is ambiguous.
std::shared_ptr<toml::table> body_tree(const toml::table& root, const BodyTable& body, const std::string& path,
                                       const std::map<std::string, std::string>& origins) {
  auto tree = std::make_shared<toml::table>();
  for (const auto& section : body_sections())
    if (const auto* table = body.table.raw()[section].as_table()) tree->insert(section, *table);
  for (const auto& section : shared_sections()) {
    const auto* shared = root[section].as_table();
    if (!shared) continue;
    if (!tree->contains(section)) {
      tree->insert(section, *shared);
      continue;
    }
    auto& own = *(*tree)[section].as_table();
    for (const auto& [key_node, value] : *shared) {
      const std::string key(key_node.str()), dotted = section + "." + key;
      if (own.contains(key) && !origins.contains(dotted))
        throw_bad_input(path, dotted, fmt::format("(given for the whole scene and in [[body]] '{}')", body.name),
                        "one place: the scene's [" + section + "] or the body's");
      own.insert_or_assign(key, value);
    }
  }
  return tree;
}

// The origins of a body's keys: the body, unless an override replaced the value (one of the body's
// own, body.<name>.section.key, or of the whole scene).
std::map<std::string, std::string> body_origins(const BodyTable& body, const std::string& path,
                                                const std::map<std::string, std::string>& origins) {
  std::map<std::string, std::string> out = origins;
  for (const auto& section : body_sections()) {
    const auto* table = body.table.raw()[section].as_table();
    if (!table) continue;
    for (const auto& [key_node, value] : *table) {
      const std::string dotted = section + "." + std::string(key_node.str());
      if (const auto found = origins.find("body." + body.name + "." + dotted); found != origins.end())
        out[dotted] = found->second;
      else if (!origins.contains(dotted))
        out[dotted] = fmt::format("{} ([[body]] '{}')", path, body.name);
    }
  }
  return out;
}

// The multiplier and its data live on the slave's Γ_C: given in the master's own tables they would
// do nothing.
void refuse_multiplier_keys(const BodyTable& master, const std::string& slave, const std::string& path) {
  for (const auto& [section, key] : {std::pair<std::string, std::string>{"discretization", "pC"},
                                     {"data", "s"},
                                     {"data", "friction_coefficient"},
                                     {"exact", "pressure"}}) {
    const auto* table = master.table.raw()[section].as_table();
    if (!table || !table->contains(key)) continue;
    throw_bad_input(fmt::format("{} ([[body]] '{}')", path, master.name), section + "." + key, "(given)",
                    fmt::format("absent for the master: the multiplier and its data live on the slave's Γ_C; give it "
                                "for the slave ('{}')",
                                slave));
  }
}

void check_pair_effects(const Scene& slave, const Scene& master) {
  const std::string where = slave.where("run.effects");
  for (const auto effect : slave.effects)
    if (!elastic_problem_of(effect) && effect != Effect::infsup)
      throw_bad_input(where, "run.effects", to_string(effect),
                      "frictionless, tresca, coulomb, tied or infsup in a two-body scene (convergence and the scalar "
                      "two-body problems are not available yet)");
  if (slave.effects.empty())
    throw_bad_input(where, "run.effects", "[]", "at least one of frictionless, tresca, coulomb, tied, infsup");
  for (const Scene* body : {&slave, &master})
    if (!body->is_elastic())
      throw_bad_input(body->file, "material", fmt::format("(missing in [[body]] '{}')", body->body),
                      "a [body.material] table, or an elastic effect: the bodies of a pair are elastic");
}

}  // namespace

KeyPlace place_of_key(toml::table& root, const std::string& name, const std::string& origin,
                      const std::string& shown_name) {
  const std::string& shown = shown_name.empty() ? name : shown_name;
  std::vector<std::string> parts;
  for (std::size_t start = 0;;) {
    const auto dot = name.find('.', start);
    parts.push_back(name.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  toml::table* owner = &root;
  if (parts.size() == 4 && parts[0] == "body") {
    owner = nullptr;
    std::vector<std::string> names;
    if (auto* bodies = root["body"].as_array())
      for (auto& node : *bodies)
        if (auto* body = node.as_table()) {
          const auto* body_name = body->get_as<std::string>("name");
          if (body_name) names.push_back("'" + body_name->get() + "'");
          if (body_name && body_name->get() == parts[1]) owner = body;
        }
    if (!owner)
      throw_bad_input(origin, shown, "",
                      fmt::format("a body of the scene after 'body.' (the scene has: {})",
                                  names.empty() ? "no [[body]]" : fmt::format("{}", fmt::join(names, ", "))));
    parts.erase(parts.begin(), parts.begin() + 2);
  }
  if (parts.size() != 2 || parts[0].empty() || parts[1].empty())
    throw_bad_input(
        origin, shown, "",
        "a dotted scene key \"section.key\" (e.g. \"discretization.p\"), or \"body.<name>.section.key\" for "
        "one body of a two-body scene");
  if (!owner->contains(parts[0])) owner->insert(parts[0], toml::table{});
  auto* table = owner->get_as<toml::table>(parts[0]);
  if (!table) throw_bad_input(origin, shown, "", "'" + parts[0] + "' is not a table of the scene");
  return {table, parts[0], parts[1]};
}

Scene read_two_body_tree(const std::shared_ptr<toml::table>& tree, const std::string& path,
                         const std::map<std::string, std::string>& origins) {
  check_top_level(*tree, path, origins);
  io::TomlTable root(tree, tree.get(), path, "");
  root.set_origins(origins);
  const auto bodies = read_bodies(root);
  const PairNames names = read_pair(root, bodies);
  std::map<std::string, Scene> scenes;
  for (const auto& body : bodies) {
    const bool is_master = body.name == names.master;
    if (is_master) refuse_multiplier_keys(body, names.slave, path);
    scenes.emplace(body.name, read_scene_tree(body_tree(*tree, body, path, origins), path,
                                              body_origins(body, path, origins), body.name, is_master));
  }
  Scene slave = scenes.at(names.slave);
  const Scene& master = scenes.at(names.master);
  check_pair_effects(slave, master);
  slave.pair = std::make_shared<const ContactPair>(ContactPair{names.name, scenes.at(names.master)});
  return slave;
}

}  // namespace hpcontact::scene
