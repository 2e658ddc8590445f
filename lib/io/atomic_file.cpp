// AtomicFile: temporary name + fsync + rename (atomic on POSIX within one file system) + fsync of
// the folder.
#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

#include "core/error.hpp"
#include "core/interrupt.hpp"

namespace hpcontact::io {

void ensure_writable_directory(const std::filesystem::path& directory) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error || !std::filesystem::is_directory(directory))
    throw InputError("output folder (--out) '" + directory.string() +
                     "' cannot be created: " + (error ? error.message() : "not a directory"));
  if (access(directory.c_str(), W_OK) != 0)
    throw InputError("output folder (--out) '" + directory.string() + "' is not writable");
}

std::filesystem::path normalized_folder(const std::filesystem::path& directory) {
  if (directory.empty()) throw InputError("output folder (--out) '': an empty path; name a folder");
  std::filesystem::path path = std::filesystem::absolute(directory).lexically_normal();
  // "DIR/" and "DIR/." name DIR: its siblings (staging folders) must not land inside it.
  if (!path.has_filename() && path.has_parent_path() && path != path.root_path()) path = path.parent_path();
  return path;
}

void check_folder_can_be_made_in(const std::filesystem::path& path, const std::filesystem::path& given) {
  std::filesystem::path existing = path;
  while (!std::filesystem::exists(existing) && existing.has_parent_path() && existing != existing.parent_path())
    existing = existing.parent_path();
  if (!std::filesystem::is_directory(existing))
    throw InputError("output folder (--out) '" + given.string() + "' cannot be created: '" + existing.string() +
                     "' is not a folder");
  // A trial folder made and removed says what access() cannot (read-only mounts, /proc, quotas).
  std::string trial = (existing / ".hpcontact-trial-XXXXXX").string();
  errno = 0;
  if (!mkdtemp(trial.data()))
    throw InputError(describe_io_failure(
        "output folder (--out) '" + given.string() + "' cannot be written: no folder can be made in",
        existing.string()));
  rmdir(trial.c_str());
}

void check_output_directory(const std::filesystem::path& directory) {
  // The files go into the folder itself: it, or else its nearest existing ancestor, must take them.
  const std::filesystem::path path = normalized_folder(directory);
  if (std::filesystem::exists(path) && !std::filesystem::is_directory(path))
    throw InputError("output folder (--out) '" + directory.string() + "' exists and is not a folder");
  check_folder_can_be_made_in(path, directory);
}

void sync_to_disk(const std::filesystem::path& path) {
  errno = 0;
  const int fd = open(path.c_str(), O_RDONLY);
  if (fd < 0) throw IoError(describe_io_failure("cannot open for syncing", path.string()));
  const bool synced = fsync(fd) == 0;
  const std::string reason = synced ? "" : describe_io_failure("cannot sync to disk", path.string());
  close(fd);
  if (!synced) throw IoError(reason);
}

AtomicFile::AtomicFile(std::filesystem::path path) : path_(std::move(path)) {
  temporary_ = path_;
  temporary_ += ".tmp-" + std::to_string(getpid());
  interrupt_slot_ = register_file_in_progress(temporary_.string());
  errno = 0;
  stream_.open(temporary_, std::ios::out | std::ios::trunc);
  if (!stream_) {
    const std::string reason = describe_io_failure("cannot write output file", path_.string());
    release_file_in_progress(interrupt_slot_);
    throw IoError(reason);
  }
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  stream_.close();
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
  release_file_in_progress(interrupt_slot_);
}

void AtomicFile::commit() {
  throw_if_cancelled();  // an interrupted run writes nothing
  // errno still holds the reason of a write that failed earlier (buffered writes of the caller).
  stream_.flush();
  const bool good = static_cast<bool>(stream_);
  const std::string reason = describe_io_failure("cannot write output file", path_.string());
  stream_.close();
  if (!good) throw IoError(reason);
  sync_to_disk(temporary_);
  std::error_code error;
  std::filesystem::rename(temporary_, path_, error);
  if (error) throw IoError("cannot move output into '" + path_.string() + "': " + error.message());
  committed_ = true;
  release_file_in_progress(interrupt_slot_);
  sync_to_disk(std::filesystem::absolute(path_).parent_path());
}

void write_file_atomically(const std::filesystem::path& path, const std::string& content) {
  AtomicFile file(path);
  file.stream() << content;
  file.commit();
}

}  // namespace hpcontact::io
