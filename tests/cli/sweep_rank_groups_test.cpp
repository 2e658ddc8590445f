// A sweep's units taken by groups of ranks under mpirun (`hpcontact sweep --ranks-per-unit k`):
// each unit's factorizations and extension references distributed over its group, the result
// equal to the serial sweep's, and --ranks-per-unit checked against the ranks.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_runner.hpp"
#include "support/csv_file.hpp"

namespace {

using hpcontact::testing::read_csv;
using hpcontact::testing::run_command;
using hpcontact::testing::scratch;

const std::string& kMpi = hpcontact::testing::kMpiEnvironment;

// A sweep of the §7 square: 2 levels, p = 1..3, both norms, ratios and pairings (BDDC's
// iterative solves of the extension norm's references take most of its time: 18 s on 4 ranks with
// a third level n = 16, 6 s without).
std::filesystem::path write_sweep(const std::filesystem::path& dir, const std::string& levels = "[4, 8]",
                                  const std::string& degrees = "p = \"1..3\"\npC = \"0..2\"\n",
                                  const std::string& norms = "[\"interp\", \"extension\"]") {
  std::filesystem::copy_file(HPCONTACT_SOURCE_DIR "/studies/stability/square.toml", dir / "square.toml",
                             std::filesystem::copy_options::overwrite_existing);
  std::ofstream(dir / "sweep.toml") << "[sweep]\nscene = \"square.toml\"\n"
                                    << degrees << "levels = { \"domain.n_x\" = " << levels
                                    << ", \"domain.n_y\" = " << levels << " }\n"
                                    << "ratio = [1, \"1/2\"]\nnorm = " << norms << "\n"
                                    << "problem = [\"signorini\", \"friction\"]\n";
  return dir / "sweep.toml";
}

// Every column of `b` equal to `a`'s, but alpha (to 1e-10 relative, 1e-13 absolute below 1e-3:
// the distributed factors sum in another order, and the eigenvalue's round-off is relative to the
// largest, 1), alpha_error (an estimate of round-off size at these levels) and seconds.
void expect_equal_sweeps(const std::filesystem::path& a, const std::filesystem::path& b) {
  const auto expected_file = read_csv(a), actual_file = read_csv(b);
  const auto &expected = expected_file.rows, &actual = actual_file.rows;
  ASSERT_EQ(expected.size(), actual.size()) << b;
  ASSERT_GT(expected.size(), 0u);
  const auto& header = expected_file.header;
  EXPECT_EQ(actual_file.header, header) << b;
  for (std::size_t r = 0; r < expected.size(); ++r) {
    ASSERT_EQ(expected[r].size(), actual[r].size());
    for (std::size_t c = 0; c < header.size(); ++c) {
      if (header[c] == "seconds" || header[c] == "alpha_error") continue;
      if (header[c] == "alpha")
        EXPECT_NEAR(std::stod(actual[r][c]), std::stod(expected[r][c]),
                    1e-10 * std::max(std::stod(expected[r][c]), 1e-3))
            << b << " row " << r;
      else
        EXPECT_EQ(actual[r][c], expected[r][c]) << b << " row " << r << " column " << header[c];
    }
  }
}

}  // namespace

// Two groups of two ranks, each unit over its group by substructuring, MUMPS and BDDC: the serial α.
TEST(SweepRankGroups, GroupsOfTwoRanksGiveTheSerialAlpha) {
  const auto dir = scratch("sweep_groups");
  const auto sweep = write_sweep(dir);
  const auto serial =
      run_command(kMpi + HPCONTACT_CLI " sweep " + sweep.string() + " --out " + (dir / "serial").string());
  ASSERT_EQ(serial.exit_code, 0) << serial.output;
  for (const std::string solver : {"substructuring", "mumps", "bddc"}) {
    const auto out = dir / solver;
    const auto groups =
        run_command(kMpi + "timeout 300 mpirun -n 4 --oversubscribe " HPCONTACT_CLI " sweep " + sweep.string() +
                    " --out " + out.string() + " --ranks-per-unit 2 --distributed-solver " + solver);
    ASSERT_EQ(groups.exit_code, 0) << groups.output;
    EXPECT_NE(groups.output.find("on 4 ranks"), std::string::npos) << groups.output;
    expect_equal_sweeps(dir / "serial" / "alpha.csv", out / "alpha.csv");
    EXPECT_TRUE(std::filesystem::exists(out / "verdicts.csv"));
  }
}

// A group run stopped half-way keeps the groups its leaders finished (in their shards, named by
// the leader's rank); the next run (serial here) computes only the rest and equals a serial run.
TEST(SweepRankGroups, InterruptedGroupRunKeepsFinishedGroups) {
  const auto dir = scratch("sweep_groups_resume");
  // Many short units (the interpolation norm's), so that the stop comes on the way.
  const auto sweep = write_sweep(dir, "[8, 16, 24, 32, 40]", "p = \"1..6\"\npC = \"0..5\"\n", "[\"interp\"]");
  const auto out = dir / "out";
  const auto shard = [&](int rank) { return (out / ("alpha.csv.rank" + std::to_string(rank))).string(); };
  const auto stopped =
      run_command(kMpi + "sh -c 'mpirun -n 4 --oversubscribe " HPCONTACT_CLI " sweep " + sweep.string() + " --out " +
                  out.string() + " --ranks-per-unit 2 & for i in $(seq 6000); do [ -s " + shard(0) + " ] || [ -s " +
                  shard(2) + " ] && break; sleep 0.05; done; kill -TERM $!; wait $!'");
  ASSERT_TRUE(hpcontact::testing::wait_for_sweep_lock(out)) << "rank 0 of the stopped run still holds the folder";
  ASSERT_FALSE(std::filesystem::exists(out / "alpha.csv")) << "the run finished before it was stopped";
  EXPECT_FALSE(std::filesystem::exists(shard(1)) || std::filesystem::exists(shard(3))) << "only leaders write";
  std::size_t kept = 0;
  for (int rank : {0, 2}) {
    std::ifstream in(shard(rank));
    for (std::string line; std::getline(in, line);) ++kept;
  }
  EXPECT_GT(kept, 0u) << stopped.output;
  const auto resumed = run_command(kMpi + HPCONTACT_CLI " sweep " + sweep.string() + " --out " + out.string());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  const auto fresh =
      run_command(kMpi + HPCONTACT_CLI " sweep " + sweep.string() + " --out " + (dir / "fresh").string());
  ASSERT_EQ(fresh.exit_code, 0) << fresh.output;
  expect_equal_sweeps(dir / "fresh" / "alpha.csv", out / "alpha.csv");
}

// The solves of a unit run on its group's two ranks, not on one rank or on all four (PETSc's
// view of the BDDC solver names the size of its communicator).
TEST(SweepRankGroups, UnitSolvesRunOnTheGroupsRanks) {
  const auto dir = scratch("sweep_groups_view");
  const auto sweep = write_sweep(dir, "[4]", "p = [2]\npC = [1]\n");
  const auto result =
      run_command(kMpi + "timeout 300 mpirun -n 4 --oversubscribe " HPCONTACT_CLI " sweep " + sweep.string() +
                  " --out " + (dir / "out").string() + " --ranks-per-unit 2 --distributed-solver bddc -bddc_ksp_view");
  ASSERT_EQ(result.exit_code, 0) << result.output.substr(0, 4000);
  EXPECT_NE(result.output.find("KSP Object: (bddc_) 2 MPI processes"), std::string::npos);
  EXPECT_EQ(result.output.find("KSP Object: (bddc_) 4 MPI processes"), std::string::npos);
  EXPECT_EQ(result.output.find("KSP Object: (bddc_) 1 MPI process"), std::string::npos);
}

// Groups must divide the ranks. Exit 2 naming the option, on every rank alike, before anything is
// computed.
TEST(SweepRankGroups, GroupSizesThatDoNotFitAreRefused) {
  const auto dir = scratch("sweep_groups_bad");
  const auto sweep = write_sweep(dir);
  const auto uneven = run_command(kMpi + "timeout 120 mpirun -n 3 --oversubscribe " HPCONTACT_CLI " sweep " +
                                  sweep.string() + " --out " + (dir / "a").string() + " --ranks-per-unit 2");
  EXPECT_EQ(uneven.exit_code, 2) << uneven.output;
  EXPECT_NE(uneven.output.find("key '--ranks-per-unit' = 2: a divisor of the 3 ranks"), std::string::npos)
      << uneven.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "a" / "alpha.csv"));
}

// An elastic scene's units over a group of two ranks (its factors distributed like the scalar
// model's): the serial α.
TEST(SweepRankGroups, ElasticUnitsOnGroupsGiveTheSerialAlpha) {
  const auto dir = scratch("sweep_groups_elastic");
  std::ofstream(dir / "elastic.toml") << "[sweep]\nscene = \"" HPCONTACT_SOURCE_DIR
                                         "/studies/elasticity/square.toml\"\np = [1, 2]\npC = [0, 1]\n";
  const std::string sweep = (dir / "elastic.toml").string();
  const auto serial = run_command(kMpi + HPCONTACT_CLI " sweep " + sweep + " --out " + (dir / "serial").string());
  ASSERT_EQ(serial.exit_code, 0) << serial.output;
  const auto groups = run_command(kMpi + "timeout 300 mpirun -n 2 --oversubscribe " HPCONTACT_CLI " sweep " + sweep +
                                  " --out " + (dir / "groups").string() + " --ranks-per-unit 2");
  ASSERT_EQ(groups.exit_code, 0) << groups.output;
  expect_equal_sweeps(dir / "serial" / "alpha.csv", dir / "groups" / "alpha.csv");
}

// A PETSc error raised by every rank of a group (an unknown KSP type for the unit's BDDC solver)
// is agreed on: one message without a rank, exit 3, on 2 and on 4 ranks. (PETSc's default error
// handler made the ranks other than 0 sleep 10 s and exit with 0, and rank 0 abort as if alone.)
TEST(SweepRankGroups, APetscErrorOfEveryRankIsReportedOnce) {
  const auto dir = scratch("sweep_groups_petsc_error");
  const auto sweep = write_sweep(dir, "[4]", "p = [2]\npC = [1]\n");
  for (int ranks : {2, 4}) {
    const auto out = dir / ("out" + std::to_string(ranks));
    const auto result =
        run_command(kMpi + "timeout 300 mpirun -n " + std::to_string(ranks) +
                    " --oversubscribe " HPCONTACT_CLI " sweep " + sweep.string() + " --out " + out.string() +
                    " --ranks-per-unit 2 --distributed-solver bddc " + "-bddc_ksp_type no_such_type");
    EXPECT_EQ(result.exit_code, 3) << result.output;
    const std::string message = "hpcontact: numerical failure: PETSc error";
    const auto first = result.output.find(message);
    ASSERT_NE(first, std::string::npos) << result.output;
    EXPECT_EQ(result.output.find(message, first + 1), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("Unable to find requested KSP type no_such_type"), std::string::npos);
    EXPECT_EQ(result.output.find("on rank"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find("PETSC ERROR"), std::string::npos) << result.output;
  }
}

// A rank failing alone inside its unit's collective work (here its own PETSc option makes its
// BDDC setup fail while its partner waits in PETSc's collective setup) meets no partner on the
// group's failure channel and ends the job within seconds, naming itself: 4 ranks in 2 groups,
// the second rank of each group failing, so that whichever group takes a unit fails alone.
TEST(SweepRankGroups, ARankFailingAloneInAUnitEndsTheJob) {
  const auto dir = scratch("sweep_groups_alone");
  const auto sweep = write_sweep(dir, "[4, 8]", "p = [2]\npC = [1]\n");
  const std::string command = std::string(HPCONTACT_CLI) + " sweep " + sweep.string() + " --out " +
                              (dir / "out").string() + " --ranks-per-unit 2 --distributed-solver bddc";
  const std::string failing = command + " -bddc_ksp_type no_such_type";
  const auto started = std::chrono::steady_clock::now();
  const auto result = run_command(kMpi + "timeout 300 mpirun --oversubscribe -n 1 " + command + " : -n 1 " + failing +
                                  " : -n 1 " + command + " : -n 1 " + failing);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  EXPECT_EQ(result.exit_code, 3) << result.output;
  const bool names_a_failing_rank =
      result.output.find("hpcontact: numerical failure on rank 1: PETSc error") != std::string::npos ||
      result.output.find("hpcontact: numerical failure on rank 3: PETSc error") != std::string::npos;
  EXPECT_TRUE(names_a_failing_rank) << result.output;
  EXPECT_NE(result.output.find("no_such_type"), std::string::npos) << result.output;
  EXPECT_LT(seconds, 200.0) << "the job should end after the 10 s patience, not at the timeout";
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "alpha.csv"));
}
