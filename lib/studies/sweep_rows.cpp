// Stored sweep rows: validated reading into records, durable appending, the folder lock; the rows
// a run holds.
#include "studies/sweep_rows.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <mpi.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <fstream>
#include <type_traits>

#include "core/byte_buffer.hpp"
#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "io/infsup_record_csv.hpp"

namespace hpcontact::studies {
namespace {

// Whether two rows of one point agree: the seconds differ between runs, every other number is the
// same (alpha_predicted NaN in both, as 3-D rows have it, agrees).
bool same_numbers(infsup::InfSupRecord a, infsup::InfSupRecord b) {
  a.seconds = b.seconds;
  if (std::isnan(a.alpha_predicted) && std::isnan(b.alpha_predicted)) a.alpha_predicted = b.alpha_predicted = 0.0;
  return a == b;
}

// Adds the whole rows of `file` whose point is one of `keys` to `rows`; a point stored twice with
// other numbers goes to `conflicting`, the other rows left out to `dropped` ("file:line").
void read_rows(const std::filesystem::path& file, bool with_header, const std::set<std::string>& keys,
               StoredRowsUse use, std::map<std::string, infsup::InfSupRecord>& rows, std::vector<std::string>& dropped,
               std::set<std::string>& conflicting) {
  std::ifstream in(file);
  if (!in) return;
  std::string line;
  int number = 0;
  if (with_header) {
    std::getline(in, line);
    ++number;
    if (line + '\n' != io::CsvTable(io::alpha_columns()).to_string())
      throw InputError("'" + file.string() + "' is not an alpha.csv written by this version of hpcontact sweep " +
                       (use == StoredRowsUse::resume
                            ? "(other columns): choose another --out folder, or --restart"
                            : "(other columns): merge only the folders of this sweep's slices"));
  }
  while (std::getline(in, line)) {
    ++number;
    if (line.empty()) continue;
    // A last line without its newline was cut while being written.
    const auto record = in.eof() ? std::nullopt : io::read_alpha_row(line);
    const std::string key = record ? point_key(*record) : "";
    if (key.empty() || !keys.contains(key)) {
      dropped.push_back(
          fmt::format("{}:{}{}", file.filename().string(), number, key.empty() ? "" : " (not a point of this study)"));
      continue;
    }
    const auto [held, inserted] = rows.emplace(key, *record);
    if (!inserted && !same_numbers(held->second, *record)) conflicting.insert(key);
  }
}

// Writes all of `text` to the open file `fd`, retrying after signals. @throws IoError naming `file`.
void write_all(int fd, const std::string& text, const std::filesystem::path& file) {
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string reason = describe_io_failure("cannot append to", file.string());
      close(fd);
      throw IoError(reason);
    }
    written += static_cast<std::size_t>(n);
  }
}

// Every rank's `bytes`, one piece per rank, on rank 0 (empty on the others). Collective.
std::vector<std::vector<char>> gather_bytes_on_rank_zero(const std::vector<char>& bytes) {
  const int rank = mpi_rank_and_size().first, size = mpi_rank_and_size().second;
  int length = static_cast<int>(bytes.size());
  std::vector<int> lengths(size), offsets(size, 0);
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<char> all;
  if (rank == 0) {
    for (int r = 1; r < size; ++r) offsets[r] = offsets[r - 1] + lengths[r - 1];
    all.resize(static_cast<std::size_t>(offsets[size - 1] + lengths[size - 1]));
  }
  MPI_Gatherv(bytes.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, 0, MPI_COMM_WORLD);
  std::vector<std::vector<char>> pieces;
  if (rank == 0)
    for (int r = 0; r < size; ++r) pieces.emplace_back(all.begin() + offsets[r], all.begin() + offsets[r] + lengths[r]);
  return pieces;
}

}  // namespace

std::string point_key(const std::string& problem, const std::string& norm, int p, int pc,
                      const space::MultiplierFamily& family, int level, long m) {
  return fmt::format("{}/{}/{}/{}/{}/{}/{}", problem, norm, p, pc, space::to_string(family), level, m);
}

std::string point_key(const infsup::InfSupRecord& record) {
  return point_key(infsup::to_string(record.problem), infsup::to_string(record.norm), record.p, record.pc,
                   record.family, record.level, record.m);
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

std::map<std::string, infsup::InfSupRecord> read_stored_rows(const std::filesystem::path& alpha_csv,
                                                             const std::set<std::string>& keys, bool warn,
                                                             StoredRowsUse use) {
  std::map<std::string, infsup::InfSupRecord> rows;
  std::vector<std::string> dropped;
  std::set<std::string> conflicting;
  read_rows(alpha_csv, true, keys, use, rows, dropped, conflicting);
  for (const auto& shard : existing_shards(alpha_csv)) read_rows(shard, false, keys, use, rows, dropped, conflicting);
  // Which of two rows of a point is right cannot be told: neither is kept.
  for (const auto& key : conflicting) rows.erase(key);
  if (warn && !conflicting.empty())
    fmt::print(stderr, "hpcontact: warning: {} point{} stored twice with other numbers in {} (e.g. {}): {}\n",
               conflicting.size(), conflicting.size() > 1 ? "s" : "", alpha_csv.string(), *conflicting.begin(),
               use == StoredRowsUse::resume ? "computed again" : "left out of this folder's rows");
  if (warn && !dropped.empty()) {
    std::string list;
    for (std::size_t k = 0; k < dropped.size() && k < 10; ++k) list += (k ? ", " : "") + dropped[k];
    if (dropped.size() > 10) list += fmt::format(" and {} more", dropped.size() - 10);
    fmt::print(stderr,
               "hpcontact: warning: {} stored row{} of {} {} (torn, incomplete, unparsable or not of this "
               "sweep): {}\n",
               dropped.size(), dropped.size() > 1 ? "s" : "", alpha_csv.string(),
               use == StoredRowsUse::resume
                   ? "will be computed again"
                   : (dropped.size() > 1 ? "are left out of the merge" : "is left out of the merge"),
               list);
  }
  return rows;
}

void append_durably(const std::filesystem::path& file, const std::vector<infsup::InfSupRecord>& records) {
  io::CsvTable rows(io::alpha_columns());
  for (const auto& record : records) io::add_alpha_row(rows, record);
  errno = 0;
  const int fd = open(file.c_str(), O_WRONLY | O_APPEND | O_CREAT, 0644);
  if (fd < 0) throw IoError(describe_io_failure("cannot open for appending", file.string()));
  write_all(fd, rows.rows_to_string(), file);
  const bool synced = fsync(fd) == 0;
  const std::string reason = synced ? "" : describe_io_failure("cannot sync to disk", file.string());
  close(fd);
  if (!synced) throw IoError(reason);
}

std::vector<std::pair<int, infsup::InfSupRecord>> gather_rows_on_rank_zero(
    const std::vector<std::pair<int, infsup::InfSupRecord>>& rows) {
  static_assert(std::is_trivially_copyable_v<infsup::InfSupRecord>, "records travel between ranks as bytes");
  std::vector<int> indices;
  std::vector<infsup::InfSupRecord> records;
  for (const auto& [index, record] : rows) indices.push_back(index), records.push_back(record);
  ByteWriter out;
  out.put(indices), out.put(records);
  std::vector<std::pair<int, infsup::InfSupRecord>> gathered;
  for (const auto& piece : gather_bytes_on_rank_zero(out.take())) {
    ByteReader in(piece);
    const auto piece_indices = in.get_vector<int>();
    const auto piece_records = in.get_vector<infsup::InfSupRecord>();
    HPC_VERIFY(in.at_end() && piece_indices.size() == piece_records.size(), "bytes of a rank's sweep rows garbled");
    for (std::size_t k = 0; k < piece_indices.size(); ++k) gathered.emplace_back(piece_indices[k], piece_records[k]);
  }
  std::sort(gathered.begin(), gathered.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return gathered;
}

FolderLock::FolderLock(const std::filesystem::path& folder) {
  const auto path = folder / ".sweep.lock";
  errno = 0;
  fd_ = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);  // (a child, e.g. MPI's, must not hold it)
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
  for (auto& [key, record] : read_stored_rows(alpha_csv, keys_, true, StoredRowsUse::merge)) {
    const auto [held, inserted] = rows_.emplace(key, record);
    if (!inserted && !same_numbers(held->second, record)) conflicts.push_back(key);
  }
  return conflicts;
}

std::set<std::string> AlphaRows::keys() const {
  std::set<std::string> keys;
  for (const auto& [key, record] : rows_) keys.insert(key);
  return keys;
}

std::vector<infsup::InfSupRecord> AlphaRows::records() const {
  std::vector<std::pair<std::size_t, const infsup::InfSupRecord*>> held;
  for (const auto& [key, record] : rows_) held.emplace_back(index_of_key_.at(key), &record);
  std::sort(held.begin(), held.end());
  std::vector<infsup::InfSupRecord> records;
  for (const auto& [index, record] : held) records.push_back(*record);
  return records;
}

std::string AlphaRows::content() const {
  io::CsvTable table(io::alpha_columns());
  for (const auto& record : records()) io::add_alpha_row(table, record);
  return table.to_string();
}

}  // namespace hpcontact::studies
