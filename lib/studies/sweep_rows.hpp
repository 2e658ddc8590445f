// The rows of a sweep's alpha.csv as they are stored between runs: read back into records with
// validation when a sweep resumes, and appended durably, group by group, to one shard per MPI rank
// ("alpha.csv.rank<r>") so that an interrupted run keeps every finished group; and the rows a run
// holds (AlphaRows), written in the order of the points.
#pragma once

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "infsup/infsup_record.hpp"
#include "studies/sweep_plan.hpp"

namespace hpcontact::studies {

/// Identifies a point for resuming: the ratio through m, degrees as reported.
std::string point_key(const std::string& problem, const std::string& norm, int p, int pc,
                      const space::MultiplierFamily& family, int level, long m);
/// The key of the point a record belongs to (SweepPoint::key of that point).
std::string point_key(const infsup::InfSupRecord& record);

/// Why stored rows are read: to resume a sweep in its folder, or to merge the folders of its slices.
/// The messages differ (a dropped row is computed again, or left out of the merge).
enum class StoredRowsUse { resume, merge };

/// The rows stored for a sweep, key → record, from alpha.csv and every shard beside it. A row is
/// kept only if it is whole (io::read_alpha_row) and its key is one of `keys` (a point of the
/// study); the others are dropped with one warning on stderr (when `warn`) naming the file and line.
/// @throws InputError if alpha.csv has other columns (another program's or version's file).
std::map<std::string, infsup::InfSupRecord> read_stored_rows(const std::filesystem::path& alpha_csv,
                                                             const std::set<std::string>& keys, bool warn,
                                                             StoredRowsUse use = StoredRowsUse::resume);

/// The shard of `rank` beside alpha.csv, and all shards present (of any earlier run).
std::filesystem::path shard_path(const std::filesystem::path& alpha_csv, int rank);
std::vector<std::filesystem::path> existing_shards(const std::filesystem::path& alpha_csv);

/// Appends `records` as rows of alpha.csv (without its header) to `file` and syncs it to disk.
/// @throws IoError naming the file.
void append_durably(const std::filesystem::path& file, const std::vector<infsup::InfSupRecord>& records);

/// Every rank's (point index, record) pairs gathered on rank 0 of MPI_COMM_WORLD, sorted by index
/// (empty on the other ranks). Collective.
std::vector<std::pair<int, infsup::InfSupRecord>> gather_rows_on_rank_zero(
    const std::vector<std::pair<int, infsup::InfSupRecord>>& rows);

/// Holds an exclusive lock on `folder`/.sweep.lock for the life of the object (released when the
/// process ends, however it ends). @throws InputError naming the process that holds it.
class FolderLock {
 public:
  explicit FolderLock(const std::filesystem::path& folder);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  int fd_ = -1;
};

/// The rows of alpha.csv: those stored by an earlier run (validated: bad or foreign rows are
/// computed again) and the new ones, always in the order of the points.
class AlphaRows {
 public:
  explicit AlphaRows(const std::vector<SweepPoint>& points);
  /// Adds the valid rows stored in alpha_csv and the per-rank shards beside it; a point already
  /// held keeps its row.
  void read(const std::filesystem::path& alpha_csv, bool warn);
  /// Adds the rows of one slice's folder; returns the keys it holds that an earlier folder already
  /// gave with other numbers (any column but the seconds), which keep the earlier row.
  std::vector<std::string> merge_slice(const std::filesystem::path& alpha_csv);
  bool has(const std::string& key) const { return rows_.contains(key); }
  std::set<std::string> keys() const;
  void set(const std::string& key, const infsup::InfSupRecord& record) { rows_[key] = record; }
  /// Whether every point has its row.
  bool complete() const { return rows_.size() == index_of_key_.size(); }
  /// The rows held, in the order of the points.
  std::vector<infsup::InfSupRecord> records() const;
  /// The file's text: the header and the rows held, in the order of the points.
  std::string content() const;

 private:
  std::set<std::string> keys_;
  std::map<std::string, std::size_t> index_of_key_;
  std::map<std::string, infsup::InfSupRecord> rows_;
};

}  // namespace hpcontact::studies
