// Checked access to TOML input files (toml++): typed getters with ranges and defaults, and a
// check that rejects unknown keys with a "did you mean" suggestion. Every error names the file,
// the key, the value and what is allowed.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace toml {
inline namespace v3 {
class table;
}
}  // namespace toml

namespace hpcontact::io {

class TomlTable {
 public:
  TomlTable(std::shared_ptr<const toml::table> root, const toml::table* table, std::string file, std::string prefix);

  const std::string& file() const { return file_; }
  /// Where a key's value came from, for messages: the file, or what replaced the file's value
  /// (e.g. "hpcontact solve --p"), as recorded by `set_origins`.
  std::string origin(const std::string& key) const;
  /// Dotted key (e.g. "discretization.p") → origin of its value, for keys that did not come from
  /// the file. Tables taken from this one share the map.
  void set_origins(std::map<std::string, std::string> origins);
  /// Dotted name of a key of this table, e.g. "runs[1].p".
  std::string qualified(const std::string& key) const;
  bool has(const std::string& key) const;

  /// A number (integers are accepted). Required when no fallback is given.
  double number(const std::string& key, std::optional<double> fallback = std::nullopt) const;
  /// A number in [min, max] (inclusive).
  double number_in(const std::string& key, double min, double max, std::optional<double> fallback = std::nullopt) const;
  long long integer(const std::string& key, long long min, long long max,
                    std::optional<long long> fallback = std::nullopt) const;
  std::string string(const std::string& key, std::optional<std::string> fallback = std::nullopt) const;
  /// An expression's text: a string, or a number (written back at full precision, so that
  /// `E = 210e9` and `E = "210e9"` are the same value).
  std::string expression(const std::string& key, std::optional<std::string> fallback = std::nullopt) const;
  /// A string from a fixed set of choices.
  std::string choice(const std::string& key, const std::vector<std::string>& allowed,
                     std::optional<std::string> fallback = std::nullopt) const;
  /// Integers given as one integer, a list [1, 2, 4], or an inclusive range "1..12"; each in
  /// [min, max].
  std::vector<long long> integer_list(const std::string& key, long long min, long long max,
                                      std::optional<std::vector<long long>> fallback = std::nullopt) const;
  /// Strings or numbers, given as one value or a list; numbers are returned as their text
  /// (full precision), so "2/3" and 0.5 can stand side by side.
  std::vector<std::string> string_list(const std::string& key,
                                       std::optional<std::vector<std::string>> fallback = std::nullopt) const;
  bool boolean(const std::string& key, bool fallback) const;
  /// Pairs of numbers [[x, y], ...] (points); an empty list if absent.
  std::vector<std::array<double, 2>> pair_list(const std::string& key) const;
  /// A sub-table; an empty one if absent and not required.
  TomlTable table(const std::string& key, bool required = false) const;
  /// An array of tables ([[key]] blocks).
  std::vector<TomlTable> table_array(const std::string& key, bool required = false) const;

  /// The underlying toml++ table (an empty one for an absent table), for code that copies whole
  /// sub-trees (scene variants).
  const toml::table& raw() const;

  /// @throws InputError for the first key of this table that no getter asked for, with the
  /// nearest known key as suggestion. Call after reading the table.
  void reject_unknown_keys() const;
  /// The value of `key` as written (for messages about a key that is not allowed here).
  std::string value_text(const std::string& key) const;

 private:
  [[noreturn]] void fail(const std::string& key, const std::string& value, const std::string& allowed) const;

  std::shared_ptr<const toml::table> root_;
  const toml::table* table_;
  std::string file_;
  std::string prefix_;
  std::shared_ptr<const std::map<std::string, std::string>> origins_;
  mutable std::set<std::string> asked_;
};

/// The whole file as text. @throws InputError naming the file if it cannot be read.
std::string read_text_file(const std::string& path);

/// Parses a TOML file. @throws InputError with line and column if it cannot be read or parsed.
TomlTable parse_toml_file(const std::string& path);
/// Parses TOML text; `name` stands for the file in messages.
TomlTable parse_toml_string(const std::string& text, const std::string& name);

/// Levenshtein distance, for suggestions.
std::size_t edit_distance(const std::string& a, const std::string& b);
/// The candidate closest to `name` if it is close enough to be a typo of it (an edit distance of
/// at most max(2, a third of its length)); `name` is compared case-insensitively first, so that
/// "pc" finds "pC".
std::optional<std::string> nearest_name(const std::string& name, const std::vector<std::string>& candidates);

}  // namespace hpcontact::io
