// Stage 7, the distributed solvers over MPI ranks (run under mpirun through a helper program):
// substructuring, MUMPS and MATIS + BDDC must give CHOLMOD's solves and Schur complements B A⁻¹ Bᵀ (through the
// trailing set, and by solves when B reaches outside it) on 1, 2 and 3 ranks, with the elements
// split in strips or scattered (every unknown shared, ranks without interior, floating parts);
// an indefinite matrix must fail on every rank with a clear message, not hang.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#define HPCONTACT_CLI "hpcontact"  // cli_runner.hpp's run() is not used here
#include "cli_runner.hpp"
#include "linalg/substructured_cholesky.hpp"

using hpcontact::testing::run_command;
namespace linalg = hpcontact::linalg;

namespace {

double number_after(const std::string& text, const std::string& key) {
  const auto at = text.find(key + " ");
  return at == std::string::npos ? NAN : std::stod(text.substr(at + key.size() + 1));
}

std::string check_command(int ranks, const std::string& arguments) {
  return "env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1 "
         "timeout 120 mpirun -n " +
         std::to_string(ranks) + " --oversubscribe " HPCONTACT_FACTOR_CHECK " " + arguments;
}

}  // namespace

TEST(DistributedFactor, SubstructuringMumpsAndBddcEqualCholmodOnEverySplit) {
  for (const char* solver : {"substructuring", "mumps", "bddc"})
    for (const char* split : {"strips", "scattered"})
      for (int ranks : {1, 2, 3}) {
        const auto run = run_command(check_command(ranks, std::string(solver) + " " + split));
        const std::string where = std::string(solver) + ", " + split + ", " + std::to_string(ranks) + " ranks";
        ASSERT_EQ(run.exit_code, 0) << where << "\n" << run.output;
        for (const char* key : {"solve", "schur_trailing", "schur_fallback"})
          EXPECT_LT(number_after(run.output, key), 1e-11) << where << ": " << key << "\n" << run.output;
        // BDDC: a handful of iterations with strips (one interface per neighbour); scattered
        // cells make every node an interface node, still well below the 384 unknowns.
        if (std::string(solver) == "bddc") {
          EXPECT_LT(number_after(run.output, "iterations_largest"), std::string(split) == "strips" ? 15 : 60) << where;
        }
        if (std::string(solver) == "mumps") {
          EXPECT_EQ(number_after(run.output, "interface"), 24) << where << ": S_T from MUMPS's Schur interface";
        }
        if (std::string(solver) == "substructuring") {
          // The interface: the trailing row (24) alone on one rank; with strips, plus the nodes
          // between strips and the top nodes rank 0 shares; scattered, nearly every node.
          const double interface = number_after(run.output, "interface");
          if (ranks == 1) {
            EXPECT_EQ(interface, 24) << where;
          }
          if (ranks > 1 && std::string(split) == "strips") {
            EXPECT_GT(interface, 24 + 15 * (ranks - 1)) << where;
            EXPECT_LT(interface, 24 * 16 / 2) << where;
          }
          if (ranks > 1 && std::string(split) == "scattered") {
            EXPECT_GT(interface, 24 * 16 / 2) << where;
          }
          // The ranks' sparse factors: on one rank the serial factor with the trailing set last
          // (AMD may break ties differently in the local numbering); strips split it.
          const double mean = number_after(run.output, "factor_nonzeros_mean");
          const double serial = number_after(run.output, "reference_factor_nonzeros");
          if (ranks == 1) {
            EXPECT_NEAR(mean, serial, 0.1 * serial) << where;
          }
          if (ranks > 1 && std::string(split) == "strips") {
            EXPECT_GT(mean, 0.0) << where;
            EXPECT_LT(mean, serial) << where;
          }
        }
      }
}

// (BDDC on one rank is a direct solve of the one subdomain that does not check definiteness; the
// toolkit never uses it there: one rank takes the serial CHOLMOD path.)
TEST(DistributedFactor, IndefiniteMatrixFailsOnEveryRankWithAClearMessage) {
  for (const char* solver : {"substructuring", "mumps", "bddc"})
    for (int ranks : {1, 2}) {
      if (std::string(solver) == "bddc" && ranks == 1) continue;
      const auto run = run_command(check_command(ranks, std::string(solver) + " strips indefinite"));
      EXPECT_EQ(run.exit_code, 3) << solver << ", " << ranks << " ranks\n" << run.output;
      EXPECT_NE(run.output.find("not positive definite"), std::string::npos) << run.output;
    }
}

TEST(DistributedFactor, SubstructuringNotesAnInterfaceLargerThanTheFactorsAndThan64MB) {
  // 2000² entries are 32 MB: too small to matter whatever the factors; 3000² are 72 MB.
  EXPECT_FALSE(linalg::interface_outweighs_factors(2000, 0.0));
  EXPECT_TRUE(linalg::interface_outweighs_factors(3000, 1e6));
  EXPECT_FALSE(linalg::interface_outweighs_factors(3000, 1e7));
}
