// 3-D solves under mpirun: K factorized over two ranks (each eliminates its half of the box) by
// each distributed solver, on the dense and the products path of S, give the serial run's energy
// and boundary samples (Tresca's disc QP by products too); α with A_G factorized over the ranks gives
// the serial α.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/cli_runner.hpp"

namespace hpcontact::testing {
namespace {

const std::string kStudies = std::string(HPCONTACT_SOURCE_DIR) + "/studies/three_d/";

nlohmann::json summary_at(const std::filesystem::path& out) {
  return nlohmann::json::parse(std::ifstream(out / "summary.json"));
}

// The largest difference of column `name` between two boundary CSVs of one discretization,
// relative to its largest value.
double relative_difference(const std::filesystem::path& a, const std::filesystem::path& b, const std::string& name) {
  const auto rows_a = read_csv(a).records(), rows_b = read_csv(b).records();
  EXPECT_EQ(rows_a.size(), rows_b.size());
  double largest = 0.0, difference = 0.0;
  for (std::size_t k = 0; k < std::min(rows_a.size(), rows_b.size()); ++k) {
    const double x = std::stod(rows_a[k].at(name)), y = std::stod(rows_b[k].at(name));
    largest = std::max(largest, std::abs(x));
    difference = std::max(difference, std::abs(x - y));
  }
  return difference / std::max(largest, 1e-300);
}

TEST(SolidMpi, TwoRanksGiveTheSerialSolveWithEverySolverOnBothPaths) {
  struct Case {
    const char* name;
    std::string scene;
    const char* effect;
    const char* column;
  };
  const std::vector<Case> cases{{"frictionless", kStudies + "extruded_frictionless.toml", "frictionless", "pressure"},
                                {"signorini", kStudies + "extruded_signorini.toml", "signorini", "lambda"}};
  for (const Case& c : cases)
    for (const char* path : {"dense", "products"}) {
      const std::string keys = " --effects " + std::string(c.effect) + " --set 'solve.trace_operator=\"" + path + "\"'";
      const auto dir = scratch(std::string("solid_mpi_") + c.name + "_" + path);
      const auto serial = run_command("env OPENBLAS_NUM_THREADS=1 " HPCONTACT_CLI " solve " + c.scene + keys +
                                      " --out " + (dir / "serial").string());
      ASSERT_EQ(serial.exit_code, 0) << serial.output;
      const double energy = summary_at(dir / "serial").at(c.effect).at("energy").get<double>();
      for (const char* solver : {"substructuring", "mumps", "bddc", "gamg"}) {
        const std::string what = std::string(c.name) + ", " + path + ", " + solver;
        const auto out = dir / solver;
        const auto parallel = run_command(
            kMpiEnvironment + "mpirun -n 2 --oversubscribe -x OPENBLAS_NUM_THREADS=1 " HPCONTACT_CLI " solve " +
            c.scene + keys + " --distributed-solver " + solver + " --out " + out.string());
        ASSERT_EQ(parallel.exit_code, 0) << what << ": " << parallel.output;
        const auto summary = summary_at(out);
        EXPECT_EQ(summary.at("ranks").get<int>(), 2) << what;
        EXPECT_EQ(summary.at("distributed_solver").get<std::string>(), solver) << what;
        EXPECT_EQ(summary.at(c.effect).at("solver").at("trace_operator").get<std::string>(), path) << what;
        EXPECT_NEAR(summary.at(c.effect).at("energy").get<double>(), energy, 1e-9 * std::abs(energy)) << what;
        const std::string csv = std::string("boundary_") + c.effect + ".csv";
        EXPECT_LT(relative_difference(dir / "serial" / csv, out / csv, c.column), 1e-7) << what;
        // (each rank holds the whole solution: one VTU from rank 0, no pieces)
        EXPECT_TRUE(std::filesystem::exists(out / (std::string("solution_") + c.effect + ".vtu"))) << what;
        EXPECT_FALSE(std::filesystem::exists(out / (std::string("solution_") + c.effect + ".pvtu"))) << what;
      }
    }
}

// A named --distributed-solver runs on one process too (it used to fall back to CHOLMOD there
// without a word): summary.json names it, and it gives CHOLMOD's solve; unnamed, one process is
// serial. Both paths of S.
TEST(SolidMpi, NamedSolverRunsOnOneRankAndGivesTheSerialSolve) {
  const std::string scene = kStudies + "extruded_frictionless.toml";
  for (const char* path : {"dense", "products"}) {
    const std::string keys = " --set 'solve.trace_operator=\"" + std::string(path) + "\"'";
    const auto dir = scratch(std::string("solid_one_rank_") + path);
    const auto serial = run_command("env OPENBLAS_NUM_THREADS=1 " HPCONTACT_CLI " solve " + scene + keys + " --out " +
                                    (dir / "serial").string());
    ASSERT_EQ(serial.exit_code, 0) << serial.output;
    EXPECT_EQ(summary_at(dir / "serial").at("distributed_solver").get<std::string>(), "serial");
    const double energy = summary_at(dir / "serial").at("frictionless").at("energy").get<double>();
    for (const char* solver : {"substructuring", "mumps", "bddc", "gamg"}) {
      const std::string what = std::string(path) + ", " + solver;
      const auto out = dir / solver;
      const auto one = run_command("env OPENBLAS_NUM_THREADS=1 " HPCONTACT_CLI " solve " + scene + keys +
                                   " --distributed-solver " + solver + " --out " + out.string());
      ASSERT_EQ(one.exit_code, 0) << what << ": " << one.output;
      const auto summary = summary_at(out);
      EXPECT_EQ(summary.at("ranks").get<int>(), 1) << what;
      EXPECT_EQ(summary.at("distributed_solver").get<std::string>(), solver) << what;
      EXPECT_NEAR(summary.at("frictionless").at("energy").get<double>(), energy, 1e-10 * std::abs(energy)) << what;
      EXPECT_LT(relative_difference(dir / "serial" / "boundary_frictionless.csv", out / "boundary_frictionless.csv",
                                    "pressure"),
                1e-8)
          << what;
    }
  }
}

// Tresca's disc QP by products under mpirun: the first rank alone runs the projected gradient and
// the other serves its products (contact/led_products.hpp), so both end with its λ: the serial
// energy and samples.
TEST(SolidMpi, TrescaByProductsOnTwoRanksGivesTheSerialSolve) {
  const std::string keys =
      " --set 'run.effects=[\"tresca\"]' --set 'data.f_x=\"0.05\"' --set 'data.s=\"0.1\"' "
      "--set 'solve.trace_operator=\"products\"'";
  const auto dir = scratch("solid_mpi_tresca_products");
  const std::string scene = kStudies + "extruded_frictionless.toml";
  const auto serial = run_command("env OPENBLAS_NUM_THREADS=1 " HPCONTACT_CLI " solve " + scene + keys + " --out " +
                                  (dir / "serial").string());
  ASSERT_EQ(serial.exit_code, 0) << serial.output;
  const auto parallel =
      run_command(kMpiEnvironment + "mpirun -n 2 --oversubscribe -x OPENBLAS_NUM_THREADS=1 " HPCONTACT_CLI " solve " +
                  scene + keys + " --distributed-solver mumps --out " + (dir / "mumps").string());
  ASSERT_EQ(parallel.exit_code, 0) << parallel.output;
  const double energy = summary_at(dir / "serial").at("tresca").at("energy").get<double>();
  EXPECT_NEAR(summary_at(dir / "mumps").at("tresca").at("energy").get<double>(), energy, 1e-9 * std::abs(energy));
  for (const char* column : {"pressure", "traction_1"})
    EXPECT_LT(
        relative_difference(dir / "serial" / "boundary_tresca.csv", dir / "mumps" / "boundary_tresca.csv", column),
        1e-7)
        << column;
}

// The α `hpcontact infsup` prints (its first line, "alpha = …").
double printed_alpha(const Run& run) {
  const auto at = run.output.find("alpha = ");
  EXPECT_NE(at, std::string::npos) << run.output;
  return at == std::string::npos ? std::nan("") : std::stod(run.output.substr(at + 8));
}

// α under mpirun: A_G factorized over two ranks by each distributed solver, S_G dense (from the
// distributed factor's Schur complement) or by products, and every rank running the same
// eigensolver, gives the serial α; so does the effect infsup of an elastic solve.
// solve.trace_operator = "saddle_point": the primal-dual active set on K's projected CG (GAMG and
// BDDC, one and two ranks) gives the serial dense path's energy and pressure; without an iterative
// K, or with friction, the key is refused by name before any work.
TEST(SolidMpi, SaddlePointGivesTheDenseSolveOnOneAndTwoRanks) {
  const std::string scene = kStudies + "extruded_frictionless.toml";
  const auto dir = scratch("solid_saddle_point");
  const auto serial = run_command("env OPENBLAS_NUM_THREADS=1 " HPCONTACT_CLI " solve " + scene +
                                  " --set 'solve.trace_operator=\"dense\"' --out " + (dir / "serial").string());
  ASSERT_EQ(serial.exit_code, 0) << serial.output;
  const double energy = summary_at(dir / "serial").at("frictionless").at("energy").get<double>();
  const std::string keys = " --set 'solve.trace_operator=\"saddle_point\"'";
  for (const char* solver : {"gamg", "bddc"})
    for (int ranks : {1, 2}) {
      const std::string what = std::string(solver) + " on " + std::to_string(ranks);
      const auto out = dir / (std::string(solver) + std::to_string(ranks));
      const auto run = run_command(kMpiEnvironment + "mpirun -n " + std::to_string(ranks) +
                                   " --oversubscribe -x OPENBLAS_NUM_THREADS=1 " HPCONTACT_CLI " solve " + scene +
                                   keys + " --distributed-solver " + solver + " --out " + out.string());
      ASSERT_EQ(run.exit_code, 0) << what << ": " << run.output;
      const auto solver_json = summary_at(out).at("frictionless").at("solver");
      EXPECT_EQ(solver_json.at("trace_operator").get<std::string>(), "saddle_point") << what;
      EXPECT_EQ(solver_json.at("method").get<std::string>(), "primal-dual-active-set") << what;
      EXPECT_GT(solver_json.at("cg_iterations").get<long>(), 0) << what;
      EXPECT_LE(solver_json.at("kkt_residual").get<double>(), 1e-11) << what;
      EXPECT_NEAR(summary_at(out).at("frictionless").at("energy").get<double>(), energy, 1e-9 * std::abs(energy))
          << what;
      EXPECT_LT(relative_difference(dir / "serial" / "boundary_frictionless.csv", out / "boundary_frictionless.csv",
                                    "pressure"),
                1e-7)
          << what;
    }
  const auto direct = run_command(HPCONTACT_CLI " solve " + scene + keys + " --out " + (dir / "direct").string());
  EXPECT_NE(direct.exit_code, 0);
  EXPECT_NE(direct.output.find("solve.trace_operator"), std::string::npos) << direct.output;
  EXPECT_NE(direct.output.find("--distributed-solver gamg or bddc"), std::string::npos) << direct.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "direct" / "summary.json"));
  const auto tresca =
      run_command(HPCONTACT_CLI " solve " + scene + keys +
                  " --set 'run.effects=[\"tresca\"]' --set 'data.s=\"0.1\"' --distributed-solver gamg --out " +
                  (dir / "tresca").string());
  EXPECT_NE(tresca.exit_code, 0);
  EXPECT_NE(tresca.output.find("frictionless contact only"), std::string::npos) << tresca.output;
}

TEST(SolidMpi, TwoRanksGiveTheSerialAlphaWithEverySolverOnBothPaths) {
  const std::string cube = std::string(HPCONTACT_SOURCE_DIR) + "/studies/three_d/cube.toml";
  for (const char* path : {"dense", "products"}) {
    // (p = 1, p_C = 0, H = h on 4³ cells: a decaying pairing, α = 0.31, 16 multipliers)
    const std::string keys =
        " --scene " + cube + " --p 1 --pc 0 --ratio 1 --set 'infsup.operator=\"" + std::string(path) + "\"'";
    const auto serial = run_command("env OPENBLAS_NUM_THREADS=1 " HPCONTACT_CLI " infsup" + keys);
    ASSERT_EQ(serial.exit_code, 0) << serial.output;
    const double alpha = printed_alpha(serial);
    for (const char* solver : {"substructuring", "mumps", "bddc"}) {
      const auto parallel = run_command(
          kMpiEnvironment + "mpirun -n 2 --oversubscribe -x OPENBLAS_NUM_THREADS=1 " HPCONTACT_CLI " infsup" + keys +
          " --distributed-solver " + solver);
      ASSERT_EQ(parallel.exit_code, 0) << path << ", " << solver << ": " << parallel.output;
      EXPECT_NEAR(printed_alpha(parallel), alpha, 1e-9 * alpha) << path << ", " << solver;
      // (rank 0 alone reports)
      EXPECT_EQ(parallel.output.find("alpha = "), parallel.output.rfind("alpha = ")) << parallel.output;
    }
  }
  const auto dir = scratch("solid_mpi_alpha");
  const std::string solve = " solve " + kStudies + "extruded_frictionless.toml --effects frictionless,infsup --out ";
  const auto serial = run_command("env OPENBLAS_NUM_THREADS=1 " HPCONTACT_CLI + solve + (dir / "serial").string());
  ASSERT_EQ(serial.exit_code, 0) << serial.output;
  const auto parallel = run_command(kMpiEnvironment + "mpirun -n 2 --oversubscribe -x OPENBLAS_NUM_THREADS=1 " +
                                    HPCONTACT_CLI + solve + (dir / "parallel").string());
  ASSERT_EQ(parallel.exit_code, 0) << parallel.output;
  const double alpha = summary_at(dir / "serial").at("infsup").at("alpha").get<double>();
  EXPECT_GT(alpha, 0.0);
  EXPECT_NEAR(summary_at(dir / "parallel").at("infsup").at("alpha").get<double>(), alpha, 1e-9 * alpha);
  EXPECT_EQ(summary_at(dir / "parallel").at("ranks").get<int>(), 2);
}

}  // namespace
}  // namespace hpcontact::testing
