// TomlTable on top of toml++.
#include "io/toml_reader.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <fstream>
#include <numeric>
#include <regex>
#include <sstream>

#include "core/error.hpp"
#include "io/csv_writer.hpp"

namespace hpcontact::io {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), 0);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1] ? 1 : 0)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

TomlTable::TomlTable(std::shared_ptr<const toml::table> root, const toml::table* table, std::string file,
                     std::string prefix)
    : root_(std::move(root)), table_(table), file_(std::move(file)), prefix_(std::move(prefix)) {}

std::string TomlTable::qualified(const std::string& key) const { return prefix_.empty() ? key : prefix_ + "." + key; }

std::string TomlTable::origin(const std::string& key) const {
  if (origins_) {
    const auto found = origins_->find(qualified(key));
    if (found != origins_->end()) return found->second;
  }
  return file_;
}

void TomlTable::set_origins(std::map<std::string, std::string> origins) {
  origins_ = std::make_shared<const std::map<std::string, std::string>>(std::move(origins));
}

bool TomlTable::has(const std::string& key) const {
  asked_.insert(key);
  return table_ && table_->contains(key);
}

void TomlTable::fail(const std::string& key, const std::string& value, const std::string& allowed) const {
  throw_bad_input(origin(key), qualified(key), value, allowed);
}

std::string TomlTable::value_text(const std::string& key) const {
  std::ostringstream out;
  if (const auto* node = table_->get(key)) {
    if (node->is_table())
      out << "{...}";
    else if (node->is_array())
      out << *node->as_array();
    else
      node->visit([&out](const auto& value) { out << value; });
  }
  return out.str();
}

namespace {

// The value of a numeric node as a double. toml++'s value<double>() refuses integers that a
// double cannot hold exactly (e.g. 2222222222222222220); those are still numbers to a user.
double numeric_value(const toml::node& node) {
  if (node.is_integer()) return static_cast<double>(node.as_integer()->get());
  return node.as_floating_point()->get();
}

}  // namespace

double TomlTable::number(const std::string& key, std::optional<double> fallback) const {
  if (!has(key)) {
    if (fallback) return *fallback;
    fail(key, "(missing)", "a number is required");
  }
  const auto* node = table_->get(key);
  if (!(node->is_floating_point() || node->is_integer())) fail(key, value_text(key), "must be a number");
  return numeric_value(*node);
}

double TomlTable::number_in(const std::string& key, double min, double max, std::optional<double> fallback) const {
  const double value = number(key, fallback);
  if (!(value >= min && value <= max))
    // The shortest text that reads back as the number ("0.1", not "0.10000000000000001").
    fail(key, fmt::format("{}", value), fmt::format("must be in [{}, {}]", min, max));
  return value;
}

long long TomlTable::integer(const std::string& key, long long min, long long max,
                             std::optional<long long> fallback) const {
  if (!has(key)) {
    if (fallback) return *fallback;
    fail(key, "(missing)", "an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "] is required");
  }
  const auto* node = table_->get(key);
  if (!node->is_integer()) fail(key, value_text(key), "must be an integer");
  const long long value = node->value<long long>().value();
  if (value < min || value > max)
    fail(key, std::to_string(value), "must be in [" + std::to_string(min) + ", " + std::to_string(max) + "]");
  return value;
}

std::string TomlTable::string(const std::string& key, std::optional<std::string> fallback) const {
  if (!has(key)) {
    if (fallback) return *fallback;
    fail(key, "(missing)", "a string is required");
  }
  const auto* node = table_->get(key);
  if (!node->is_string()) fail(key, value_text(key), "must be a string (in quotes)");
  return node->value<std::string>().value();
}

std::string TomlTable::expression(const std::string& key, std::optional<std::string> fallback) const {
  if (!has(key)) {
    if (fallback) return *fallback;
    fail(key, "(missing)", "an expression (a string in quotes) or a number is required");
  }
  const auto* node = table_->get(key);
  if (node->is_string()) return node->value<std::string>().value();
  if (!(node->is_integer() || node->is_floating_point()))
    fail(key, value_text(key), "must be an expression (a string in quotes) or a number");
  const double value = numeric_value(*node);
  if (!std::isfinite(value)) fail(key, value_text(key), "must be a finite number");
  return format_full_precision(value);
}

std::string TomlTable::choice(const std::string& key, const std::vector<std::string>& allowed,
                              std::optional<std::string> fallback) const {
  const std::string value = string(key, fallback);
  if (std::find(allowed.begin(), allowed.end(), value) != allowed.end()) return value;
  std::string list;
  for (const auto& option : allowed) list += (list.empty() ? "" : ", ") + option;
  fail(key, "\"" + value + "\"", "must be one of: " + list);
}

std::vector<long long> TomlTable::integer_list(const std::string& key, long long min, long long max,
                                               std::optional<std::vector<long long>> fallback) const {
  const std::string range = "each in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
  const std::string forms = "an integer, a list [1, 2, 4] or a range \"1..12\"";
  if (!has(key)) {
    if (fallback) return *fallback;
    fail(key, "(missing)", forms + " is required");
  }
  const auto* node = table_->get(key);
  std::vector<long long> values;
  if (node->is_integer()) {
    values.push_back(node->value<long long>().value());
  } else if (node->is_array()) {
    for (const auto& element : *node->as_array()) {
      if (!element.is_integer()) fail(key, value_text(key), "must be " + forms);
      values.push_back(element.value<long long>().value());
    }
  } else if (node->is_string()) {
    static const std::regex pattern(R"(^\s*(-?\d+)\s*\.\.\s*(-?\d+)\s*$)");
    std::smatch match;
    const std::string text = node->value<std::string>().value();
    if (!std::regex_match(text, match, pattern))
      fail(key, "\"" + text + "\"", "must be " + forms + " with first <= last");
    // Bounds checked before the range is expanded, so "1..99999999999" is an error, not a hang.
    long long first = 0, last = 0;
    const std::string first_text = match[1], last_text = match[2];
    const auto [first_end, first_error] =
        std::from_chars(first_text.data(), first_text.data() + first_text.size(), first);
    const auto [last_end, last_error] = std::from_chars(last_text.data(), last_text.data() + last_text.size(), last);
    if (first_error != std::errc() || last_error != std::errc() || first > last)
      fail(key, "\"" + text + "\"", "must be " + forms + " with first <= last");
    if (first < min || last > max) fail(key, "\"" + text + "\"", range);
    for (long long v = first; v <= last; ++v) values.push_back(v);
  } else {
    fail(key, value_text(key), "must be " + forms);
  }
  if (values.empty()) fail(key, "[]", "must not be empty");
  for (long long v : values)
    if (v < min || v > max) fail(key, std::to_string(v), range);
  return values;
}

std::vector<std::string> TomlTable::string_list(const std::string& key,
                                                std::optional<std::vector<std::string>> fallback) const {
  const std::string forms = "a string, a number, or a list of them";
  if (!has(key)) {
    if (fallback) return *fallback;
    fail(key, "(missing)", forms + " is required");
  }
  const auto* node = table_->get(key);
  auto text_of = [&](const toml::node& element) -> std::string {
    if (element.is_string()) return element.value<std::string>().value();
    if (element.is_integer() || element.is_floating_point()) return format_full_precision(numeric_value(element));
    fail(key, value_text(key), "must be " + forms);
  };
  std::vector<std::string> values;
  if (node->is_array()) {
    for (const auto& element : *node->as_array()) values.push_back(text_of(element));
  } else {
    values.push_back(text_of(*node));
  }
  if (values.empty()) fail(key, "[]", "must not be empty");
  return values;
}

bool TomlTable::boolean(const std::string& key, bool fallback) const {
  if (!has(key)) return fallback;
  const auto* node = table_->get(key);
  if (!node->is_boolean()) fail(key, value_text(key), "must be true or false");
  return node->as_boolean()->get();
}

std::vector<std::array<double, 2>> TomlTable::pair_list(const std::string& key) const {
  std::vector<std::array<double, 2>> pairs;
  if (!has(key)) return pairs;
  const auto* node = table_->get(key);
  if (!node->is_array()) fail(key, value_text(key), "must be a list of pairs [[x, y], ...]");
  for (const auto& element : *node->as_array()) {
    const auto* pair = element.as_array();
    if (!pair || pair->size() != 2 || !(*pair)[0].is_number() || !(*pair)[1].is_number())
      fail(key, value_text(key), "must be a list of pairs of numbers [[x, y], ...]");
    const std::array<double, 2> values{numeric_value((*pair)[0]), numeric_value((*pair)[1])};
    if (!std::isfinite(values[0]) || !std::isfinite(values[1])) fail(key, value_text(key), "must hold finite numbers");
    pairs.push_back(values);
  }
  return pairs;
}

const toml::table& TomlTable::raw() const {
  static const toml::table empty;
  return table_ ? *table_ : empty;
}

TomlTable TomlTable::table(const std::string& key, bool required) const {
  if (!has(key)) {
    if (required) fail(key, "(missing)", "a table [" + qualified(key) + "] is required");
    TomlTable absent(root_, nullptr, file_, qualified(key));
    absent.origins_ = origins_;
    return absent;
  }
  const auto* node = table_->get(key);
  if (!node->is_table()) fail(key, value_text(key), "must be a table [" + qualified(key) + "]");
  TomlTable sub(root_, node->as_table(), file_, qualified(key));
  sub.origins_ = origins_;
  return sub;
}

std::vector<TomlTable> TomlTable::table_array(const std::string& key, bool required) const {
  std::vector<TomlTable> tables;
  if (!has(key)) {
    if (required) fail(key, "(missing)", "at least one [[" + qualified(key) + "]] block is required");
    return tables;
  }
  const auto* array = table_->get(key)->as_array();
  if (!array || !array->is_array_of_tables()) fail(key, value_text(key), "must be [[" + qualified(key) + "]] blocks");
  for (std::size_t k = 0; k < array->size(); ++k)
    tables.emplace_back(root_, array->get(k)->as_table(), file_, qualified(key) + "[" + std::to_string(k) + "]");
  return tables;
}

void TomlTable::reject_unknown_keys() const {
  if (!table_) return;
  for (const auto& [key_node, value] : *table_) {
    const std::string key(key_node.str());
    if (asked_.contains(key)) continue;
    std::string message = file_ + ": unknown key '" + qualified(key) + "'";
    if (const auto nearest = nearest_name(key, {asked_.begin(), asked_.end()}))
      message += " (did you mean '" + *nearest + "'?)";
    std::string known;
    for (const auto& k : asked_) known += (known.empty() ? "" : ", ") + k;
    message += "; known keys here: " + known;
    throw InputError(message);
  }
}

std::optional<std::string> nearest_name(const std::string& name, const std::vector<std::string>& candidates) {
  auto lower = [](std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
  };
  for (const auto& candidate : candidates)
    if (lower(candidate) == lower(name)) return candidate;
  const auto nearest = std::min_element(candidates.begin(), candidates.end(), [&](const auto& a, const auto& b) {
    return edit_distance(name, a) < edit_distance(name, b);
  });
  if (nearest != candidates.end() && edit_distance(name, *nearest) <= std::max<std::size_t>(2, name.size() / 3))
    return *nearest;
  return std::nullopt;
}

namespace {

TomlTable wrap(toml::table parsed, const std::string& name) {
  auto root = std::make_shared<const toml::table>(std::move(parsed));
  const toml::table* top = root.get();
  return TomlTable(std::move(root), top, name, "");
}

[[noreturn]] void rethrow_parse_error(const toml::parse_error& error, const std::string& name) {
  throw InputError(name + ":" + std::to_string(error.source().begin.line) + ":" +
                   std::to_string(error.source().begin.column) +
                   ": malformed TOML: " + std::string(error.description()));
}

}  // namespace

std::string read_text_file(const std::string& path) {
  errno = 0;
  std::ifstream file(path);
  if (!file) throw InputError(describe_io_failure("cannot open the file", path));
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

TomlTable parse_toml_file(const std::string& path) { return parse_toml_string(read_text_file(path), path); }

TomlTable parse_toml_string(const std::string& text, const std::string& name) {
  try {
    return wrap(toml::parse(text, name), name);
  } catch (const toml::parse_error& error) {
    rethrow_parse_error(error, name);
  }
}

}  // namespace hpcontact::io
