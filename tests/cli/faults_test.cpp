// Faults: a full disk, an interrupt, a torn or foreign alpha.csv, two sweeps on one
// folder, a rank that fails under mpirun. Each ends with the documented exit code (4 I/O, 130
// interrupted, 2 bad input) and message, within seconds, and leaves nothing half-written.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/mount.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include "studies/sweep_rows.hpp"
#include "support/cli_runner.hpp"

namespace {

using hpcontact::testing::run;
using hpcontact::testing::run_command;
using hpcontact::testing::scratch;
using hpcontact::testing::without_seconds;

const std::string& kMpi = hpcontact::testing::kMpiEnvironment;

// A 16 KiB tmpfs: a disk that fills up. Unmounted by the destructor.
struct SmallDisk {
  std::filesystem::path path;
  bool mounted = false;
  explicit SmallDisk(const std::string& name) : path(scratch("small_disk_" + name)) {
    mounted = mount("tmpfs", path.c_str(), "tmpfs", 0, "size=16k") == 0;
  }
  ~SmallDisk() {
    if (mounted) umount(path.c_str());
  }
};

bool has_temporary_files(const std::filesystem::path& folder) {
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder))
    if (entry.path().filename().string().find(".tmp-") != std::string::npos) return true;
  return false;
}

// A sweep of the §7 square on three levels, small enough for a second, big enough for 16 KiB; or
// a longer one to be stopped on the way: 84 configurations of many short units (2.4 s on one rank
// in Release, 1.2 s on two; the interpolation norm only, whose α costs least per unit, so that
// the resumed and the fresh run after the stop stay short under the sanitizers too).
std::filesystem::path write_sweep(const std::filesystem::path& dir, bool long_running = false) {
  std::filesystem::copy_file(HPCONTACT_SOURCE_DIR "/studies/stability/square.toml", dir / "square.toml",
                             std::filesystem::copy_options::overwrite_existing);
  std::ofstream(dir / "sweep.toml") << "[sweep]\nscene = \"square.toml\"\n"
                                    << (long_running
                                            ? "p = \"1..6\"\npC = \"0..5\"\nnorm = [\"interp\"]\n"
                                              "levels = { \"domain.n_x\" = [8, 16, 24, 32, 40, 56, 80], \"domain.n_y\" "
                                              "= [8, 16, 24, 32, 40, 56, 80] }\n"
                                            : "p = \"1..3\"\npC = \"0..2\"\n"
                                              "levels = { \"domain.n_x\" = [4, 8, 16], \"domain.n_y\" = [4, 8, 16] }\n")
                                    << "ratio = [1, \"1/2\"]\nproblem = [\"signorini\", \"friction\"]\n";
  return dir / "sweep.toml";
}

}  // namespace

// Disk full while writing: exit 4 naming the file and the reason, no temporary file left.
TEST(Faults, FullDiskIsAnIoFailure) {
  SmallDisk disk("infsup");
  if (!disk.mounted) GTEST_SKIP() << "cannot mount a tmpfs here (needs root)";
  const auto result = run("infsup --p 2 --pc 1 --n 64 --mode " + (disk.path / "mode.csv").string());
  EXPECT_EQ(result.exit_code, 4) << result.output;
  EXPECT_NE(result.output.find("No space left on device"), std::string::npos) << result.output;
  EXPECT_EQ(result.output.find("No space left on device failed"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find((disk.path / "mode.csv").string()), std::string::npos) << result.output;
  EXPECT_FALSE(has_temporary_files(disk.path));
  EXPECT_FALSE(std::filesystem::exists(disk.path / "mode.csv"));
}

// Under mpirun, rank 0 cannot write (a full disk): every rank ends with exit 4 and the message is
// printed once, instead of the other ranks waiting forever in a collective call. Also with units
// taken by groups of two ranks, where the failing leader's partner learns of the failure in the
// group's agreement on the write and the other group stops after its unit.
TEST(Faults, FullDiskUnderMpirunEndsEveryRank) {
  SmallDisk disk("mpirun");
  if (!disk.mounted) GTEST_SKIP() << "cannot mount a tmpfs here (needs root)";
  const auto dir = scratch("faults_mpi_disk");
  for (const std::string launch : {"-n 2", "-n 4", "-n 4 --ranks-per-unit 2"}) {
    const std::string ranks = launch.substr(0, 4), options = launch.substr(4);
    std::filesystem::remove_all(disk.path / "sweep");
    const auto start = std::chrono::steady_clock::now();
    const auto result = run_command(kMpi + "timeout 120 mpirun " + ranks + " --oversubscribe " HPCONTACT_CLI " sweep " +
                                    write_sweep(dir).string() + " --out " + (disk.path / "sweep").string() + options);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(result.exit_code, 4) << launch << "\n" << result.output;
    EXPECT_LT(seconds, 60.0) << launch;
    const auto first = result.output.find("hpcontact: I/O failure");
    ASSERT_NE(first, std::string::npos) << launch << "\n" << result.output;
    EXPECT_EQ(result.output.find("hpcontact: I/O failure", first + 1), std::string::npos) << result.output;
    EXPECT_FALSE(has_temporary_files(disk.path)) << launch;
  }
}

// Under mpirun, a failure every rank raises alike (bad input, a refusal, a bad command line) is
// printed once by rank 0 and ends every rank with exit 2, without aborting the job.
TEST(Faults, FailuresOfEveryRankAreReportedOnceUnderMpirun) {
  const auto dir = scratch("faults_mpi_alike");
  std::ofstream(dir / "bad.toml") << "[domain]\nn_x = -3\n";
  // (found while building T_h, which rank 0 alone does under mpirun)
  std::ofstream(dir / "overlap.toml")
      << "[domain]\nn_x = 8\nn_y = 8\n[boundary]\ncontact = \"abs(y + 1) < 1e-9\"\n"
         "dirichlet = \"y < 0\"\n[contact_mesh]\nratio = 1\n[discretization]\np = 2\npC = 1\n"
         "[data]\nf = \"-1\"\ng = \"-x^2\"\n[run]\neffects = [\"signorini\"]\n";
  // (a sweep's levels are built by rank 0 alone too)
  std::ofstream(dir / "overlap_sweep.toml")
      << "[sweep]\nscene = \"overlap.toml\"\nlevels = { \"domain.n_x\" = [4, 8] }\np = [2]\npC = [1]\n";
  const std::vector<std::pair<std::string, std::string>> cases{
      {"solve " + (dir / "bad.toml").string(), "key 'domain.n_x' = -3"},
      {"solve " + (dir / "overlap.toml").string(), "Γ_C and Γ_D overlap"},
      {"sweep " + (dir / "overlap_sweep.toml").string() + " --out " + (dir / "o").string(),
       "level 1 (domain.n_x=4) of the scene"},
      {"sweep " HPCONTACT_SOURCE_DIR "/studies/stability/quick.toml --shard 5/3 --out " + (dir / "s").string(),
       "key '--shard' = 5/3"},
      {"solve " HPCONTACT_SOURCE_DIR "/studies/elasticity/square.toml --distributed-solver cholesky --out " +
           (dir / "e").string(),
       "key '--distributed-solver' = cholesky"},
      {"solve " + (dir / "missing.toml").string(), "File does not exist"}};
  for (const auto& [arguments, message] : cases) {
    const auto start = std::chrono::steady_clock::now();
    const auto result = run_command(kMpi + "timeout 120 mpirun -n 3 --oversubscribe " HPCONTACT_CLI " " + arguments);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(result.exit_code, 2) << arguments << "\n" << result.output;
    EXPECT_LT(seconds, 30.0) << arguments;
    const auto first = result.output.find(message);
    ASSERT_NE(first, std::string::npos) << arguments << "\n" << result.output;
    EXPECT_EQ(result.output.find(message, first + 1), std::string::npos) << "printed once: " << result.output;
    EXPECT_EQ(result.output.find("on rank"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find("MPI_ABORT"), std::string::npos) << result.output;
  }
}

// SIGINT during a run: exit 130, one line saying so, and no temporary file (finished files are
// whole).
TEST(Faults, InterruptExitsWith130AndLeavesNoTemporaryFile) {
  const auto dir = scratch("faults_interrupt");
  const auto pid_file = dir / "pid";
  // The shell execs hpcontact in the background, records its pid, interrupts it after a moment.
  const auto result = run_command("sh -c '" HPCONTACT_CLI " sweep " + write_sweep(dir, true).string() + " --out " +
                                  (dir / "out").string() + " & echo $! > " + pid_file.string() +
                                  "; sleep 2; kill -INT $!; wait $!; echo exit=$?'");
  EXPECT_NE(result.output.find("exit=130"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("hpcontact: interrupted (SIGINT); files in progress removed"), std::string::npos)
      << result.output;
  EXPECT_FALSE(has_temporary_files(dir / "out"));
}

// A torn last row, a row with a missing column and a number cut short are computed again, with a
// warning naming them; the result equals a fresh run. A row of another study is dropped.
TEST(Faults, ResumeRecomputesTornAndIncompleteRows) {
  const auto dir = scratch("faults_resume");
  const auto sweep = write_sweep(dir);
  ASSERT_EQ(run("sweep " + sweep.string() + " --out " + (dir / "fresh").string()).exit_code, 0);
  std::ifstream in(dir / "fresh" / "alpha.csv");
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_GT(lines.size(), 10u);
  std::filesystem::create_directories(dir / "damaged");
  std::filesystem::copy_file(dir / "fresh" / "sweep_identity.txt", dir / "damaged" / "sweep_identity.txt");
  {
    std::ofstream out(dir / "damaged" / "alpha.csv");
    for (std::size_t k = 0; k + 1 < lines.size(); ++k) {
      std::string line = lines[k];
      if (k == 3) line = line.substr(0, line.find(",", line.find(",") + 1));  // most columns missing
      if (k == 5) line.replace(line.find("signorini"), 9, "Signorini");       // not a point of the study
      if (k == 7) line.insert(line.find(',', line.find("0.")), "x");          // a number that does not parse
      out << line << "\n";
    }
    out << lines.back().substr(0, lines.back().size() / 2);  // torn: no newline
  }
  const auto resumed = run("sweep " + sweep.string() + " --out " + (dir / "damaged").string());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("4 stored rows"), std::string::npos) << resumed.output;
  EXPECT_NE(resumed.output.find("alpha.csv:4"), std::string::npos) << resumed.output;
  EXPECT_EQ(without_seconds(dir / "damaged" / "alpha.csv"), without_seconds(dir / "fresh" / "alpha.csv"));
}

// A second sweep on a folder in use: exit 2 naming the holder.
TEST(Faults, SecondSweepOnOneFolderIsRefused) {
  const auto dir = scratch("faults_lock");
  std::filesystem::create_directories(dir / "out");
  const hpcontact::studies::FolderLock held(dir / "out");
  const auto result = run("sweep " + write_sweep(dir).string() + " --out " + (dir / "out").string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("in use by another sweep (process " + std::to_string(getpid())), std::string::npos)
      << result.output;
}

// An mpirun sweep stopped half-way keeps its finished groups in per-rank shards; the next run
// (serial here) computes only the rest and writes the same alpha.csv as an uninterrupted run.
TEST(Faults, InterruptedMpirunSweepKeepsFinishedGroups) {
  const auto dir = scratch("faults_mpi_resume");
  const auto sweep = write_sweep(dir, true);
  const auto out = dir / "out";
  const auto result = run_command(
      kMpi + "sh -c 'mpirun -n 2 --oversubscribe " HPCONTACT_CLI " sweep " + sweep.string() + " --out " + out.string() +
      " & for i in $(seq 6000); do [ -s " + (out / "alpha.csv.rank0").string() + " ] || [ -s " +
      (out / "alpha.csv.rank1").string() + " ] && break; sleep 0.05; done; kill -TERM $!; wait $!'");
  ASSERT_TRUE(hpcontact::testing::wait_for_sweep_lock(out)) << "rank 0 of the stopped run still holds the folder";
  std::size_t kept = 0;
  for (const auto& shard : hpcontact::studies::existing_shards(out / "alpha.csv")) {
    std::ifstream in(shard);
    for (std::string line; std::getline(in, line);) ++kept;
  }
  ASSERT_FALSE(std::filesystem::exists(out / "alpha.csv")) << "the run finished before it was stopped";
  EXPECT_GT(kept, 0u) << result.output;
  // One BLAS thread in every run, so that the floating-point operations are the same.
  const auto resumed = run_command(kMpi + HPCONTACT_CLI " sweep " + sweep.string() + " --out " + out.string());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  ASSERT_EQ(
      run_command(kMpi + HPCONTACT_CLI " sweep " + sweep.string() + " --out " + (dir / "fresh").string()).exit_code, 0);
  EXPECT_EQ(without_seconds(out / "alpha.csv"), without_seconds(dir / "fresh" / "alpha.csv"));
  EXPECT_TRUE(hpcontact::studies::existing_shards(out / "alpha.csv").empty());
}

// PETSc options are checked before any work: a value SLEPc rejects, a name without the prefix (the
// prefixed one suggested), a misspelled name. Exit 2 within a second, nothing computed.
TEST(Faults, PetscOptionsAreCheckedBeforeAnyWork) {
  struct Case {
    std::string options, expected;
  };
  for (const auto& [options, expected] :
       {Case{"-infsup_eps_type nonsense", "SLEPc rejects a value"},
        Case{"-eps_type arpack", "did you mean -infsup_eps_type?"},
        Case{"-infsup_eps_typo arpack", "not an option of the inf-sup eigensolver"}}) {
    const auto result = run("infsup --p 2 --pc 1 --n 8 " + options);
    EXPECT_EQ(result.exit_code, 2) << options << "\n" << result.output;
    EXPECT_NE(result.output.find(expected), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find("alpha ="), std::string::npos) << result.output;
  }
  const auto good = run("infsup --p 2 --pc 1 --n 8 -infsup_eps_type arpack -infsup_eps_tol 1e-10 -log_view");
  EXPECT_EQ(good.exit_code, 0) << good.output;
}

// Messages that misled: each names the key, the value and why.
TEST(Faults, MessagesNameTheInputAndWhy) {
  const auto dir = scratch("faults_messages");
  const std::string base =
      "[domain]\nn_x = 4\nn_y = 4\n[boundary]\ncontact = \"abs(y + 1) < 1e-9\"\n"
      "dirichlet = \"abs(y - 1) < 1e-9\"\n[contact_mesh]\nratio = 1\n[discretization]\np = 2\n"
      "pC = 1\n[data]\ng = \"-x^2\"\n[run]\neffects = [\"signorini\"]\n";
  auto scene_with = [&](const std::string& name, const std::string& from, const std::string& to) {
    std::string text = base;
    text.replace(text.find(from), from.size(), to);
    std::ofstream(dir / name) << text;
    return run("solve " + (dir / name).string() + " --out " + (dir / ("out_" + name)).string());
  };
  struct Case {
    std::string name, from, to, expected;
  };
  const std::string huge(200000, '1');
  for (const auto& c : {
           Case{"tiny.toml", "[domain]\n", "[domain]\nx_min = 0\nx_max = 1e-300\n", "the width 1e-300 is below"},
           Case{"equal.toml", "[domain]\n", "[domain]\nx_min = 1\nx_max = 1\n", "= 1, 1: must satisfy x_min < x_max"},
           Case{"huge.toml", "n_x = 4\nn_y = 4", "n_x = 100000\nn_y = 100000", "at most 2^31 - 1 unknowns"},
           Case{"free.toml", "dirichlet = \"abs(y - 1) < 1e-9\"", "dirichlet = \"x > 5\"",
                "no boundary edge is in Γ_D"},
           Case{"empty.toml", "contact = \"abs(y + 1) < 1e-9\"", "contact = \"abs(y + 1) < 1e-9 && x > 5\"",
                "empty.toml: key 'boundary.contact' = abs(y + 1) < 1e-9 && x > 5: it must select at least one"},
           Case{"expression.toml", "g = \"-x^2\"", "g = \"" + huge + "+\"", "(200001 characters)"},
       }) {
    const auto result = scene_with(c.name, c.from, c.to);
    EXPECT_EQ(result.exit_code, 2) << c.name << "\n" << result.output.substr(0, 2000);
    EXPECT_NE(result.output.find(c.expected), std::string::npos) << c.name << "\n" << result.output.substr(0, 2000);
    EXPECT_LT(result.output.size(), 2000u) << c.name;
  }
  // A misspelled physical group lists the groups the mesh has.
  std::ofstream(dir / "groups.toml")
      << "[domain]\nmesh = \"" HPCONTACT_TEST_DATA
         "/square_2x2.msh\"\n[boundary]\n"
         "contact_groups = [\"contcat\"]\ndirichlet_groups = [\"dirichlet\"]\n"
         "[contact_mesh]\nratio = 1\n[discretization]\np = 2\npC = 1\n[data]\ng = \"-x^2\"\n"
         "[run]\neffects = [\"signorini\"]\n";
  const auto groups = run("solve " + (dir / "groups.toml").string() + " --out " + (dir / "out_groups").string());
  EXPECT_EQ(groups.exit_code, 2) << groups.output;
  EXPECT_NE(groups.output.find("the mesh has: contact, dirichlet, neumann"), std::string::npos) << groups.output;
}

// The outputs of a solve are one set: a second run replaces the first run's folder whole (no file
// of the first run stays beside the new ones), a folder of other files is refused and left alone,
// and a run that cannot write leaves no partial set.
TEST(Faults, SolveOutputsAreOneSet) {
  const auto dir = scratch("faults_output_set");
  const std::string scene = std::string("[domain]\nn_x = 4\nn_y = 4\n[boundary]\ncontact = \"abs(y + 1) < 1e-9\"\n") +
                            "dirichlet = \"abs(y - 1) < 1e-9\"\n[contact_mesh]\nratio = 1\n[discretization]\np = 2\n"
                            "pC = 1\n[data]\ng = \"-x^2\"\ns = \"1\"\n";
  std::ofstream(dir / "scene.toml") << scene;
  const auto out = (dir / "out").string(), file = (dir / "scene.toml").string();
  ASSERT_EQ(run("solve " + file + " --effects signorini,friction --out " + out).exit_code, 0);
  ASSERT_TRUE(std::filesystem::exists(dir / "out" / "boundary_friction.csv"));
  const auto second = run("solve " + file + " --effects signorini --out " + out);
  ASSERT_EQ(second.exit_code, 0) << second.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "boundary_signorini.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "boundary_friction.csv"));
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();

  std::filesystem::create_directories(dir / "mine");
  std::ofstream(dir / "mine" / "notes.txt") << "a user's file\n";
  const auto refused = run("solve " + file + " --effects signorini --out " + (dir / "mine").string());
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_NE(refused.output.find("holds files that hpcontact did not write"), std::string::npos) << refused.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "mine" / "notes.txt"));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir / "mine"), std::filesystem::directory_iterator()), 1);

  SmallDisk disk("solve");
  if (!disk.mounted) GTEST_SKIP() << "cannot mount a tmpfs here (needs root)";
  std::ofstream(dir / "fine.toml") << std::string(scene).replace(scene.find("n_x = 4\nn_y = 4"), 15,
                                                                 "n_x = 32\nn_y = 32");
  const auto full =
      run_command(kMpi + "timeout 120 mpirun -n 2 --oversubscribe " HPCONTACT_CLI " solve " +
                  (dir / "fine.toml").string() + " --effects signorini --out " + (disk.path / "out").string());
  EXPECT_EQ(full.exit_code, 4) << full.output;
  EXPECT_TRUE(std::filesystem::is_empty(disk.path)) << "a partial set was left";
}
