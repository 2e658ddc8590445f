// The identity of a sweep's folder: computed from the study, stored beside alpha.csv, compared
// before a resume or a merge.
#include "studies/sweep_folder.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <map>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace hpcontact::studies {
namespace {

constexpr const char* kHeader = "# The study whose rows this folder holds (hpcontact sweep): a resume must match it.\n";

// FNV-1a of a file's bytes: a mesh file edited in place changes the rows of every level using it.
std::string file_digest(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "unreadable";
  std::uint64_t hash = 14695981039346656037ull;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    for (std::streamsize k = 0; k < in.gcount(); ++k) {
      hash ^= static_cast<unsigned char>(buffer[k]);
      hash *= 1099511628211ull;
    }
    if (in.eof()) break;
  }
  return fmt::format("{:016x}", hash);
}

template <typename T, typename Name>
std::string listed(const std::vector<T>& values, Name name, const std::string& when_empty) {
  if (values.empty()) return when_empty;
  std::vector<std::string> names;
  for (const auto& value : values) names.push_back(name(value));
  return fmt::format("{}", fmt::join(names, " "));
}

// One line per key: the value is everything after the first " = " (values keep no newline).
std::map<std::string, std::string> keyed(const std::vector<std::string>& lines) {
  std::map<std::string, std::string> values;
  for (const auto& line : lines) {
    if (line.empty() || line[0] == '#') continue;
    const auto equals = line.find(" = ");
    if (equals == std::string::npos)
      values[line] = "";
    else
      values[line.substr(0, equals)] = line.substr(equals + 3);
  }
  return values;
}

std::vector<std::string> read_lines(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// "key: X in the folder, Y in the study" for up to five keys whose values differ.
std::string differences(const std::map<std::string, std::string>& stored,
                        const std::map<std::string, std::string>& study) {
  std::vector<std::string> changes;
  auto value_in = [](const std::map<std::string, std::string>& values, const std::string& key) {
    const auto found = values.find(key);
    return found == values.end() ? std::string("(absent)") : found->second;
  };
  std::map<std::string, std::string> every = stored;
  every.insert(study.begin(), study.end());
  for (const auto& [key, unused] : every) {
    const std::string before = value_in(stored, key), now = value_in(study, key);
    if (before != now) changes.push_back(fmt::format("{}: {} in the folder, {} in the study", key, before, now));
  }
  std::string text;
  for (std::size_t k = 0; k < changes.size() && k < 5; ++k) text += (k ? "; " : "") + changes[k];
  if (changes.size() > 5) text += fmt::format("; and {} more", changes.size() - 5);
  return text;
}

}  // namespace

std::filesystem::path identity_path(const std::filesystem::path& folder) { return folder / "sweep_identity.txt"; }

std::vector<std::string> sweep_identity(const StabilitySweep& sweep) {
  auto number = [](int value) { return std::to_string(value); };
  std::vector<std::string> lines = {
      "sweep.p = " + listed(sweep.degrees, number, "the scene's"),
      "sweep.pC = " + listed(sweep.multiplier_degrees, number, "the scene's"),
      std::string("sweep.pc_rule = ") + (sweep.pc_below_p ? "below_p" : "all"),
      "sweep.ratio = " + listed(
                             sweep.ratios, [](const scene::Ratio& r) { return r.text; }, "the scene's"),
      "sweep.norm = " + listed(
                            sweep.norms, [](infsup::GramNorm n) { return infsup::to_string(n); }, ""),
      "sweep.problem = " + listed(
                               sweep.problems, [](infsup::PairingProblem p) { return infsup::to_string(p); }, ""),
      "sweep.family = " + listed(
                              sweep.families, [](space::MultiplierFamily f) { return space::to_string(f); }, ""),
      "sweep.eigensolver = " + sweep.eigensolver,
      fmt::format("sweep.alpha_tol = {}", sweep.alpha_tolerance),
      fmt::format("sweep.levels = {}", sweep.levels.size())};
  for (std::size_t level = 0; level < sweep.levels.size(); ++level) {
    const auto& variant = sweep.levels[level];
    const std::string prefix = fmt::format("level {}: ", level + 1);
    for (std::string key : variant.keys) {
      std::replace(key.begin(), key.end(), '\n', ' ');
      lines.push_back(prefix + key);
    }
    // (Named by the key, not the path: the path is relative to where the sweep runs.)
    if (!variant.scene.mesh_file.empty())
      lines.push_back(prefix + "contents of domain.mesh = " + file_digest(variant.scene.mesh_file));
    if (variant.scene.pair && !variant.scene.pair->master.mesh_file.empty())
      lines.push_back(prefix +
                      "contents of the master's domain.mesh = " + file_digest(variant.scene.pair->master.mesh_file));
  }
  return lines;
}

void claim_sweep_folder(const std::filesystem::path& folder, const std::vector<std::string>& identity,
                        bool merge_source) {
  const auto file = identity_path(folder);
  const auto alpha_csv = folder / "alpha.csv";
  const bool has_rows = std::filesystem::exists(alpha_csv) || !existing_shards(alpha_csv).empty();
  const std::string way_out = merge_source ? "merge only the folders of this study's slices"
                                           : "choose another --out folder, or --restart to replace its rows";
  if (!std::filesystem::exists(file) && has_rows)
    throw InputError(
        fmt::format("'{}' holds sweep rows without {} (another version's, or copied there): they "
                    "cannot be matched to this study; {}",
                    folder.string(), file.filename().string(), way_out));
  // A folder without rows (new, or a run stopped before its first group) is this study's now.
  if (!has_rows) {
    if (!merge_source) write_sweep_identity(folder, identity);
    return;
  }
  const std::string changed = differences(keyed(read_lines(file)), keyed(identity));
  if (!changed.empty())
    throw InputError(fmt::format("'{}' holds the rows of another study ({}): {}; {}", folder.string(),
                                 file.filename().string(), changed, way_out));
}

void write_sweep_identity(const std::filesystem::path& folder, const std::vector<std::string>& identity) {
  std::string text = kHeader;
  for (const auto& line : identity) text += line + "\n";
  io::write_file_atomically(identity_path(folder), text);
}

std::unique_ptr<FolderLock> open_sweep_folder(const StabilitySweep& sweep, const std::filesystem::path& folder,
                                              bool restart) {
  io::ensure_writable_directory(folder);
  auto lock = std::make_unique<FolderLock>(folder);
  const auto alpha_csv = folder / "alpha.csv";
  if (restart) {
    std::filesystem::remove(alpha_csv);
    for (const auto& shard : existing_shards(alpha_csv)) std::filesystem::remove(shard);
    std::filesystem::remove(identity_path(folder));
  }
  claim_sweep_folder(folder, sweep_identity(sweep));
  return lock;
}

}  // namespace hpcontact::studies
