// Output files written under a temporary name and renamed on success, so that a failed run
// never leaves a half-written file behind.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

namespace hpcontact::io {

/// Checks, creating nothing, that `directory` exists and is writable or could be created (its
/// nearest existing ancestor is a writable folder): commands that write only at the end call
/// this first, so that bad input leaves no empty folder behind. @throws InputError otherwise.
void check_output_directory(const std::filesystem::path& directory);

/// Creates the directory (and parents). @throws InputError naming it if that fails or it is not
/// writable.
void ensure_writable_directory(const std::filesystem::path& directory);

class AtomicFile {
 public:
  /// Opens "<path>.tmp-<pid>" for writing. @throws InputError if it cannot be created.
  explicit AtomicFile(std::filesystem::path path);
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ofstream& stream() { return stream_; }
  /// Flushes, closes and renames onto the final path. @throws InputError on I/O failure.
  void commit();

 private:
  std::filesystem::path path_;
  std::filesystem::path temporary_;
  std::ofstream stream_;
  bool committed_ = false;
};

/// Writes `content` to `path` atomically.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

}  // namespace hpcontact::io
