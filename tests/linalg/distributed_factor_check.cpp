// Helper of distributed_factor_test, run under mpirun: every rank contributes its share of the
// element matrices of a random weighted graph Laplacian on a grid (semidefinite per element, so a
// rank's part floats unless it holds some of the "Dirichlet" diagonal), factorizes their sum over
// the ranks, and rank 0 prints the relative differences from CHOLMOD on the assembled matrix (and
// of the solve from shares at each rank's unknowns from the solver's replicated solve).
//
//   distributed_factor_check SOLVER SPLIT [indefinite]
//     SOLVER  substructuring | mumps | bddc
//     SPLIT   strips (elements in strips of x, one per rank) | scattered (element e on rank e %
//             ranks) | wide (strips, the trailing set also the second row and the side columns:
//             76 unknowns, more than twice what 2 strips share)
//     indefinite: one Dirichlet diagonal is −50 and one on the trailing row too (the
//     factorization must fail on every rank; exit 5 if the solver accepted the matrix)
//     untouched: the matrix has one more unknown than the grid, which no entry touches (outside
//     the trailing set: the factorization must fail on every rank, exit 5 otherwise; mumps or
//     substructuring)
//     indefinite_plain: as indefinite, factorized without a trailing set
//     indefinite_interior: the −50 on the Dirichlet row only, none on the trailing row (A_II is
//     indefinite, S_T alone would not tell)
//
//   distributed_factor_check fail_alone
//     rank 1 throws while rank 0 waits in a collective call: the helper must end the job (as the
//     tool does, MPI_Abort with exit 3) instead of hanging
//
//   distributed_factor_check interface N M [indefinite]
//     substructuring's interface problem alone (InterfaceCholesky): an N × N matrix, its last M
//     unknowns the trailing set, summed from random positive definite blocks each rank holds on
//     overlapping positions; prints the relative differences of its solve and of L_CC L_CCᵀ from
//     dense Cholesky of the sum (indefinite: one block negative, the factorization must fail)
#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <cstdio>
#include <random>
#include <string>

#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "core/rank_agreement.hpp"
#include "linalg/bddc_solver.hpp"
#include "linalg/distributed_cholesky.hpp"
#include "linalg/interface_cholesky.hpp"
#include "linalg/sparse_cholesky.hpp"
#include "linalg/substructured_cholesky.hpp"
#include "support/helper_failure.hpp"

using namespace hpcontact;

namespace {

constexpr int kNx = 24, kNy = 16;

int node(int i, int j) { return j * kNx + i; }

double relative_difference(const Eigen::MatrixXd& value, const Eigen::MatrixXd& reference) {
  return (value - reference).cwiseAbs().maxCoeff() / reference.cwiseAbs().maxCoeff();
}

int run(const std::string& solver, const std::string& split, bool indefinite, bool untouched, bool plain,
        bool interior_only) {
  // (not a structured binding: clang 14 refuses to capture one in the lambda below)
  const int rank = mpi_rank_and_size().first, ranks = mpi_rank_and_size().second;
  const int n = kNx * kNy;
  std::mt19937 random(7);  // the same numbers on every rank
  std::uniform_real_distribution<double> weight(0.5, 2.0), value(-1.0, 1.0);
  std::vector<Eigen::Triplet<double>> all, mine;
  std::vector<std::vector<int>> touching(n + 1);  // the ranks whose entries touch each unknown
  int element = 0;
  auto add_element = [&](const std::vector<Eigen::Triplet<double>>& entries, int owner) {
    for (const auto& entry : entries) {
      all.push_back(entry);
      if (owner == rank) mine.push_back(entry);
      for (int index : {entry.row(), entry.col()})
        if (std::find(touching[index].begin(), touching[index].end(), owner) == touching[index].end())
          touching[index].push_back(owner);
    }
    ++element;
  };
  // Cells: w (e_a − e_b)(e_a − e_b)ᵀ over the six pairs of the cell's nodes (lower triangle).
  for (int j = 0; j + 1 < kNy; ++j)
    for (int i = 0; i + 1 < kNx; ++i) {
      const int nodes[4] = {node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)};
      std::vector<Eigen::Triplet<double>> entries;
      for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b) {
          const double w = weight(random);
          const int hi = std::max(nodes[a], nodes[b]), lo = std::min(nodes[a], nodes[b]);
          entries.emplace_back(hi, hi, w), entries.emplace_back(lo, lo, w), entries.emplace_back(hi, lo, -w);
        }
      add_element(entries, split != "scattered" ? i * ranks / (kNx - 1) : element % ranks);
    }
  // "Dirichlet" diagonal on the top row, all on rank 0 (it touches every strip's top nodes).
  for (int i = 0; i < kNx; ++i)
    add_element({{node(i, kNy - 1), node(i, kNy - 1), indefinite && i == kNx / 2 ? -50.0 : weight(random)}}, 0);
  // The trailing set: the bottom row. B: 10 rows on it; B_out also reaches one interior node.
  std::vector<int> trailing;
  for (int i = 0; i < kNx; ++i) trailing.push_back(node(i, 0));
  if (split == "wide") {
    for (int i = 0; i < kNx; ++i) trailing.push_back(node(i, 1));
    for (int j = 2; j < kNy; ++j) trailing.push_back(node(0, j)), trailing.push_back(node(kNx - 1, j));
  }
  if (indefinite && !interior_only) add_element({{node(kNx / 2, 0), node(kNx / 2, 0), -50.0}}, 0);
  std::vector<Eigen::Triplet<double>> b_entries;
  for (int r = 0; r < 10; ++r)
    for (int k = 0; k < 5; ++k) b_entries.emplace_back(r, trailing[(3 * r + 5 * k) % kNx], value(random));
  linalg::Coupling b(10, n), b_out(10, n);
  b.setFromTriplets(b_entries.begin(), b_entries.end());
  b_entries.emplace_back(4, node(kNx / 2, kNy / 2), 1.0);
  b_out.setFromTriplets(b_entries.begin(), b_entries.end());
  Eigen::MatrixXd rhs(n, 3);
  for (Eigen::Index k = 0; k < rhs.size(); ++k) rhs.data()[k] = value(random);

  // Each rank's share of rhs at the unknowns it touches: the first toucher holds rhs + 0.5, the
  // last −0.5 (the same rank when one touches it alone).
  auto share_of = [&](const std::vector<int>& local) {
    Eigen::MatrixXd share = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(local.size()), rhs.cols());
    for (std::size_t k = 0; k < local.size(); ++k) {
      const auto& ranks_there = touching[local[k]];
      if (ranks_there.front() == rank) share.row(k).array() += rhs.row(local[k]).array() + 0.5;
      if (ranks_there.back() == rank) share.row(k).array() -= 0.5;
    }
    return share;
  };
  // solve_local against the same solver's replicated solve, at the rank's local unknowns; −1 when
  // the local unknowns are not those its entries touch, or a solve of no columns fails.
  double local_difference = 0.0;
  auto check_local = [&](const auto& factor, const Eigen::MatrixXd& replicated) {
    const std::vector<int>& local = factor.local_unknowns();
    std::vector<int> expected;
    for (int i = 0; i < n; ++i)
      if (std::find(touching[i].begin(), touching[i].end(), rank) != touching[i].end()) expected.push_back(i);
    local_difference = local == expected
                           ? relative_difference(factor.solve_local(share_of(local)), replicated(local, Eigen::all))
                           : -1.0;
    // No columns: no columns back, on both paths.
    const Eigen::MatrixXd none_local = factor.solve_local(Eigen::MatrixXd(local.size(), 0));
    const Eigen::MatrixXd none = factor.solve(Eigen::MatrixXd(n, 0));
    if (none_local.rows() != static_cast<Eigen::Index>(local.size()) || none_local.cols() != 0 || none.rows() != n ||
        none.cols() != 0)
      local_difference = -1.0;
    // The largest difference over the ranks, −1 if any rank's local unknowns were wrong.
    double worst[2] = {local_difference, -local_difference};
    MPI_Allreduce(MPI_IN_PLACE, worst, 2, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    local_difference = worst[1] > 0.0 ? -1.0 : worst[0];
  };
  Eigen::MatrixXd solution, schur, schur_out;
  int interface = 0;
  if (plain) {  // only the factorization is under test
    if (solver == "substructuring") {
      const linalg::SubstructuredCholesky factor(MPI_COMM_WORLD, n, mine, {});
    } else if (solver == "mumps") {
      const linalg::DistributedCholesky factor(MPI_COMM_WORLD, n, mine, {});
    }
    if (rank == 0) fmt::print("error: {} accepted an indefinite matrix\n", solver);
    return 5;
  }
  if (untouched) {  // (an unknown outside the trailing set: A_II is singular)
    if (solver == "mumps") {
      const linalg::DistributedCholesky factor(MPI_COMM_WORLD, n + 1, mine, trailing);
    } else {
      const linalg::SubstructuredCholesky factor(MPI_COMM_WORLD, n + 1, mine, trailing);
    }
    if (rank == 0) fmt::print("error: an unknown without entries was accepted\n");
    return 5;
  }
  if (solver == "substructuring") {
    const linalg::SubstructuredCholesky factor(MPI_COMM_WORLD, n, mine, trailing);
    solution = factor.solve(rhs), schur = factor.schur_complement(b), schur_out = factor.schur_complement(b_out);
    interface = factor.interface_size();
    check_local(factor, solution);
    if (rank == 0) fmt::print("factor_nonzeros_mean {}\n", factor.mean_factor_nonzeros());
  } else if (solver == "mumps") {
    const linalg::DistributedCholesky factor(MPI_COMM_WORLD, n, mine, trailing);
    solution = factor.solve(rhs), schur = factor.schur_complement(b), schur_out = factor.schur_complement(b_out);
    interface = factor.trailing_size();  // the Schur complement MUMPS returned
    check_local(factor, solution);
    // Without a trailing set MUMPS runs its Cholesky and MatMatSolve: the local solves again.
    const double with_trailing = local_difference;
    const linalg::DistributedCholesky cholesky(MPI_COMM_WORLD, n, mine, {});
    check_local(cholesky, solution);
    local_difference = std::min(with_trailing, local_difference) < 0 ? -1.0 : std::max(with_trailing, local_difference);
  } else if (solver == "bddc") {
    const linalg::BddcSolver factor(MPI_COMM_WORLD, n, mine);
    solution = factor.solve(rhs), schur = factor.schur_complement(b), schur_out = factor.schur_complement(b_out);
    check_local(factor, solution);
    if (rank == 0) fmt::print("iterations_largest {}\n", factor.iterations()->largest);
  } else {
    throw_bad_input("distributed_factor_check", "SOLVER", solver, "substructuring | mumps | bddc");
  }
  if (indefinite) {  // the solver under test must have refused it (not the reference below)
    if (rank == 0) fmt::print("error: {} accepted an indefinite matrix\n", solver);
    return 5;
  }
  if (rank != 0) return 0;
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(all.begin(), all.end());
  const linalg::SparseCholesky reference(a);
  fmt::print("solve {:.3e}\n", relative_difference(solution, reference.solve(rhs)));
  fmt::print("schur_trailing {:.3e}\n", relative_difference(schur, reference.schur_complement(b)));
  fmt::print("schur_fallback {:.3e}\n", relative_difference(schur_out, reference.schur_complement(b_out)));
  fmt::print("interface {}\n", interface);
  fmt::print("solve_local {:.3e}\n", local_difference);
  fmt::print("trailing_set {}\n", trailing.size());
  fmt::print("reference_factor_nonzeros {}\n", linalg::SparseCholesky(a, trailing).factor_nonzeros());
  return 0;
}

}  // namespace

// Rank r's positions: those ≡ r or r + 1 (mod the ranks), so that neighbours overlap; its block
// X Xᵀ + I there (−(X Xᵀ + 10 I) on rank 0 when `indefinite`).
std::pair<std::vector<int>, Eigen::MatrixXd> interface_block(int r, int ranks, int n, bool indefinite) {
  std::vector<int> positions;
  for (int i = 0; i < n; ++i)
    if (i % ranks == r || i % ranks == (r + 1) % ranks) positions.push_back(i);
  std::mt19937 random(11 + r);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  const auto size = static_cast<Eigen::Index>(positions.size());
  Eigen::MatrixXd x(size, size + 1);
  for (Eigen::Index i = 0; i < x.size(); ++i) x(i) = value(random);
  Eigen::MatrixXd block = x * x.transpose() + Eigen::MatrixXd::Identity(size, size);
  if (indefinite && r == 0) block = -(block + 10.0 * Eigen::MatrixXd::Identity(size, size));
  return {positions, block};
}

int run_interface(int n, int m, bool indefinite) {
  const auto [rank, ranks] = mpi_rank_and_size();
  Eigen::MatrixXd whole = Eigen::MatrixXd::Zero(n, n);
  for (int r = 0; r < ranks; ++r) {
    const auto [positions, block] = interface_block(r, ranks, n, indefinite);
    for (std::size_t i = 0; i < positions.size(); ++i)
      for (std::size_t j = 0; j < positions.size(); ++j) whole(positions[i], positions[j]) += block(i, j);
  }
  const auto [positions, block] = interface_block(rank, ranks, n, indefinite);
  const linalg::InterfaceCholesky factor(MPI_COMM_WORLD, n, m, positions, block);
  if (indefinite) return 5;
  std::mt19937 random(3);  // the same right-hand side on every rank
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Eigen::MatrixXd rhs(n, 2);
  for (Eigen::Index i = 0; i < rhs.size(); ++i) rhs(i) = value(random);
  const Eigen::MatrixXd reference = whole.llt().solve(rhs);
  double trailing = 0.0;
  if (m > 0) {
    const int h = n - m;
    const Eigen::MatrixXd schur =
        whole.bottomRightCorner(m, m) -
        whole.bottomLeftCorner(m, h) * whole.topLeftCorner(h, h).llt().solve(whole.topRightCorner(h, m));
    const Eigen::MatrixXd& l = factor.trailing_factor();
    trailing = relative_difference(l * l.transpose(), schur);
  }
  if (rank == 0)
    fmt::print("interface_solve {:.3e}\ninterface_trailing {:.3e}\n", relative_difference(factor.solve(rhs), reference),
               trailing);
  else
    (void)factor.solve(rhs);
  return 0;
}

int main(int argc, char** argv) {
  const PetscSession session({argv[0]});
  open_failure_channel();
  try {
    if (argc == 2 && std::string(argv[1]) == "fail_alone") {
      if (mpi_rank_and_size().first == 1) throw NumericalError("rank 1 failed alone");
      MPI_Barrier(MPI_COMM_WORLD);  // (rank 0 waits here for good)
      return 0;
    }
    if (argc < 3)
      throw_bad_input("distributed_factor_check", "arguments", std::to_string(argc - 1), "SOLVER SPLIT [indefinite]");
    const std::string mode = argc > 3 ? argv[3] : "";
    if (std::string(argv[1]) == "interface" && argc < 4)
      throw_bad_input("distributed_factor_check", "arguments", std::to_string(argc - 1), "interface N M [indefinite]");
    if (std::string(argv[1]) == "interface")
      return run_interface(std::stoi(argv[2]), std::stoi(argv[3]), argc > 4 && std::string(argv[4]) == "indefinite");
    const bool plain = mode == "indefinite_plain", interior_only = mode == "indefinite_interior";
    return run(argv[1], argv[2], mode == "indefinite" || plain || interior_only, mode == "untouched", plain,
               interior_only);
  } catch (const std::exception& error) {
    return testing::end_helper_on_failure(error);
  }
}
