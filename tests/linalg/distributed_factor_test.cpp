// The distributed solvers over MPI ranks (run under mpirun through a helper program):
// substructuring, MUMPS and MATIS + BDDC must give CHOLMOD's solves and Schur complements B A⁻¹ Bᵀ (through the
// trailing set, and by solves when B reaches outside it) on 1, 2 and 3 ranks (substructuring also
// on 4), with the elements
// split in strips or scattered (every unknown shared, ranks without interior, floating parts);
// an indefinite matrix must fail on every rank with a clear message, not hang; the split of the
// cells over the ranks must be balanced and take the shorter cut of bisection and PT-Scotch, and
// each rank's part cut by the first rank must hold its cells with the whole space's dofs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <string>

#define HPCONTACT_CLI "hpcontact"  // cli_runner.hpp's run() is not used here
#include "core/byte_buffer.hpp"
#include "linalg/substructured_cholesky.hpp"
#include "mesh/cell_partition.hpp"
#include "mesh/contact_boundary.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "operators/rank_parts.hpp"
#include "support/cli_runner.hpp"

using hpcontact::testing::run_command;
namespace linalg = hpcontact::linalg;

namespace {

double number_after(const std::string& text, const std::string& key) {
  const auto at = text.find(key + " ");
  return at == std::string::npos ? NAN : std::stod(text.substr(at + key.size() + 1));
}

std::string mpirun_command(int ranks, const std::string& program, const std::string& arguments) {
  return "env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1 "
         "timeout 120 mpirun -n " +
         std::to_string(ranks) + " --oversubscribe " + program + " " + arguments;
}

std::string check_command(int ranks, const std::string& arguments) {
  return mpirun_command(ranks, HPCONTACT_FACTOR_CHECK, arguments);
}

// The number after `key` on the line that starts with `mesh method`.
double partition_number(const std::string& output, const std::string& mesh, const std::string& method,
                        const std::string& key) {
  const auto line = output.find(mesh + " " + method + " ");
  if (line == std::string::npos) return NAN;
  return number_after(output.substr(line, output.find('\n', line) - line), key);
}

}  // namespace

// B x and Bᵀ y with x at each rank's own dofs and Bᵀ y as the ranks' shares (B stored by rows, its
// columns found among the rank's dofs) equal the serial products, for every solver's split.
TEST(DistributedFactor, CouplingProductsOverTheRanksEqualTheSerialOnes) {
  for (const std::string solver : {"substructuring", "mumps", "bddc"})
    for (int ranks : {1, 2, 3}) {
      const auto run = run_command(mpirun_command(ranks, HPCONTACT_PRODUCTS_CHECK, solver));
      const std::string where = solver + " on " + std::to_string(ranks) + " ranks";
      ASSERT_EQ(run.exit_code, 0) << where << "\n" << run.output;
      EXPECT_LT(number_after(run.output, "multiply"), 1e-14) << where << "\n" << run.output;
      EXPECT_LT(number_after(run.output, "transpose"), 1e-14) << where << "\n" << run.output;
      EXPECT_EQ(number_after(run.output, "held_dofs_ok"), 1.0) << where << "\n" << run.output;
    }
}

// A trailing set large against the unknowns the ranks share and the entries they hold (76 against
// a cut of a few unknowns: its dense work would exceed solves through the ranks' factors) stays out
// of substructuring's dense interface problem (its unknowns interior to their ranks), and
// B A⁻¹ Bᵀ from solves equals CHOLMOD's; on one rank it is the interface, as in the serial path.
TEST(DistributedFactor, SubstructuringKeepsALargeTrailingSetOutOfTheInterface) {
  for (int ranks : {1, 2}) {
    const auto run = run_command(check_command(ranks, "substructuring wide"));
    const std::string where = std::to_string(ranks) + " ranks";
    ASSERT_EQ(run.exit_code, 0) << where << "\n" << run.output;
    for (const char* key : {"solve", "schur_trailing", "schur_fallback", "solve_local"})
      EXPECT_LT(number_after(run.output, key), 1e-11) << where << ": " << key << "\n" << run.output;
    EXPECT_GE(number_after(run.output, "solve_local"), 0.0) << where << ": wrong local unknowns\n" << run.output;
    const double interface = number_after(run.output, "interface"), trailing = number_after(run.output, "trailing_set");
    EXPECT_EQ(trailing, 76) << where;
    if (ranks == 1) {
      EXPECT_EQ(interface, trailing) << where;
    } else {
      EXPECT_GT(interface, 0) << where;
      EXPECT_LT(2 * interface, trailing) << where << ": the trailing set joined the interface";
    }
  }
}

TEST(DistributedFactor, SubstructuringMumpsAndBddcEqualCholmodOnEverySplit) {
  for (const char* solver : {"substructuring", "mumps", "bddc"})
    for (const char* split : {"strips", "scattered"})
      for (int ranks : {1, 2, 3, 4}) {
        // (4 ranks: substructuring's ScaLAPACK interface with its sizes padded to the ranks)
        if (ranks == 4 && std::string(solver) != "substructuring") continue;
        const auto run = run_command(check_command(ranks, std::string(solver) + " " + split));
        const std::string where = std::string(solver) + ", " + split + ", " + std::to_string(ranks) + " ranks";
        ASSERT_EQ(run.exit_code, 0) << where << "\n" << run.output;
        for (const char* key : {"solve", "schur_trailing", "schur_fallback", "solve_local"})
          EXPECT_LT(number_after(run.output, key), 1e-11) << where << ": " << key << "\n" << run.output;
        // The solve from each rank's share at the unknowns it touches (−1: other local unknowns).
        EXPECT_GE(number_after(run.output, "solve_local"), 0.0) << where << ": wrong local unknowns\n" << run.output;
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

// PT-Scotch's parts: the same on every rank, on a second call and in a second run, every cell in one of them, equal
// work (cells weighted by their unknowns, degrees 1 to 8 on the p-graded square) to 2 % by either
// method, a cut no longer than coordinate bisection's by more than 10 % on these small meshes
// and shorter on the unstructured annulus; the ranks' split takes the shorter of the two cuts.
TEST(DistributedFactor, GraphPartitionIsBalancedAndRanksTakeTheShorterCut) {
  for (int ranks : {2, 3, 4}) {
    const auto run = run_command(mpirun_command(ranks, HPCONTACT_PARTITION_CHECK, HPCONTACT_TEST_DATA));
    const std::string where = std::to_string(ranks) + " ranks";
    ASSERT_EQ(run.exit_code, 0) << where << "\n" << run.output;
    // A second run (another process) must split every mesh the same way.
    const auto again = run_command(mpirun_command(ranks, HPCONTACT_PARTITION_CHECK, HPCONTACT_TEST_DATA));
    ASSERT_EQ(again.exit_code, 0) << where << "\n" << again.output;
    for (const char* mesh : {"square", "mixed_degrees", "graded", "triangles", "annulus"}) {
      const std::string at = where + ", " + mesh + "\n" + run.output;
      EXPECT_EQ(partition_number(run.output, mesh, "graph", "outside"), 0) << at;
      EXPECT_EQ(partition_number(run.output, mesh, "graph", "ranks_differ"), 0) << at;
      EXPECT_EQ(partition_number(run.output, mesh, "graph", "repeat_differs"), 0) << at;
      EXPECT_EQ(partition_number(again.output, mesh, "graph", "parts_hash"),
                partition_number(run.output, mesh, "graph", "parts_hash"))
          << at;
      EXPECT_LE(partition_number(run.output, mesh, "graph", "imbalance"), 1.02) << at;
      // Bisection by weight: within one cell's weight per level (81 unknowns of a mean part's
      // 16 000 and more on the p-graded square).
      EXPECT_LE(partition_number(run.output, mesh, "bisection", "imbalance"), 1.02) << at;
      const double graph = partition_number(run.output, mesh, "graph", "cut_edges");
      const double bisection = partition_number(run.output, mesh, "bisection", "cut_edges");
      EXPECT_GT(graph, 0) << at;
      // (PT-Scotch's cut of the p-graded square, balancing weights from 4 to 81, runs 10 % longer)
      EXPECT_LE(graph, (std::string(mesh) == "mixed_degrees" ? 1.15 : 1.1) * bisection) << at;
      if (std::string(mesh) == "annulus") {
        EXPECT_LT(graph, 0.9 * bisection) << at;
      }
      EXPECT_EQ(partition_number(run.output, mesh, "chosen", "cut_edges"), std::min(graph, bisection)) << at;
    }
  }
}

// The first rank alone holds the mesh and sends each rank its part: on 2 and 3 ranks every part's
// numbering, rollers, Γ_D-kept space and materials equal the whole space's on the same cells,
// Γ_C's cells are on every part, each cell is owned once, and every part is smaller than the mesh.
// A bad degree on the first rank fails every rank alike, reported once.
TEST(DistributedFactor, FirstRankSendsEachRankItsPartOfTheSpace) {
  for (int ranks : {2, 3}) {
    const auto run = run_command(mpirun_command(ranks, HPCONTACT_RANK_SPACE_CHECK, ""));
    const std::string where = std::to_string(ranks) + " ranks\n" + run.output;
    ASSERT_EQ(run.exit_code, 0) << where;
    for (const std::string mesh : {"square", "triangles"}) {
      const auto line = run.output.find(mesh + " mismatches");
      ASSERT_NE(line, std::string::npos) << where;
      const std::string text = run.output.substr(line);
      EXPECT_EQ(number_after(text, "mismatches"), 0) << where;
      EXPECT_EQ(number_after(text, "owned"), number_after(text, "cells")) << where;
      EXPECT_EQ(number_after(text, "smaller"), ranks) << where;
    }
  }
  const auto bad = run_command(mpirun_command(3, HPCONTACT_RANK_SPACE_CHECK, "bad"));
  EXPECT_EQ(bad.exit_code, 3) << bad.output;
  const auto message = bad.output.find("must be >= 1");
  ASSERT_NE(message, std::string::npos) << bad.output;
  EXPECT_EQ(bad.output.find("must be >= 1", message + 1), std::string::npos) << bad.output;
}

// The first rank's cutting of the parts, serially: rank r's part is its own cells and Γ_C's,
// ascending and each once (Γ_C turns the square's corner, so one cell has two Γ_C edges, and the
// list is handed over unsorted with repeats), read back with each cell's owner and material and
// the whole space's dofs, Γ_D eliminated and kept (interior modes included: their offsets are read
// from the whole space).
TEST(DistributedFactor, RankPartsHoldEachRanksOwnCellsAndGammaCsWithTheirDofs) {
  namespace mesh = hpcontact::mesh;
  namespace space = hpcontact::space;
  namespace operators = hpcontact::operators;
  auto square = mesh::make_paper_square_mesh(8);
  mesh::assign_boundary_part(square, mesh::BoundaryPart::contact,
                             [](const mesh::Point& x) { return x.x() > 0.999 && x.y() < 0.0; });
  std::vector<int> degrees(square.n_cells());
  for (int c = 0; c < square.n_cells(); ++c) degrees[c] = 1 + c % 4;  // interiors of 0, 1, 4 and 9 modes
  const space::H1Space eliminated(square, degrees), kept(square, degrees, space::DirichletDofs::kept);
  operators::WholeNumbering whole = operators::number_whole_space(square, degrees, nullptr);
  ASSERT_TRUE(whole.kept);
  ASSERT_EQ(whole.contact_cells.size(), 12u);  // the bottom's 8 edges and the right side's lower 4
  std::vector<char> on_contact(square.n_cells(), 0);
  for (int c : whole.contact_cells) on_contact[c] = 1;
  const std::vector<int> reversed(whole.contact_cells.rbegin(), whole.contact_cells.rend());
  whole.contact_cells = reversed;  // unsorted, and each twice
  whole.contact_cells.insert(whole.contact_cells.end(), reversed.begin(), reversed.end());
  std::vector<hpcontact::assembly::Material> materials(square.n_cells());
  for (int c = 0; c < square.n_cells(); ++c) materials[c].mu = c;
  const int ranks = 3;
  const auto parts = mesh::bisect_cells(square, ranks, std::vector<int>(square.n_cells(), 1));
  const operators::RankParts cutter(square, whole, parts, ranks, &materials);
  std::vector<int> owners(square.n_cells(), 0);
  for (int rank = 0; rank < ranks; ++rank) {
    const std::string where = "rank " + std::to_string(rank);
    const auto cells = cutter.cells_of(rank);
    int expected = 0;
    for (int c = 0; c < square.n_cells(); ++c) expected += parts[c] == rank || on_contact[c];
    ASSERT_EQ(static_cast<int>(cells.size()), expected) << where;
    EXPECT_TRUE(std::adjacent_find(cells.begin(), cells.end(), std::greater_equal<>()) == cells.end()) << where;
    for (int c : cells) owners[c] += parts[c] == rank;
    const auto part = operators::rank_space_from_bytes(cutter.bytes_for(rank), false, true);
    ASSERT_EQ(part.part->n_cells(), expected) << where;
    ASSERT_TRUE(part.kept) << where;
    const auto kept_part = part.kept->with_shapes();
    for (int c = 0; c < part.part->n_cells(); ++c) {
      const int whole_cell = cells[c];
      ASSERT_EQ(part.part->global_cell(c), whole_cell) << where;
      EXPECT_EQ(part.cell_parts[c], parts[whole_cell]) << where;
      EXPECT_EQ(part.materials[c].mu, whole_cell) << where;
      for (const auto& [mine, reference] : {std::pair{part.space->cell_shapes(c), eliminated.cell_shapes(whole_cell)},
                                            std::pair{kept_part.cell_shapes(c), kept.cell_shapes(whole_cell)}}) {
        ASSERT_EQ(mine.size(), reference.size()) << where << ", cell " << whole_cell;
        for (std::size_t k = 0; k < mine.size(); ++k)
          EXPECT_EQ(mine[k].dof, reference[k].dof) << where << ", cell " << whole_cell;
      }
    }
  }
  EXPECT_TRUE(std::all_of(owners.begin(), owners.end(), [](int n) { return n == 1; }));
  std::vector<int> beyond = parts;
  beyond[0] = ranks;  // a cell of a rank outside the split
  EXPECT_THROW(operators::RankParts(square, whole, beyond, ranks, nullptr), std::logic_error);
}

// The sweep's work queue: every value below N goes to exactly one rank, on 1 to 4 ranks; a rank
// that exhausts the counter stops every rank from taking more.
TEST(SharedCounter, HandsEveryValueToExactlyOneRankAndStopsWhenExhausted) {
  for (int ranks : {1, 2, 4}) {
    const std::string where = std::to_string(ranks) + " ranks";
    const auto run = run_command(mpirun_command(ranks, HPCONTACT_COUNTER_CHECK, "400"));
    ASSERT_EQ(run.exit_code, 0) << where << "\n" << run.output;
    EXPECT_EQ(number_after(run.output, "taken"), 400) << where << "\n" << run.output;
    EXPECT_EQ(number_after(run.output, "distinct"), 400) << where << "\n" << run.output;
    EXPECT_EQ(number_after(run.output, "outside"), 0) << where << "\n" << run.output;
    // Value 3 exhausts the counter: exactly the values handed out before (0 .. 3 and any other
    // rank's meanwhile) are taken, each once, and none after.
    const auto stopped = run_command(mpirun_command(ranks, HPCONTACT_COUNTER_CHECK, "400 3"));
    ASSERT_EQ(stopped.exit_code, 0) << where << "\n" << stopped.output;
    const double taken = number_after(stopped.output, "taken");
    EXPECT_GE(taken, 4) << where << "\n" << stopped.output;
    EXPECT_EQ(number_after(stopped.output, "handed_out"), taken) << where << "\n" << stopped.output;
    EXPECT_EQ(number_after(stopped.output, "distinct"), taken) << where << "\n" << stopped.output;
  }
}

// Sums over the ranks are the same on every rank to the last bit (the replicated contact solvers
// and eigenproblems take their decisions from them), and right to round-off, on 3 to 5 ranks
// with additions whose order changes the rounded result, over two and a half 8 MB pieces.
TEST(DistributedFactor, SumsOverTheRanksAreBitIdenticalOnEveryRank) {
  for (int ranks : {3, 4, 5}) {
    const std::string where = std::to_string(ranks) + " ranks";
    const auto run = run_command(mpirun_command(ranks, HPCONTACT_SUM_CHECK, "2621440"));
    ASSERT_EQ(run.exit_code, 0) << where << "\n" << run.output;
    EXPECT_EQ(number_after(run.output, "differing_entries"), 0) << where << "\n" << run.output;
    EXPECT_LT(number_after(run.output, "relative_deviation"), 1e-15) << where << "\n" << run.output;
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
  // Indefinite in A_II alone, S_T positive definite: LU with a Schur set accepted this (MUMPS's
  // LDLᵀ counts the negative pivot).
  for (const char* solver : {"substructuring", "mumps"})
    for (int ranks : {1, 2, 3}) {
      const auto run = run_command(check_command(ranks, std::string(solver) + " strips indefinite_interior"));
      EXPECT_EQ(run.exit_code, 3) << solver << ", " << ranks << " ranks\n" << run.output;
      EXPECT_NE(run.output.find("not positive definite"), std::string::npos) << run.output;
    }
  // Without a trailing set (MUMPS's Cholesky, which counts negative pivots instead of stopping).
  for (const char* solver : {"substructuring", "mumps"})
    for (int ranks : {1, 2}) {
      const auto run = run_command(check_command(ranks, std::string(solver) + " strips indefinite_plain"));
      EXPECT_EQ(run.exit_code, 3) << solver << ", " << ranks << " ranks\n" << run.output;
      EXPECT_NE(run.output.find("not positive definite"), std::string::npos) << run.output;
    }
}

// An unknown that no rank's entries touch: substructuring finds it by the ranks' directory of
// shared unknowns (no array of the global length), MUMPS as a null pivot (with a Schur set its
// LDLᵀ would otherwise pivot past it and factorize a singular matrix); the same message on every
// rank, exit 3.
TEST(DistributedFactor, SubstructuringAndMumpsRefuseAnUnknownWithoutEntriesOnEveryRank) {
  for (int ranks : {1, 2, 3}) {
    const auto run = run_command(check_command(ranks, "substructuring strips untouched"));
    EXPECT_EQ(run.exit_code, 3) << ranks << " ranks\n" << run.output;
    EXPECT_NE(run.output.find("unknown 384 of 385 has no entries"), std::string::npos) << run.output;
    const auto mumps = run_command(check_command(ranks, "mumps strips untouched"));
    EXPECT_EQ(mumps.exit_code, 3) << ranks << " ranks\n" << mumps.output;
    EXPECT_NE(mumps.output.find("null pivot: the matrix is singular"), std::string::npos) << mumps.output;
  }
}

// A rank of the helper failing alone while the others wait in a collective call ends the job with
// its message and exit 3 (after the failure channel's patience) instead of hanging.
TEST(DistributedFactor, ARankFailingAloneEndsTheJobInsteadOfHanging) {
  const auto run = run_command(check_command(2, "fail_alone"));
  EXPECT_EQ(run.exit_code, 3) << run.output;
  EXPECT_NE(run.output.find("rank 1 failed alone"), std::string::npos) << run.output;
}

// Substructuring's interface problem alone (ScaLAPACK between the parts, the trailing block
// replicated), against dense Cholesky of the summed blocks: with both parts, without a trailing
// set, with the trailing set alone, and with fewer unknowns between the parts than ranks (the
// padding); a negative block fails on every rank.
TEST(DistributedFactor, InterfaceProblemOverTheRanksEqualsDenseCholesky) {
  for (int ranks : {1, 2, 3, 4})
    for (const auto& [n, m] : std::vector<std::pair<int, int>>{{37, 5}, {37, 0}, {5, 5}, {3, 1}}) {
      const std::string where =
          std::to_string(ranks) + " ranks, n = " + std::to_string(n) + ", m = " + std::to_string(m);
      const auto run = run_command(check_command(ranks, "interface " + std::to_string(n) + " " + std::to_string(m)));
      ASSERT_EQ(run.exit_code, 0) << where << "\n" << run.output;
      EXPECT_LT(number_after(run.output, "interface_solve"), 1e-11) << where << "\n" << run.output;
      EXPECT_LT(number_after(run.output, "interface_trailing"), 1e-11) << where << "\n" << run.output;
    }
  for (int ranks : {1, 3}) {
    const auto run = run_command(check_command(ranks, "interface 37 5 indefinite"));
    EXPECT_EQ(run.exit_code, 3) << ranks << " ranks\n" << run.output;
    EXPECT_NE(run.output.find("not positive definite"), std::string::npos) << run.output;
  }
}

TEST(DistributedFactor, SubstructuringNotesAnInterfaceLargerThanTheFactorsAndThan64MB) {
  // 2000² entries are 32 MB: too small to matter whatever the factors; 3000² are 72 MB.
  EXPECT_FALSE(linalg::interface_outweighs_factors(2000.0 * 2000.0, 0.0));
  EXPECT_TRUE(linalg::interface_outweighs_factors(3000.0 * 3000.0, 1e6));
  EXPECT_FALSE(linalg::interface_outweighs_factors(3000.0 * 3000.0, 1e7));
}
