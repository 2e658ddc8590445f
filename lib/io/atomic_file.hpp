// Output files written under a temporary name, synced to disk and renamed on success (and the
// folder synced), so that neither a failed run nor a power loss leaves a half-written or empty
// file behind; an interrupt (core/interrupt.hpp) removes the temporary file.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

namespace hpcontact::io {

/// Checks, leaving nothing behind, that files can be written into `directory`: it is a folder, or
/// does not exist yet, and a folder can be made in it or in its nearest existing ancestor (a
/// trial folder is made and removed there). Commands that write only at the end call this first,
/// so that bad input leaves no empty folder behind. @throws InputError otherwise.
void check_output_directory(const std::filesystem::path& directory);
/// The trial of check_output_directory in `path` (or its nearest existing ancestor); `given`
/// names the output folder in the message. @throws InputError.
void check_folder_can_be_made_in(const std::filesystem::path& path, const std::filesystem::path& given);
/// `directory` absolute and normalized, without a trailing separator ("out/", "out/." and "out"
/// are one folder). @throws InputError for an empty path.
std::filesystem::path normalized_folder(const std::filesystem::path& directory);

/// Creates the directory (and parents). @throws InputError naming it if that fails or it is not
/// writable.
void ensure_writable_directory(const std::filesystem::path& directory);

class AtomicFile {
 public:
  /// Opens "<path>.tmp-<pid>" for writing. @throws IoError if it cannot be created.
  explicit AtomicFile(std::filesystem::path path);
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ofstream& stream() { return stream_; }
  /// Flushes, syncs, closes and renames onto the final path, then syncs the folder.
  /// @throws IoError (path and the system's reason) on failure; the temporary file is removed.
  void commit();

 private:
  std::filesystem::path path_;
  std::filesystem::path temporary_;
  std::ofstream stream_;
  bool committed_ = false;
  int interrupt_slot_ = -1;
};

/// fsync of an existing file or folder. @throws IoError naming it.
void sync_to_disk(const std::filesystem::path& path);

/// Writes `content` to `path` atomically.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

}  // namespace hpcontact::io
