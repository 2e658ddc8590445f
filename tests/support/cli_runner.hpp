// Shared by the command-line tests: run the hpcontact executable and capture its output and exit
// code; fresh scratch folders (support/scratch.hpp).
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <thread>

#include "core/error.hpp"
#include "studies/sweep_rows.hpp"
#include "support/csv_file.hpp"
#include "support/scratch.hpp"

namespace hpcontact::testing {

struct Run {
  int exit_code;
  std::string output;  ///< standard output and error together
};

/// Runs a whole shell command line (stderr merged into the output).
inline Run run_command(const std::string& command_line) {
  const std::string command = command_line + " 2>&1";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  std::string output;
  std::array<char, 4096> buffer;
  while (fgets(buffer.data(), buffer.size(), pipe.get())) output += buffer.data();
  const int status = pclose(pipe.release());
  return {WEXITSTATUS(status), output};
}

/// The environment of an mpirun command line in the tests: one BLAS thread per rank (the ranks
/// take the cores), and mpirun allowed to run as root (containers).
inline const std::string kMpiEnvironment =
    "env OPENBLAS_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ";

/// Runs hpcontact with `arguments`.
inline Run run(const std::string& arguments) { return run_command(std::string(HPCONTACT_CLI) + " " + arguments); }

/// A run refused as bad input (exit code 2) with a message that contains `text`.
inline void expect_refused(const Run& refused, const std::string& text) {
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_NE(refused.output.find(text), std::string::npos) << "no \"" << text << "\" in: " << refused.output;
}

// Waits (up to 30 s) until no process holds `folder`'s sweep lock (rank 0 of a run holds it): a
// stopped mpirun may return before its rank 0 has exited. Whether the lock came free.
inline bool wait_for_sweep_lock(const std::filesystem::path& folder) {
  for (int attempt = 0; attempt < 600; ++attempt) {
    try {
      const studies::FolderLock lock(folder);
      return true;
    } catch (const InputError&) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  }
  return false;
}

// A sweep's alpha.csv without its last column (seconds), for comparing runs.
inline std::string without_seconds(const std::filesystem::path& path) {
  auto file = read_csv(path);
  if (!file.header.empty()) file.rows.insert(file.rows.begin(), file.header);
  std::string text;
  for (auto& fields : file.rows) {
    if (!fields.empty()) fields.pop_back();
    text += line_of(fields) + "\n";
  }
  return text;
}

}  // namespace hpcontact::testing
