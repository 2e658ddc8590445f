// OutputFolder: staging folder, marker file, renameat2(RENAME_EXCHANGE) into place.
#include "io/output_folder.hpp"

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>

#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "io/atomic_file.hpp"

namespace hpcontact::io {
namespace {
constexpr const char* kMarker = ".hpcontact-output";

// An existing folder is replaced whole on commit only if hpcontact wrote it.
void check_replaceable(const std::filesystem::path& out) {
  if (!std::filesystem::exists(out)) return;
  if (!std::filesystem::is_directory(out))
    throw InputError("output folder (--out) '" + out.string() + "' exists and is not a folder");
  // (summary.json: a folder of a version before the marker)
  if (!std::filesystem::is_empty(out) && !std::filesystem::exists(out / kMarker) &&
      !std::filesystem::exists(out / "summary.json"))
    throw InputError("output folder (--out) '" + out.string() + "' holds files that hpcontact did not write (no " +
                     kMarker + "): choose a new or empty folder; a folder of an earlier run is replaced whole");
}
// Staging folders "<out>.tmp-<pid>" of processes that no longer run (killed before they could
// clean up) are removed: no run of theirs can commit them any more. Those of live processes,
// another run into the same folder, are left alone.
void remove_stale_staging(const std::filesystem::path& out) {
  const std::string prefix = out.filename().string() + ".tmp-";
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(out.parent_path(), error)) {
    const std::string name = entry.path().filename().string();
    if (!name.starts_with(prefix)) continue;
    const std::string digits = name.substr(prefix.size());
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) continue;
    const pid_t pid = static_cast<pid_t>(std::stol(digits));
    if (pid == getpid() || kill(pid, 0) == 0 || errno != ESRCH) continue;
    std::error_code ignored;
    std::filesystem::remove_all(entry.path(), ignored);
  }
}

}  // namespace

void check_output_folder(const std::filesystem::path& out) {
  check_output_directory(out);
  // The outputs are staged beside the folder, in its parent.
  check_folder_can_be_made_in(normalized_folder(out).parent_path(), out);
  check_replaceable(normalized_folder(out));
}

OutputFolder::OutputFolder(std::filesystem::path out) : out_(normalized_folder(out)) {
  check_replaceable(out_);
  remove_stale_staging(out_);
  staging_ = out_;
  staging_ += ".tmp-" + std::to_string(getpid());
  std::error_code error;
  std::filesystem::remove_all(staging_, error);
  errno = 0;
  if (!std::filesystem::create_directories(staging_, error))
    throw IoError("cannot create the output folder '" + staging_.string() + "': " + error.message());
  interrupt_slot_ = register_folder_in_progress(staging_.string());
  write_file_atomically(staging_ / kMarker, "outputs of one hpcontact run; the folder is replaced whole by the next\n");
}

OutputFolder::~OutputFolder() {
  if (committed_) return;
  std::error_code ignored;
  std::filesystem::remove_all(staging_, ignored);
  release_file_in_progress(interrupt_slot_);
}

void OutputFolder::commit() {
  throw_if_cancelled();  // an interrupted run writes nothing
  sync_to_disk(staging_);
  errno = 0;
  if (std::filesystem::exists(out_)) {
    // Swap atomically: --out is this run's folder at once, the old one is now at the staging name.
    if (renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, out_.c_str(), RENAME_EXCHANGE) != 0)
      throw IoError(describe_io_failure("cannot move the outputs into", out_.string()));
    committed_ = true;
    release_file_in_progress(interrupt_slot_);
    std::error_code ignored;
    std::filesystem::remove_all(staging_, ignored);
  } else {
    std::error_code error;
    std::filesystem::create_directories(out_.parent_path(), error);
    if (std::rename(staging_.c_str(), out_.c_str()) != 0)
      throw IoError(describe_io_failure("cannot move the outputs into", out_.string()));
    committed_ = true;
    release_file_in_progress(interrupt_slot_);
  }
  sync_to_disk(out_.parent_path());
}

}  // namespace hpcontact::io
