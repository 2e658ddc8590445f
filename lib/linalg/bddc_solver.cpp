// BddcSolver: the local numbering of a rank's contributions, MATIS with its local SeqAIJ matrix,
// KSP CG + PCBDDC (or the MATIS assembled, + PCGAMG), replicated right-hand sides scattered in and
// results gathered back.
#include "linalg/bddc_solver.hpp"

#include <fmt/format.h>
#include <petscksp.h>

#include <algorithm>
#include <exception>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

#include "core/error.hpp"
#include "core/petsc_check.hpp"
#include "core/petsc_handle.hpp"
#include "core/petsc_session.hpp"
#include "linalg/node_blocks.hpp"
#include "linalg/projected_solves.hpp"
#include "linalg/row_exchange.hpp"

namespace hpcontact::linalg {

struct BddcSolver::Impl {
  PetscHandle<Mat, MatDestroy> matrix;
  PetscHandle<KSP, KSPDestroy> ksp;
  PetscInt row_begin = 0, row_end = 0;
  std::optional<RowExchange> exchange;  ///< between the subdomain's unknowns and the rank's rows
  mutable IterationCounts iterations;
  std::string name = "BDDC", prefix = "bddc_";  ///< the preconditioner's, and its PETSc options'
  std::optional<NodeBlocks> blocks;             ///< GAMG's rows, when they are a vector problem's node blocks
  /// One solve on the rank's owned rows (through the node blocks where there are). Collective.
  void solve(const double* owned_rhs, PetscInt owned, double* owned_solution) const;
};

namespace {

// The columns of `owned_rows` (this rank's rows of k vectors) orthonormalized (modified
// Gram–Schmidt, as MatNullSpaceCreate asks) and attached to `a` as its near null space. A column
// that the others (nearly) span, or that vanishes (its component fixed at every free vertex), is
// dropped: the norms are global, so every rank drops the same ones.
void set_near_null_space(Mat a, const Eigen::MatrixXd& owned_rows) {
  std::vector<PetscHandle<Vec, VecDestroy>> handles;
  std::vector<Vec> vectors;
  for (Eigen::Index j = 0; j < owned_rows.cols(); ++j) {
    PetscHandle<Vec, VecDestroy> column;
    HPC_PETSC_CALL(MatCreateVecs(a, column.out(), nullptr));
    PetscScalar* array = nullptr;
    HPC_PETSC_CALL(VecGetArray(column.get(), &array));
    std::copy(owned_rows.col(j).data(), owned_rows.col(j).data() + owned_rows.rows(), array);
    HPC_PETSC_CALL(VecRestoreArray(column.get(), &array));
    PetscReal before = 0.0, after = 0.0;
    HPC_PETSC_CALL(VecNorm(column.get(), NORM_2, &before));
    for (Vec kept : vectors) {
      PetscScalar dot = 0.0;
      HPC_PETSC_CALL(VecDot(column.get(), kept, &dot));
      HPC_PETSC_CALL(VecAXPY(column.get(), -dot, kept));
    }
    HPC_PETSC_CALL(VecNormalize(column.get(), &after));
    if (!(after > 1e-10 * before)) continue;
    vectors.push_back(column.get());
    handles.push_back(std::move(column));
  }
  if (vectors.empty()) return;
  PetscHandle<MatNullSpace, MatNullSpaceDestroy> space;
  HPC_PETSC_CALL(MatNullSpaceCreate(PetscObjectComm(reinterpret_cast<PetscObject>(a)), PETSC_FALSE,
                                    static_cast<PetscInt>(vectors.size()), vectors.data(), space.out()));
  HPC_PETSC_CALL(MatSetNearNullSpace(a, space.get()));
}

// The local unknowns `members` as a sequential index set (what PCBDDC's local setters take).
PetscHandle<IS, ISDestroy> local_index_set(const std::vector<PetscInt>& members) {
  PetscHandle<IS, ISDestroy> set;
  HPC_PETSC_CALL(ISCreateGeneral(PETSC_COMM_SELF, static_cast<PetscInt>(members.size()), members.data(),
                                 PETSC_COPY_VALUES, set.out()));
  return set;
}

// Tells BDDC the field of each local unknown. Told nothing, its graph sees one field, and the
// constraints it builds on an interface edge do not hold the displacement components apart: on
// the elastic square (n = 32, p = 4) cut into 3 parts, one floating, CG took 38 iterations per
// solve, 20 with the fields split.
void split_fields(PC pc, MPI_Comm ranks, PetscInt n_local, const std::vector<int>& fields) {
  int count = fields.empty() ? 1 : *std::max_element(fields.begin(), fields.end()) + 1;
  MPI_Allreduce(MPI_IN_PLACE, &count, 1, MPI_INT, MPI_MAX, ranks);
  int fits = fields.empty() || static_cast<PetscInt>(fields.size()) == n_local ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &fits, 1, MPI_INT, MPI_LAND, ranks);
  HPC_VERIFY(fits, "BDDC: fields not at the ranks' unknowns");
  if (count == 1) return;
  std::vector<std::vector<PetscInt>> members(count);
  for (PetscInt i = 0; i < static_cast<PetscInt>(fields.size()); ++i) members[fields[i]].push_back(i);
  std::vector<PetscHandle<IS, ISDestroy>> handles;
  std::vector<IS> sets;
  for (const auto& field : members) {
    handles.push_back(local_index_set(field));
    sets.push_back(handles.back().get());
  }
  HPC_PETSC_CALL(PCBDDCSetDofsSplittingLocal(pc, count, sets.data()));
}

// Tells BDDC which local unknowns lie on the natural (non-Dirichlet) boundary. Its graph then
// sets them apart from the interface edges, so an edge that reaches the boundary ends in a primal
// vertex there. Without them, the elastic square (n = 32) on 4 ranks (two parts floating, one
// cross point each) gave an indefinite preconditioner with the fields split, 62 iterations per
// solve without; with both, 19. (Likely cause: a part whose primal vertices leave a rigid motion
// free has a singular Neumann problem, which MUMPS's null-pivot detection only pseudo-inverts.)
void mark_natural_boundary(PC pc, MPI_Comm ranks, const RowExchange& exchange,
                           const std::vector<int>& natural_boundary) {
  const auto n_local = static_cast<Eigen::Index>(exchange.local().size());
  int fits = 1;
  for (int i : natural_boundary)
    if (i < 0 || i >= n_local) fits = 0;
  MPI_Allreduce(MPI_IN_PLACE, &fits, 1, MPI_INT, MPI_LAND, ranks);
  HPC_VERIFY(fits, "BDDC: natural boundary outside the ranks' unknowns");
  // PETSc's graph does not reconcile the marks of a shared unknown, and a rank may hold a boundary
  // vertex through a cell that touches it at a corner only (no boundary edge of its own there):
  // an unknown is marked on every rank holding it if any rank marked it.
  Eigen::MatrixXd marks = Eigen::MatrixXd::Zero(n_local, 1);
  for (int i : natural_boundary) marks(i, 0) = 1.0;
  marks = exchange.owned_to_local(exchange.sum_to_owned(marks));
  std::vector<PetscInt> members;
  for (Eigen::Index i = 0; i < n_local; ++i)
    if (marks(i, 0) > 0.0) members.push_back(static_cast<PetscInt>(i));
  HPC_PETSC_CALL(PCBDDCSetNeumannBoundariesLocal(pc, local_index_set(members).get()));
}

// The unknowns the rank's entries touch (global indices, ascending): its subdomain.
std::vector<PetscInt> subdomain_unknowns(int n, const std::vector<Eigen::Triplet<double>>& lower_entries) {
  std::vector<PetscInt> global;
  global.reserve(2 * lower_entries.size());
  for (const auto& entry : lower_entries) {
    HPC_VERIFY(entry.row() >= entry.col() && entry.row() < n, "BDDC: entry outside the lower triangle");
    global.push_back(entry.row());
    global.push_back(entry.col());
  }
  std::sort(global.begin(), global.end());
  global.erase(std::unique(global.begin(), global.end()), global.end());
  return global;
}

// The MATIS `a` of the ranks' subdomains: each rank's local matrix holds its contributions (both
// triangles) at its unknowns `subdomain`, numbered locally in global order.
void create_unassembled_matrix(MPI_Comm ranks, int n, const std::vector<PetscInt>& subdomain,
                               const std::vector<Eigen::Triplet<double>>& lower_entries, Mat* a) {
  auto local_of = [&](PetscInt g) {
    return static_cast<PetscInt>(std::lower_bound(subdomain.begin(), subdomain.end(), g) - subdomain.begin());
  };
  PetscHandle<ISLocalToGlobalMapping, ISLocalToGlobalMappingDestroy> map;
  HPC_PETSC_CALL(ISLocalToGlobalMappingCreate(ranks, 1, static_cast<PetscInt>(subdomain.size()), subdomain.data(),
                                              PETSC_COPY_VALUES, map.out()));
  HPC_PETSC_CALL(MatCreateIS(ranks, 1, PETSC_DECIDE, PETSC_DECIDE, n, n, map.get(), map.get(), a));
  Mat local = nullptr;
  HPC_PETSC_CALL(MatISGetLocalMat(*a, &local));
  std::vector<PetscInt> rows, cols;
  std::vector<PetscScalar> values;
  for (const auto& entry : lower_entries) {
    const PetscInt r = local_of(entry.row()), c = local_of(entry.col());
    rows.push_back(r), cols.push_back(c), values.push_back(entry.value());
    if (r != c) rows.push_back(c), cols.push_back(r), values.push_back(entry.value());
  }
  HPC_PETSC_CALL(MatSetType(local, MATSEQAIJ));
  HPC_PETSC_CALL(MatSetPreallocationCOO(local, static_cast<PetscCount>(rows.size()), rows.data(), cols.data()));
  HPC_PETSC_CALL(MatSetValuesCOO(local, values.data(), ADD_VALUES));
  HPC_PETSC_CALL(MatISRestoreLocalMat(*a, &local));
  HPC_PETSC_CALL(MatAssemblyBegin(*a, MAT_FINAL_ASSEMBLY));
  HPC_PETSC_CALL(MatAssemblyEnd(*a, MAT_FINAL_ASSEMBLY));
  HPC_PETSC_CALL(MatSetOption(*a, MAT_SYMMETRIC, PETSC_TRUE));
  HPC_PETSC_CALL(MatSetOption(*a, MAT_SPD, PETSC_TRUE));
}

// A subdomain that touches no Dirichlet part floats: its Neumann problem is singular (constants,
// or elasticity's rigid motions, which BDDC's vertex and edge constraints remove only from the
// coarse problem), and PETSc's own LU stops on the zero pivot. MUMPS with null-pivot detection
// (ICNTL(24)) solves it; set unless the user chose otherwise.
void solve_floating_subdomains_by_mumps() {
  for (const auto& [name, value] : {std::pair{"-bddc_pc_bddc_neumann_pc_factor_mat_solver_type", "mumps"},
                                    std::pair{"-bddc_pc_bddc_neumann_mat_mumps_icntl_24", "1"}}) {
    PetscBool set = PETSC_FALSE;
    HPC_PETSC_CALL(PetscOptionsHasName(nullptr, nullptr, name, &set));
    if (!set) HPC_PETSC_CALL(PetscOptionsSetValue(nullptr, name, value));
  }
}

// The rank's owned rows of the hints' near null space, checked to lie at the rank's unknowns
// (agreed over the ranks: one rank failing alone would leave the others in the scatter); no
// columns where no rank has motions.
Eigen::MatrixXd owned_near_null_space(MPI_Comm ranks, const Eigen::MatrixXd& near_null_space, PetscInt n_local,
                                      const RowExchange& exchange) {
  int motion_columns = static_cast<int>(near_null_space.cols());
  MPI_Allreduce(MPI_IN_PLACE, &motion_columns, 1, MPI_INT, MPI_MAX, ranks);
  if (motion_columns == 0) return Eigen::MatrixXd(exchange.owned_rows(), 0);
  int fits = near_null_space.rows() == n_local && near_null_space.cols() == motion_columns ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &fits, 1, MPI_INT, MPI_LAND, ranks);
  HPC_VERIFY(fits, "BDDC: near null space not at the ranks' unknowns");
  return exchange.consistent_to_owned(near_null_space);
}

// The near null space (elasticity's rigid motions) joins BDDC's coarse space unless the user
// sets -bddc_pc_bddc_use_nnsp 0. Since BDDC is told the fields and the natural boundary it
// converged in every run (six elastic scenes on 3, 4, 6 and 8 ranks) and kept CG's iterations
// nearly flat in the ranks (elastic square n = 32: 16.5 … 19.2 per solve, against 19.7 … 29
// without). Before, it made the preconditioner indefinite on the 8 × 8 square on 3 ranks.
// Attaches it to `a`; returns whether BDDC is to use it by the default rather than the user's
// choice (which PCBDDC reads from the options only).
bool attach_near_null_space(Mat a, MPI_Comm ranks, const Eigen::MatrixXd& near_null_space, PetscInt n_local,
                            const RowExchange& exchange) {
  PetscBool use_motions = PETSC_TRUE, user_chose = PETSC_FALSE;
  HPC_PETSC_CALL(PetscOptionsGetBool(nullptr, nullptr, "-bddc_pc_bddc_use_nnsp", &use_motions, &user_chose));
  if (!use_motions) return false;
  const Eigen::MatrixXd owned = owned_near_null_space(ranks, near_null_space, n_local, exchange);
  if (owned.cols() > 0) set_near_null_space(a, owned);
  return !user_chose && owned.cols() > 0;
}

// Makes `ksp` CG on `a` with options `prefix` and preconditioner `type`; returns the PC.
PC conjugate_gradients(KSP ksp, Mat a, const char* prefix, PCType type, double relative_tolerance) {
  HPC_PETSC_CALL(KSPSetOptionsPrefix(ksp, prefix));
  HPC_PETSC_CALL(KSPSetOperators(ksp, a, a));
  HPC_PETSC_CALL(KSPSetType(ksp, KSPCG));
  PC pc = nullptr;
  HPC_PETSC_CALL(KSPGetPC(ksp, &pc));
  HPC_PETSC_CALL(PCSetType(pc, type));
  HPC_PETSC_CALL(KSPSetTolerances(ksp, relative_tolerance, 0.0, PETSC_DEFAULT, 2000));
  // Relative to the initial residual, not to the preconditioned right-hand side: PCBDDC's pre-solve
  // starts CG from the subdomain interiors' solution, and for some right-hand sides (met on a Gmsh
  // annulus) the preconditioned b is zero, so PETSc's default test reports DIVERGED_DTOL at
  // iteration 0.
  HPC_PETSC_CALL(KSPConvergedDefaultSetUIRNorm(ksp));
  return pc;
}

// CG + BDDC on `a` with PETSc's default (multiplicity) scaling, told the hints' fields and
// natural boundary. -bddc_pc_bddc_use_deluxe_scaling saves 0-27 % of the iterations on the scenes
// measured (docs/user_guide.md), but in Debian 12's PETSc 3.18 with MUMPS 5.5 it fails on some
// splits (INFOG(1) = -46, a solve with no right-hand side, in PCBDDCSetUpCorrection; -8 in the
// deluxe Schur complements; both on test_07's graph Laplacian): an option, not the default.
void set_up_conjugate_gradients(KSP ksp, Mat a, MPI_Comm ranks, PetscInt n_local, const BddcHints& hints,
                                const RowExchange& exchange, double relative_tolerance, bool default_motions) {
  PC pc = conjugate_gradients(ksp, a, "bddc_", PCBDDC, relative_tolerance);
  split_fields(pc, ranks, n_local, hints.fields);
  mark_natural_boundary(pc, ranks, exchange, hints.natural_boundary);
  // (PCBDDC reads use_nnsp from the options only: set for this solver alone, so that it does not
  // become the user's choice for the next one)
  if (default_motions) HPC_PETSC_CALL(PetscOptionsSetValue(nullptr, "-bddc_pc_bddc_use_nnsp", "1"));
  const PetscErrorCode set_from_options = KSPSetFromOptions(ksp);
  if (default_motions) HPC_PETSC_CALL(PetscOptionsClearValue(nullptr, "-bddc_pc_bddc_use_nnsp"));
  HPC_PETSC_CALL(set_from_options);
  HPC_PETSC_CALL(KSPSetUp(ksp));
}

// CG + GAMG on the assembled `a`, whose near null space (the rigid motions) is already attached:
// smoothed aggregation builds its coarse spaces from them.
void set_up_gamg(KSP ksp, Mat a, double relative_tolerance) {
  conjugate_gradients(ksp, a, "gamg_", PCGAMG, relative_tolerance);
  HPC_PETSC_CALL(KSPSetFromOptions(ksp));
  HPC_PETSC_CALL(KSPSetUp(ksp));
}

// The rows [begin, end) of n that PETSc's default layout (PETSC_DECIDE) gives this rank.
std::pair<PetscInt, PetscInt> default_rows(MPI_Comm ranks, int n) {
  PetscInt local = PETSC_DECIDE, global = n, end = 0;
  HPC_PETSC_CALL(PetscSplitOwnership(ranks, &local, &global));
  MPI_Scan(&local, &end, 1, MPIU_INT, MPI_SUM, ranks);
  return {end - local, end};
}

// The number of components of a vector problem's nodes (1: a scalar one, or no nodes given),
// agreed over the ranks.
int node_components(MPI_Comm ranks, const BddcHints& hints, std::size_t n_local) {
  int count = hints.fields.empty() ? 1 : *std::max_element(hints.fields.begin(), hints.fields.end()) + 1;
  int given = hints.node.size() == n_local && hints.fields.size() == n_local ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &count, 1, MPI_INT, MPI_MAX, ranks);
  MPI_Allreduce(MPI_IN_PLACE, &given, 1, MPI_INT, MPI_LAND, ranks);
  return given ? count : 1;
}

}  // namespace

BddcSolver::BddcSolver(MPI_Comm ranks, int n, const std::vector<Eigen::Triplet<double>>& lower_entries,
                       double relative_tolerance, const BddcHints& hints, KrylovPreconditioner preconditioner)
    : impl_(std::make_unique<Impl>()), ranks_(ranks), size_(n) {
  // The rank's subdomain (the unknowns its entries touch).
  const std::vector<PetscInt> subdomain = subdomain_unknowns(n, lower_entries);
  const auto n_local = static_cast<PetscInt>(subdomain.size());
  std::tie(impl_->row_begin, impl_->row_end) = default_rows(ranks, n);
  impl_->exchange.emplace(ranks, n, static_cast<int>(impl_->row_begin), static_cast<int>(impl_->row_end),
                          std::vector<int>(subdomain.begin(), subdomain.end()));
  HPC_PETSC_CALL(KSPCreate(ranks, impl_->ksp.out()));
  if (preconditioner == KrylovPreconditioner::gamg) {
    // Assembled, in node blocks where the problem has them (no MATIS: one copy of the matrix).
    const Eigen::MatrixXd motions = owned_near_null_space(ranks, hints.near_null_space, n_local, *impl_->exchange);
    if (const int components = node_components(ranks, hints, subdomain.size()); components > 1) {
      impl_->blocks.emplace(ranks, n, impl_->row_begin, impl_->row_end, subdomain, hints.node, hints.fields,
                            components);
      impl_->blocks->assemble(lower_entries, impl_->matrix.out());
    } else {
      create_unassembled_matrix(ranks, n, subdomain, lower_entries, impl_->matrix.out());
      HPC_PETSC_CALL(MatConvert(impl_->matrix.get(), MATAIJ, MAT_INPLACE_MATRIX, impl_->matrix.out()));
    }
    Mat a = impl_->matrix.get();
    HPC_PETSC_CALL(MatSetOption(a, MAT_SYMMETRIC, PETSC_TRUE));
    HPC_PETSC_CALL(MatSetOption(a, MAT_SPD, PETSC_TRUE));
    if (motions.cols() > 0) set_near_null_space(a, impl_->blocks ? impl_->blocks->to_blocks(motions) : motions);
    impl_->name = "GAMG", impl_->prefix = "gamg_";
    set_up_gamg(impl_->ksp.get(), a, relative_tolerance);
    return;
  }
  // The Neumann matrices in a MATIS, what BDDC needs beyond them, then the iteration.
  create_unassembled_matrix(ranks, n, subdomain, lower_entries, impl_->matrix.out());
  Mat a = impl_->matrix.get();
  PetscInt begin = 0, end = 0;
  HPC_PETSC_CALL(MatGetOwnershipRange(a, &begin, &end));
  HPC_VERIFY(begin == impl_->row_begin && end == impl_->row_end, "BDDC: the MATIS rows are not PETSc's default");
  solve_floating_subdomains_by_mumps();
  const bool default_motions = attach_near_null_space(a, ranks, hints.near_null_space, n_local, *impl_->exchange);
  set_up_conjugate_gradients(impl_->ksp.get(), a, ranks, n_local, hints, *impl_->exchange, relative_tolerance,
                             default_motions);
}

BddcSolver::~BddcSolver() {
  // PCBDDC's coarse solver is destroyed collectively: as for DistributedCholesky, a rank unwinding
  // from a failure of its own must not wait there for the others.
  if (impl_ && std::uncaught_exceptions() > 0 && rank_and_size(ranks_).second > 1) (void)impl_.release();
}
BddcSolver::BddcSolver(BddcSolver&&) noexcept = default;
BddcSolver& BddcSolver::operator=(BddcSolver&&) noexcept = default;

std::optional<IterationCounts> BddcSolver::iterations() const { return impl_->iterations; }

namespace {

// One solve: the rank's rows of the right-hand side in, the rank's rows of the solution into
// `owned_solution` (both `owned` long: the rows PETSc gives the rank).
void solve_column(KSP ksp, Mat a, const double* owned_rhs, PetscInt owned, double* owned_solution,
                  IterationCounts& count, const std::string& name, const std::string& prefix) {
  PetscHandle<Vec, VecDestroy> b, x;
  HPC_PETSC_CALL(MatCreateVecs(a, x.out(), b.out()));
  PetscScalar* array = nullptr;
  HPC_PETSC_CALL(VecGetArray(b.get(), &array));
  std::copy(owned_rhs, owned_rhs + owned, array);
  HPC_PETSC_CALL(VecRestoreArray(b.get(), &array));
  HPC_PETSC_CALL(KSPSolve(ksp, b.get(), x.get()));
  KSPConvergedReason reason;
  HPC_PETSC_CALL(KSPGetConvergedReason(ksp, &reason));
  PetscInt iterations = 0;
  HPC_PETSC_CALL(KSPGetIterationNumber(ksp, &iterations));
  const bool round_off_stop = reason == KSP_DIVERGED_INDEFINITE_PC || reason == KSP_DIVERGED_BREAKDOWN;
  if (round_off_stop) {
    // Near round-off CG may stop on a tiny negative or zero (z, r) of the preconditioner (not
    // exactly symmetric in floating point) after the iterate is already converged: judge the answer
    // by its true residual. Other stops (iteration limit, divergence) are failures as they are.
    PetscHandle<Vec, VecDestroy> residual;
    HPC_PETSC_CALL(VecDuplicate(b.get(), residual.out()));
    HPC_PETSC_CALL(MatMult(a, x.get(), residual.get()));
    HPC_PETSC_CALL(VecAYPX(residual.get(), -1.0, b.get()));
    PetscReal residual_norm = 0.0, rhs_norm = 0.0, rtol = 0.0;
    HPC_PETSC_CALL(VecNorm(residual.get(), NORM_2, &residual_norm));
    HPC_PETSC_CALL(VecNorm(b.get(), NORM_2, &rhs_norm));
    HPC_PETSC_CALL(KSPGetTolerances(ksp, &rtol, nullptr, nullptr, nullptr));
    if (residual_norm <= 100 * rtol * rhs_norm) {
      reason = KSP_CONVERGED_RTOL;
      ++count.round_off_stops;
    }
  }
  if (reason < 0) {
    const bool indefinite = reason == KSP_DIVERGED_INDEFINITE_PC || reason == KSP_DIVERGED_INDEFINITE_MAT;
    throw NumericalError(fmt::format("{}: conjugate gradients did not converge ({} after {} iterations; {})", name,
                                     KSPConvergedReasons[reason], iterations,
                                     indefinite ? "the matrix is not positive definite"
                                                : fmt::format("raise -{0}ksp_max_it or loosen -{0}ksp_rtol", prefix)));
  }
  ++count.solves;
  count.total += iterations;
  count.largest = std::max(count.largest, static_cast<int>(iterations));
  const PetscScalar* solution = nullptr;
  HPC_PETSC_CALL(VecGetArrayRead(x.get(), &solution));
  std::copy(solution, solution + owned, owned_solution);
  HPC_PETSC_CALL(VecRestoreArrayRead(x.get(), &solution));
}

}  // namespace

void BddcSolver::Impl::solve(const double* owned_rhs, PetscInt owned, double* owned_solution) const {
  if (!blocks) {
    solve_column(ksp.get(), matrix.get(), owned_rhs, owned, owned_solution, iterations, name, prefix);
    return;
  }
  const Eigen::MatrixXd rhs = blocks->to_blocks(Eigen::Map<const Eigen::VectorXd>(owned_rhs, owned));
  Eigen::MatrixXd solution(rhs.rows(), 1);
  solve_column(ksp.get(), matrix.get(), rhs.data(), blocks->owned_block_rows(), solution.data(), iterations, name,
               prefix);
  Eigen::Map<Eigen::VectorXd>(owned_solution, owned) = blocks->from_blocks(solution);
}

Eigen::MatrixXd BddcSolver::solve_owned(const Eigen::MatrixXd& owned_rhs) const {
  const PetscInt owned = impl_->row_end - impl_->row_begin;
  HPC_VERIFY(owned_rhs.rows() == owned, "right-hand side of the wrong size");
  Eigen::MatrixXd out(owned, owned_rhs.cols());
  for (Eigen::Index k = 0; k < owned_rhs.cols(); ++k) impl_->solve(owned_rhs.col(k).data(), owned, out.col(k).data());
  return out;
}

Eigen::MatrixXd BddcSolver::solve(const Eigen::MatrixXd& rhs) const {
  HPC_VERIFY(rhs.rows() == size_, "right-hand side of the wrong size");
  return solve_replicated(ranks_, static_cast<int>(impl_->row_begin), static_cast<int>(impl_->row_end), rhs,
                          [this](const Eigen::MatrixXd& owned) { return solve_owned(owned); });
}

const std::vector<int>& BddcSolver::local_unknowns() const { return impl_->exchange->local(); }

Eigen::MatrixXd BddcSolver::solve_local(const Eigen::MatrixXd& partial_rhs) const {
  return impl_->exchange->owned_to_local(solve_owned(impl_->exchange->sum_to_owned(partial_rhs)));
}

Eigen::MatrixXd BddcSolver::schur_complement(const Coupling& b) const {
  HPC_VERIFY(b.cols() == size_, "B A⁻¹ Bᵀ: B has the wrong number of columns");
  const auto m = b.rows();
  const PetscInt owned = impl_->row_end - impl_->row_begin;
  // Only the rank's rows of Bᵀ and of each solution: no vector of the global length.
  const auto b_owned = squeezed<Coupling>(b.middleCols(impl_->row_begin, owned));
  const auto bt_owned = squeezed<Eigen::SparseMatrix<double>>(b_owned.transpose());
  Eigen::MatrixXd result = Eigen::MatrixXd::Zero(m, m);
  Eigen::VectorXd owned_rhs(owned), owned_solution(owned);
  for (Eigen::Index j = 0; j < m; ++j) {
    owned_rhs = bt_owned.col(j);
    impl_->solve(owned_rhs.data(), owned, owned_solution.data());
    result.col(j) = b_owned * owned_solution;
  }
  sum_over_ranks(ranks_, result.data(), result.size());
  return 0.5 * (result + result.transpose());
}

std::unique_ptr<ConstrainedSolver> BddcSolver::constrained(const Coupling& c) const {
  return make_projected_solves(ranks_, size_, impl_->row_begin, impl_->row_end,
                               impl_->blocks ? &*impl_->blocks : nullptr, impl_->matrix.get(), impl_->ksp.get(), c,
                               impl_->name);
}

}  // namespace hpcontact::linalg
