// A run's outputs as one set: written into a temporary folder beside --out and moved into place
// when all of them are written, so that --out holds either the previous run's outputs or this
// run's, never a mixture, and a failed or interrupted run leaves no partial set.
#pragma once

#include <filesystem>

namespace hpcontact::io {

/// Checks, creating nothing that stays, that `out` can become a run's output folder: writable or
/// creatable (io::check_output_directory) and, if it exists, a folder hpcontact wrote or an empty
/// one. Commands that write at the end call this first. @throws InputError.
void check_output_folder(const std::filesystem::path& out);

class OutputFolder {
 public:
  /// Creates "<out>.tmp-<pid>". An existing `out` must be a folder that hpcontact wrote (it has the
  /// marker file .hpcontact-output): it is replaced whole on commit, never mixed with new files.
  /// @throws InputError if `out` holds anything else, IoError if the folder cannot be created.
  explicit OutputFolder(std::filesystem::path out);
  /// Removes the temporary folder unless commit() succeeded.
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  /// Where the outputs are written until commit().
  const std::filesystem::path& path() const { return staging_; }
  /// Syncs the folder and moves it into place (swapping with an existing `out` atomically, then
  /// removing the old one). @throws IoError.
  void commit();

 private:
  std::filesystem::path out_, staging_;
  bool committed_ = false;
  int interrupt_slot_ = -1;
};

}  // namespace hpcontact::io
