// startup_row: timing whole processes.
#include "studies/startup_benchmark.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <vector>

#include "core/error.hpp"
#include "scene/scene_reader.hpp"

extern char** environ;

namespace hpcontact::studies {
namespace {

// Wall time of one run of `arguments` (program first), its output discarded.
double time_process(const std::vector<std::string>& arguments) {
  std::vector<char*> argv;
  for (const auto& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw IoError("startup benchmark: cannot start " + arguments[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw IoError("startup benchmark: " + arguments[0] + " " + arguments[1] + " failed");
  return seconds;
}

double median_time(const std::vector<std::string>& arguments, int runs) {
  std::vector<double> times;
  for (int k = 0; k < runs; ++k) times.push_back(time_process(arguments));
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

}  // namespace

BenchmarkRow startup_row(const std::string& executable, int runs) {
  const auto folder = std::filesystem::temp_directory_path() / "hpcontact_startup_benchmark";
  std::filesystem::create_directories(folder);
  const auto scene = folder / "scene.toml";
  std::ofstream(scene) << scene::paper_scene_text();
  const std::vector<std::string> solve{executable,   "solve", scene.string(),           "--effects",
                                       "friction_s", "--out", (folder / "out").string()};
  time_process(solve);  // once before timing: the file cache
  BenchmarkRow row;
  row.kind = "startup";
  row.p = 1;
  row.n = 8;
  row.seconds_baseline = median_time({executable, "--version"}, runs);
  row.seconds = median_time(solve, runs);
  row.ratio = row.seconds / row.seconds_baseline;
  std::filesystem::remove_all(folder);
  return row;
}

}  // namespace hpcontact::studies
