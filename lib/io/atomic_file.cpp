// AtomicFile: temporary name + rename (atomic on POSIX within one file system).
#include "io/atomic_file.hpp"

#include <unistd.h>

#include <system_error>

#include "core/error.hpp"

namespace hpcontact::io {

void ensure_writable_directory(const std::filesystem::path& directory) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error || !std::filesystem::is_directory(directory))
    throw InputError("output folder '" + directory.string() +
                     "' cannot be created: " + (error ? error.message() : "not a directory"));
  if (access(directory.c_str(), W_OK) != 0)
    throw InputError("output folder '" + directory.string() + "' is not writable");
}

void check_output_directory(const std::filesystem::path& directory) {
  // The folder itself, or else its nearest existing ancestor, must be a writable folder.
  std::filesystem::path existing = std::filesystem::absolute(directory);
  while (!std::filesystem::exists(existing) && existing.has_parent_path() && existing != existing.parent_path())
    existing = existing.parent_path();
  if (!std::filesystem::is_directory(existing))
    throw InputError("output folder '" + directory.string() + "' cannot be created: '" + existing.string() +
                     "' is not a folder");
  if (access(existing.c_str(), W_OK) != 0)
    throw InputError("output folder '" + directory.string() + "' cannot be written: '" + existing.string() +
                     "' is not writable");
}

AtomicFile::AtomicFile(std::filesystem::path path) : path_(std::move(path)) {
  temporary_ = path_;
  temporary_ += ".tmp-" + std::to_string(getpid());
  stream_.open(temporary_, std::ios::out | std::ios::trunc);
  if (!stream_)
    throw InputError("cannot write output file '" + path_.string() +
                     "' (is the folder writable?)");
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  stream_.close();
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
}

void AtomicFile::commit() {
  stream_.flush();
  const bool good = static_cast<bool>(stream_);
  stream_.close();
  if (!good) throw InputError("writing output file '" + path_.string() + "' failed");
  std::error_code error;
  std::filesystem::rename(temporary_, path_, error);
  if (error)
    throw InputError("cannot move output into '" + path_.string() + "': " + error.message());
  committed_ = true;
}

void write_file_atomically(const std::filesystem::path& path, const std::string& content) {
  AtomicFile file(path);
  file.stream() << content;
  file.commit();
}

}  // namespace hpcontact::io
