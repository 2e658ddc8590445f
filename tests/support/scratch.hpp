// Scratch folders for the tests: every test that writes files writes them under one folder of
// its own process, made fresh under the system's temporary directory (TMPDIR, else /tmp) with a
// unique name (mkdtemp), and removed with everything in it when the process ends. Two test runs
// on one machine, or two test processes of one run, never share a folder.
#pragma once

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace hpcontact::testing {

namespace detail {

// The process's folder: made on first use, removed at exit (by the process that made it only: a
// forked child that exits must not remove its parent's files).
class ScratchRoot {
 public:
  ScratchRoot() : owner_(::getpid()) {
    std::string pattern = (std::filesystem::temp_directory_path() / "hpcontact_test_XXXXXX").string();
    if (!::mkdtemp(pattern.data()))
      throw std::runtime_error("cannot make a scratch folder from " + pattern + ": " + std::strerror(errno));
    path_ = pattern;
  }
  ~ScratchRoot() {
    std::error_code ignored;  // (a destructor at exit must not throw)
    if (::getpid() == owner_) std::filesystem::remove_all(path_, ignored);
  }
  ScratchRoot(const ScratchRoot&) = delete;
  ScratchRoot& operator=(const ScratchRoot&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  pid_t owner_;
  std::filesystem::path path_;
};

}  // namespace detail

/// This process's scratch folder (unique per process and run, removed when the process ends).
inline const std::filesystem::path& scratch_root() {
  static const detail::ScratchRoot root;
  return root.path();
}

/// An empty folder `name` in this process's scratch folder (emptied if this process used the name
/// before).
inline std::filesystem::path scratch(const std::string& name) {
  const auto dir = scratch_root() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace hpcontact::testing
