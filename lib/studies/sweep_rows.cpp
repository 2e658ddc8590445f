// Stored sweep rows: validated reading, durable appending, the folder lock; the rows a run holds.
#include "studies/sweep_rows.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <mpi.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "io/csv_writer.hpp"
#include "studies/stability_sweep.hpp"

namespace hpcontact::studies {
namespace {

bool parses_completely(const std::string& text, bool integer) {
  if (text.empty()) return false;
  const char* end = text.data() + text.size();
  if (integer) {
    long long value = 0;
    const auto [ptr, error] = std::from_chars(text.data(), end, value);
    return error == std::errc() && ptr == end;
  }
  double value = 0.0;
  const auto [ptr, error] = std::from_chars(text.data(), end, value);
  return error == std::errc() && ptr == end;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream stream(line);
  for (std::string cell; std::getline(stream, cell, ',');) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

// The key of a complete, well-formed row, or "" if it is not one.
std::string key_of_row(const std::vector<std::string>& header, const std::vector<std::string>& cells) {
  if (cells.size() != header.size()) return "";
  std::map<std::string, std::string> row;
  for (std::size_t k = 0; k < header.size(); ++k) {
    const std::string& column = header[k];
    if (column == "problem" || column == "norm") {
      if (cells[k].empty()) return "";
    } else {
      const bool integer = column == "p" || column == "pC" || column == "level" || column == "n" || column == "m" ||
                           column == "ndofs" || column == "nmult";
      if (!parses_completely(cells[k], integer)) return "";
    }
    row[column] = cells[k];
  }
  return point_key(row["problem"], row["norm"], std::stoi(row["p"]), std::stoi(row["pC"]), std::stoi(row["level"]),
                   std::stol(row["m"]));
}

void read_rows(const std::filesystem::path& file, bool with_header, const std::set<std::string>& keys,
               StoredRowsUse use, std::map<std::string, std::string>& rows, std::vector<std::string>& dropped) {
  std::ifstream in(file);
  if (!in) return;
  const std::vector<std::string> header = alpha_columns();
  std::string line;
  int number = 0;
  if (with_header) {
    std::getline(in, line);
    ++number;
    if (split(line) != header)
      throw InputError("'" + file.string() + "' is not an alpha.csv written by this version of hpcontact sweep " +
                       (use == StoredRowsUse::resume
                            ? "(other columns): choose another --out folder, or --restart"
                            : "(other columns): merge only the folders of this sweep's slices"));
  }
  while (std::getline(in, line)) {
    ++number;
    if (line.empty()) continue;
    // A last line without its newline was cut while being written.
    const bool whole = !in.eof();
    const std::string key = whole ? key_of_row(header, split(line)) : "";
    if (key.empty() || !keys.contains(key)) {
      dropped.push_back(
          fmt::format("{}:{}{}", file.filename().string(), number, key.empty() ? "" : " (not a point of this study)"));
      continue;
    }
    rows[key] = line + '\n';
  }
}

}  // namespace

std::string point_key(const std::string& problem, const std::string& norm, int p, int pc, int level, long m) {
  return fmt::format("{}/{}/{}/{}/{}/{}", problem, norm, p, pc, level, m);
}

std::filesystem::path shard_path(const std::filesystem::path& alpha_csv, int rank) {
  std::filesystem::path shard = alpha_csv;
  shard += ".rank" + std::to_string(rank);
  return shard;
}

std::vector<std::filesystem::path> existing_shards(const std::filesystem::path& alpha_csv) {
  std::vector<std::filesystem::path> shards;
  const auto folder = alpha_csv.parent_path().empty() ? std::filesystem::path(".") : alpha_csv.parent_path();
  const std::string prefix = alpha_csv.filename().string() + ".rank";
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error))
    if (entry.path().filename().string().rfind(prefix, 0) == 0) shards.push_back(entry.path());
  std::sort(shards.begin(), shards.end());
  return shards;
}

std::map<std::string, std::string> read_stored_rows(const std::filesystem::path& alpha_csv,
                                                    const std::set<std::string>& keys, bool warn, StoredRowsUse use) {
  std::map<std::string, std::string> rows;
  std::vector<std::string> dropped;
  read_rows(alpha_csv, true, keys, use, rows, dropped);
  for (const auto& shard : existing_shards(alpha_csv)) read_rows(shard, false, keys, use, rows, dropped);
  if (warn && !dropped.empty()) {
    std::string list;
    for (std::size_t k = 0; k < dropped.size() && k < 10; ++k) list += (k ? ", " : "") + dropped[k];
    if (dropped.size() > 10) list += fmt::format(" and {} more", dropped.size() - 10);
    fmt::print(stderr,
               "hpcontact: warning: {} stored row{} of {} {} (torn, incomplete, unparsable or not of this "
               "sweep): {}\n",
               dropped.size(), dropped.size() > 1 ? "s" : "", alpha_csv.string(),
               use == StoredRowsUse::resume ? "will be computed again" : "are left out of the merge", list);
  }
  return rows;
}

void append_durably(const std::filesystem::path& file, const std::string& lines) {
  errno = 0;
  const int fd = open(file.c_str(), O_WRONLY | O_APPEND | O_CREAT, 0644);
  if (fd < 0) throw IoError(describe_io_failure("cannot open for appending", file.string()));
  std::size_t written = 0;
  while (written < lines.size()) {
    const ssize_t n = write(fd, lines.data() + written, lines.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string reason = describe_io_failure("cannot append to", file.string());
      close(fd);
      throw IoError(reason);
    }
    written += static_cast<std::size_t>(n);
  }
  const bool synced = fsync(fd) == 0;
  const std::string reason = synced ? "" : describe_io_failure("cannot sync to disk", file.string());
  close(fd);
  if (!synced) throw IoError(reason);
}

FolderLock::FolderLock(const std::filesystem::path& folder) {
  const auto path = folder / ".sweep.lock";
  errno = 0;
  fd_ = open(path.c_str(), O_RDWR | O_CREAT, 0644);
  if (fd_ < 0) throw IoError(describe_io_failure("cannot create the lock file", path.string()));
  if (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    char holder[64] = {};
    const ssize_t n = pread(fd_, holder, sizeof holder - 1, 0);
    close(fd_);
    fd_ = -1;
    throw InputError(
        fmt::format("output folder '{}' is in use by another sweep (process {}, lock {}): wait for it, "
                    "or choose another --out folder",
                    folder.string(), n > 0 ? std::string(holder) : "unknown", path.string()));
  }
  const std::string pid = std::to_string(getpid());
  if (ftruncate(fd_, 0) != 0 || pwrite(fd_, pid.data(), pid.size(), 0) < 0) {
    // The lock holds without the note of its holder; nothing else depends on it.
  }
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) close(fd_);  // releases the lock
}

namespace {

// A row of alpha.csv without its last column (the seconds, which differ between runs).
std::string without_seconds(const std::string& line) { return line.substr(0, line.rfind(',')); }

}  // namespace

AlphaRows::AlphaRows(const std::vector<SweepPoint>& points) {
  for (std::size_t k = 0; k < points.size(); ++k) {
    index_of_key_[points[k].key()] = k;
    keys_.insert(points[k].key());
  }
}

void AlphaRows::read(const std::filesystem::path& alpha_csv, bool warn) {
  rows_.merge(read_stored_rows(alpha_csv, keys_, warn));
}

std::vector<std::string> AlphaRows::merge_slice(const std::filesystem::path& alpha_csv) {
  std::vector<std::string> conflicts;
  for (auto& [key, line] : read_stored_rows(alpha_csv, keys_, true, StoredRowsUse::merge)) {
    const auto [held, inserted] = rows_.emplace(key, line);
    if (!inserted && without_seconds(held->second) != without_seconds(line)) conflicts.push_back(key);
  }
  return conflicts;
}

std::set<std::string> AlphaRows::keys() const {
  std::set<std::string> keys;
  for (const auto& [key, line] : rows_) keys.insert(key);
  return keys;
}

std::string AlphaRows::content() const {
  std::vector<std::pair<std::size_t, const std::string*>> lines;
  for (const auto& [key, line] : rows_) lines.emplace_back(index_of_key_.at(key), &line);
  std::sort(lines.begin(), lines.end());
  std::string content = io::CsvTable(alpha_columns()).to_string();
  for (const auto& [index, line] : lines) content += *line;
  return content;
}

std::vector<std::pair<int, std::string>> gather_rows_on_rank_zero(
    const std::vector<std::pair<int, std::string>>& rows) {
  const int rank = mpi_rank_and_size().first, size = mpi_rank_and_size().second;
  std::string packed;
  for (const auto& [index, line] : rows) packed += std::to_string(index) + '\t' + line;  // line ends in '\n'
  int length = static_cast<int>(packed.size());
  std::vector<int> lengths(size), offsets(size, 0);
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::string all;
  if (rank == 0) {
    for (int r = 1; r < size; ++r) offsets[r] = offsets[r - 1] + lengths[r - 1];
    all.resize(static_cast<std::size_t>(offsets[size - 1] + lengths[size - 1]));
  }
  MPI_Gatherv(packed.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, 0, MPI_COMM_WORLD);
  std::vector<std::pair<int, std::string>> out;
  std::stringstream stream(all);
  for (std::string index, line; std::getline(stream, index, '\t') && std::getline(stream, line);)
    out.emplace_back(std::stoi(index), line + '\n');
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace hpcontact::studies
