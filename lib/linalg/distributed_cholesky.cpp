// DistributedCholesky: COO assembly into MPIAIJ (both triangles: MUMPS's Cholesky reads the upper
// one of an AIJ matrix), MUMPS factorization (with a Schur set on rank 0 for the trailing set),
// MatMatSolve on dense right-hand sides whose rows are split like the matrix's; replicated
// results summed over the ranks, local ones scattered from the owned rows (RowExchange).
#include "linalg/distributed_cholesky.hpp"

#include <fmt/format.h>
#include <mpi.h>
#include <petscmat.h>
#include <petscvec.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <exception>
#include <optional>
#include <tuple>

#include "core/error.hpp"
#include "core/petsc_check.hpp"
#include "core/petsc_handle.hpp"
#include "core/petsc_session.hpp"
#include "linalg/row_exchange.hpp"
#include "linalg/schur_complement.hpp"
#include "linalg/sorted_index_map.hpp"

namespace hpcontact::linalg {

struct DistributedCholesky::Impl {
  PetscHandle<Mat, MatDestroy> matrix, factor;
  PetscInt row_begin = 0, row_end = 0;
  std::optional<RowExchange> exchange;  ///< between the unknowns the rank's entries touch and its rows
  std::vector<int> trailing;
  SortedIndexMap trailing_position;            ///< unknown → its row in S_T
  Eigen::LLT<Eigen::MatrixXd> trailing_schur;  ///< S_T = L_T L_Tᵀ, replicated
};

namespace {

// S_T as MUMPS returned it on rank 0 of `ranks` (one triangle or both) made whole and symmetric,
// then sent to every rank.
Eigen::MatrixXd replicated_trailing_schur(MPI_Comm ranks, Mat factor, int size) {
  Eigen::MatrixXd schur = Eigen::MatrixXd::Zero(size, size);
  if (rank_and_size(ranks).first == 0) {
    PetscHandle<Mat, MatDestroy> s;
    MatFactorSchurStatus status;
    HPC_PETSC_CALL(MatFactorCreateSchurComplement(factor, s.out(), &status));
    const PetscScalar* values = nullptr;
    PetscInt lda = 0;
    HPC_PETSC_CALL(MatDenseGetLDA(s.get(), &lda));
    HPC_PETSC_CALL(MatDenseGetArrayRead(s.get(), &values));
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) schur(i, j) = values[i + static_cast<std::ptrdiff_t>(j) * lda];
    HPC_PETSC_CALL(MatDenseRestoreArrayRead(s.get(), &values));
    const double upper = schur.triangularView<Eigen::StrictlyUpper>().toDenseMatrix().cwiseAbs().sum();
    const double lower = schur.triangularView<Eigen::StrictlyLower>().toDenseMatrix().cwiseAbs().sum();
    if (upper == 0.0)
      schur = Eigen::MatrixXd(schur.selfadjointView<Eigen::Lower>());
    else if (lower == 0.0)
      schur = Eigen::MatrixXd(schur.selfadjointView<Eigen::Upper>());
    else
      schur = 0.5 * (schur + schur.transpose());
  }
  if (rank_and_size(ranks).second > 1)
    HPC_VERIFY(MPI_Bcast(schur.data(), static_cast<int>(schur.size()), MPI_DOUBLE, 0, ranks) == MPI_SUCCESS,
               "MPI_Bcast failed");
  return schur;
}

// A's entries in both triangles, as PETSc's COO arrays: MUMPS's Cholesky reads the upper one of
// an AIJ matrix.
struct CooEntries {
  std::vector<PetscInt> rows, cols;
  std::vector<PetscScalar> values;
};

CooEntries both_triangles(int n, const std::vector<Eigen::Triplet<double>>& lower_entries) {
  CooEntries out;
  out.rows.reserve(2 * lower_entries.size());
  out.cols.reserve(2 * lower_entries.size());
  out.values.reserve(2 * lower_entries.size());
  for (const auto& entry : lower_entries) {
    HPC_VERIFY(entry.row() >= entry.col() && entry.row() < n, "distributed Cholesky: entry outside the lower triangle");
    out.rows.push_back(entry.row()), out.cols.push_back(entry.col()), out.values.push_back(entry.value());
    if (entry.row() != entry.col())
      out.rows.push_back(entry.col()), out.cols.push_back(entry.row()), out.values.push_back(entry.value());
  }
  return out;
}

// Each trailing unknown's row of S_T (its place in `trailing`).
SortedIndexMap trailing_positions(int n, const std::vector<int>& trailing) {
  std::vector<std::pair<int, int>> positions;
  for (std::size_t k = 0; k < trailing.size(); ++k) {
    HPC_VERIFY(trailing[k] >= 0 && trailing[k] < n, "distributed Cholesky: trailing set outside the unknowns");
    positions.emplace_back(trailing[k], static_cast<int>(k));
  }
  return SortedIndexMap(std::move(positions));  // (refuses a repeated index)
}

// The MPIAIJ matrix `a` (rows in contiguous blocks) summed from every rank's `entries` (not const:
// PETSc 3.18's COO preallocation takes its index arrays so).
void assemble_matrix(MPI_Comm ranks, int n, CooEntries& entries, bool with_schur_set, Mat* a) {
  HPC_PETSC_CALL(MatCreate(ranks, a));
  HPC_PETSC_CALL(MatSetSizes(*a, PETSC_DECIDE, PETSC_DECIDE, n, n));
  HPC_PETSC_CALL(MatSetType(*a, MATAIJ));
  HPC_PETSC_CALL(MatSetPreallocationCOO(*a, static_cast<PetscCount>(entries.rows.size()), entries.rows.data(),
                                        entries.cols.data()));
  HPC_PETSC_CALL(MatSetValuesCOO(*a, entries.values.data(), ADD_VALUES));
  HPC_PETSC_CALL(MatSetOption(*a, MAT_SYMMETRIC, PETSC_TRUE));
  // Declared positive definite, MUMPS runs its SYM = 1 LDLᵀ, whose Schur complement comes back
  // under mpirun with zero off-diagonal entries (PETSc 3.18.5, MUMPS 5.5: S_T off by 80 % in
  // test_07 on 2 and 3 ranks, right on one). With a Schur set the matrix is therefore declared
  // symmetric only: MUMPS's SYM = 2 LDLᵀ (with pivoting) returns S_T to 1e-14 on 1–3 ranks, in
  // less memory and time than the LU used before (see docs/performance.md). Without a Schur set it
  // stays SYM = 1: ScaLAPACK then factorizes the root front, and only its Cholesky (SYM = 1)
  // refuses an indefinite one there; SYM = 2 would count no negative pivots in it (PETSc asks
  // for ICNTL(13) = 1 before it reports an inertia).
  if (!with_schur_set) HPC_PETSC_CALL(MatSetOption(*a, MAT_SPD, PETSC_TRUE));
}

// The unknowns among `rows`, ascending, each once.
std::vector<int> touched_unknowns(const std::vector<PetscInt>& rows) {
  std::vector<int> touched(rows.begin(), rows.end());
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  return touched;
}

// One attempt at MUMPS's factor `f` of `a`, with `trailing` as its Schur set and `extra_workspace`
// as ICNTL(14) (percent; 0: MUMPS's default). INFOG(1) afterwards (0: factorized).
PetscInt try_mumps_factor(MPI_Comm ranks, Mat a, const std::vector<int>& trailing, PetscInt extra_workspace, Mat* f) {
  HPC_PETSC_CALL(MatGetFactor(a, MATSOLVERMUMPS, MAT_FACTOR_CHOLESKY, f));
  if (!trailing.empty()) {
    // PETSc's MUMPS interface takes a parallel Schur set only when rank 0 holds all of it: S_T
    // comes back whole on rank 0.
    const bool root = rank_and_size(ranks).first == 0;
    std::vector<PetscInt> indices =
        root ? std::vector<PetscInt>(trailing.begin(), trailing.end()) : std::vector<PetscInt>{};
    PetscHandle<IS, ISDestroy> schur_set;
    HPC_PETSC_CALL(ISCreateGeneral(PETSC_COMM_SELF, static_cast<PetscInt>(indices.size()), indices.data(),
                                   PETSC_COPY_VALUES, schur_set.out()));
    HPC_PETSC_CALL(MatFactorSetSchurIS(*f, schur_set.get()));
  }
  // Null pivots counted (INFOG(28)), not passed over: SYM = 2 with a Schur set otherwise replaces
  // a zero pivot of A_II by a static pivot and factorizes a singular matrix without complaint.
  HPC_PETSC_CALL(MatMumpsSetIcntl(*f, 24, 1));
  if (extra_workspace > 0) HPC_PETSC_CALL(MatMumpsSetIcntl(*f, 14, extra_workspace));
  MatFactorInfo info;
  HPC_PETSC_CALL(MatFactorInfoInitialize(&info));
  HPC_PETSC_CALL(MatCholeskyFactorSymbolic(*f, a, nullptr, &info));
  HPC_PETSC_CALL(MatCholeskyFactorNumeric(*f, a, &info));
  MatFactorError error = MAT_FACTOR_NOERROR;
  HPC_PETSC_CALL(MatFactorGetError(*f, &error));
  PetscInt infog1 = 0;
  if (error != MAT_FACTOR_NOERROR) HPC_PETSC_CALL(MatMumpsGetInfog(*f, 1, &infog1));
  return infog1;
}

// MUMPS's factor `f` of `a`, with `trailing` as its Schur set. Where the workspace was too small
// (INFOG(1) = -8, -9 or -17: the analysis underestimates the fill of 3-D fronts; seen on 3-D Hertz on
// two ranks), MUMPS's own remedy: ICNTL(14) doubled from 40 % and the factor made again (PETSc's
// interface refuses a second numerical factorization after a failed one), at most four times.
void factorize_by_mumps(MPI_Comm ranks, Mat a, const std::vector<int>& trailing, Mat* f) {
  // (a user's -mat_mumps_icntl_14 overrides ours in every attempt: no retry then)
  PetscBool user_workspace = PETSC_FALSE;
  HPC_PETSC_CALL(PetscOptionsHasName(nullptr, nullptr, "-mat_mumps_icntl_14", &user_workspace));
  PetscInt extra_workspace = 0;
  for (int attempt = 0; attempt < 5; ++attempt) {
    const PetscInt infog1 = try_mumps_factor(ranks, a, trailing, extra_workspace, f);
    if ((infog1 != -8 && infog1 != -9 && infog1 != -17) || attempt == 4 || user_workspace) return;
    HPC_PETSC_CALL(MatDestroy(f));
    extra_workspace = extra_workspace == 0 ? 40 : 2 * extra_workspace;
  }
}

// What MUMPS's error code INFOG(1) means for the user.
const char* mumps_failure_meaning(PetscInt infog1) {
  if (infog1 == -10 || infog1 == -40) return "the matrix is not positive definite, or singular";
  if (infog1 == -6) return "the matrix is singular";
  if (infog1 == -8 || infog1 == -9 || infog1 == -14 || infog1 == -15 || infog1 == -17)
    return "its workspace was too small: raise -mat_mumps_icntl_14 (percent of extra space; the value used is "
           "ICNTL(14) above), or run on more ranks";
  if (infog1 == -13) return "out of memory";
  if (infog1 == -38)
    return "parallel analysis (-mat_mumps_icntl_28 2) needs PT-Scotch or ParMETIS, which this MUMPS lacks";
  if (infog1 == -39)
    return "options MUMPS cannot combine, e.g. parallel analysis (-mat_mumps_icntl_28 2) with a Schur complement";
  return "see MUMPS's manual for INFOG(1)";
}

// @throws NumericalError if MUMPS's factorization `f` of the n × n matrix failed or met a
// negative or null pivot (the same on every rank).
void check_mumps_factor(Mat f, int n) {
  MatFactorError error = MAT_FACTOR_NOERROR;
  HPC_PETSC_CALL(MatFactorGetError(f, &error));
  if (error != MAT_FACTOR_NOERROR) {
    PetscInt infog1 = 0, infog2 = 0;
    HPC_PETSC_CALL(MatMumpsGetInfog(f, 1, &infog1));
    HPC_PETSC_CALL(MatMumpsGetInfog(f, 2, &infog2));
    PetscInt extra_workspace = 0;
    HPC_PETSC_CALL(MatMumpsGetIcntl(f, 14, &extra_workspace));
    throw NumericalError(fmt::format(
        "MUMPS's factorization of a {0}x{0} matrix failed: INFOG(1) = {1}, INFOG(2) = {2}, ICNTL(14) = {3} ({4})", n,
        infog1, infog2, extra_workspace, mumps_failure_meaning(infog1)));
  }
  // MUMPS's LDLᵀ runs to the end over negative and null pivots and only counts them (INFOG(12) and
  // INFOG(28), the same on every rank). With a Schur set the root front is S_T itself, not
  // factorized by ScaLAPACK, so the counts cover all of A_II; S_T's own Cholesky checks the rest.
  for (const auto& [infog, kind, meaning] : {std::tuple{12, "negative", "not positive definite"},
                                             std::tuple{28, "null", "singular, not positive definite"}}) {
    PetscInt count = 0;
    HPC_PETSC_CALL(MatMumpsGetInfog(f, infog, &count));
    if (count > 0)
      throw NumericalError(
          fmt::format("MUMPS's factorization of a {0}x{0} matrix met {1} {2} pivot{3}: the matrix is {4}", n, count,
                      kind, count > 1 ? "s" : "", meaning));
  }
}

}  // namespace

DistributedCholesky::DistributedCholesky(MPI_Comm ranks, int n,
                                         const std::vector<Eigen::Triplet<double>>& lower_entries,
                                         const std::vector<int>& trailing)
    : impl_(std::make_unique<Impl>()), ranks_(ranks), size_(n) {
  impl_->trailing = trailing;
  impl_->trailing_position = trailing_positions(n, trailing);
  {
    CooEntries entries = both_triangles(n, lower_entries);
    assemble_matrix(ranks, n, entries, !trailing.empty(), impl_->matrix.out());
    HPC_PETSC_CALL(MatGetOwnershipRange(impl_->matrix.get(), &impl_->row_begin, &impl_->row_end));
    impl_->exchange.emplace(ranks, n, impl_->row_begin, impl_->row_end, touched_unknowns(entries.rows));
  }
  factorize_by_mumps(ranks, impl_->matrix.get(), trailing, impl_->factor.out());
  check_mumps_factor(impl_->factor.get(), n);
  if (!trailing.empty()) {
    // Solves on the interior problem A_II only (MUMPS's ICNTL(26) = 0); S_T is solved here.
    HPC_PETSC_CALL(MatMumpsSetIcntl(impl_->factor.get(), 26, 0));
    impl_->trailing_schur.compute(
        replicated_trailing_schur(ranks, impl_->factor.get(), static_cast<int>(trailing.size())));
    if (impl_->trailing_schur.info() != Eigen::Success)
      throw NumericalError("distributed Cholesky (MUMPS): the Schur complement on the " +
                           std::to_string(trailing.size()) + " trailing unknowns is not positive definite");
  }
}

DistributedCholesky::~DistributedCholesky() {
  // MUMPS's destruction (JOB = -2) is collective on the ranks: a rank unwinding from a failure of
  // its own would wait there for ranks that never come, before the failure can end the job. While
  // an exception unwinds, the factor is left to the end of the run (which the failure ends).
  if (impl_ && std::uncaught_exceptions() > 0 && rank_and_size(ranks_).second > 1) (void)impl_.release();
}
DistributedCholesky::DistributedCholesky(DistributedCholesky&&) noexcept = default;
DistributedCholesky& DistributedCholesky::operator=(DistributedCholesky&&) noexcept = default;

int DistributedCholesky::trailing_size() const { return static_cast<int>(impl_->trailing.size()); }

const std::vector<int>& DistributedCholesky::local_unknowns() const { return impl_->exchange->local(); }

Eigen::MatrixXd DistributedCholesky::mumps_owned(const Eigen::MatrixXd& owned_rhs) const {
  const PetscInt owned = impl_->row_end - impl_->row_begin, k = static_cast<PetscInt>(owned_rhs.cols());
  HPC_VERIFY(owned_rhs.rows() == owned, "right-hand side of the wrong size");
  // Column-major local blocks: PETSc's dense layout (lda = owned rows).
  Eigen::MatrixXd local_rhs = owned_rhs, local_solution(owned, k);
  if (!impl_->trailing.empty()) {
    // PETSc's MatMatSolve refuses a parallel factor with a Schur set; MatSolve takes the interior
    // solve column by column.
    for (PetscInt j = 0; j < k; ++j) {
      PetscHandle<Vec, VecDestroy> b, x;
      HPC_PETSC_CALL(VecCreateMPIWithArray(ranks_, 1, owned, size_, local_rhs.col(j).data(), b.out()));
      HPC_PETSC_CALL(VecCreateMPIWithArray(ranks_, 1, owned, size_, local_solution.col(j).data(), x.out()));
      HPC_PETSC_CALL(MatSolve(impl_->factor.get(), b.get(), x.get()));
    }
    for (int t : impl_->trailing)
      if (t >= impl_->row_begin && t < impl_->row_end) local_solution.row(t - impl_->row_begin).setZero();
    return local_solution;
  }
  PetscHandle<Mat, MatDestroy> b, x;
  HPC_PETSC_CALL(MatCreateDense(ranks_, owned, PETSC_DECIDE, size_, k, local_rhs.data(), b.out()));
  HPC_PETSC_CALL(MatCreateDense(ranks_, owned, PETSC_DECIDE, size_, k, local_solution.data(), x.out()));
  HPC_PETSC_CALL(MatMatSolve(impl_->factor.get(), b.get(), x.get()));
  return local_solution;
}

Eigen::MatrixXd DistributedCholesky::multiply_owned(const Eigen::MatrixXd& owned_x) const {
  const PetscInt owned = impl_->row_end - impl_->row_begin;
  Eigen::MatrixXd x = owned_x, out(owned, owned_x.cols());
  for (Eigen::Index j = 0; j < x.cols(); ++j) {
    PetscHandle<Vec, VecDestroy> in, result;
    HPC_PETSC_CALL(VecCreateMPIWithArray(ranks_, 1, owned, size_, x.col(j).data(), in.out()));
    HPC_PETSC_CALL(VecCreateMPIWithArray(ranks_, 1, owned, size_, out.col(j).data(), result.out()));
    HPC_PETSC_CALL(MatMult(impl_->matrix.get(), in.get(), result.get()));
  }
  return out;
}

Eigen::MatrixXd DistributedCholesky::solve_owned(const Eigen::MatrixXd& owned_rhs) const {
  if (owned_rhs.cols() == 0) return Eigen::MatrixXd(owned_rhs.rows(), 0);  // (MUMPS refuses no columns)
  if (impl_->trailing.empty()) return mumps_owned(owned_rhs);
  // [A_II A_IT; A_TI A_TT] x = b: y = A_II⁻¹ b_I, S_T x_T = b_T − A_TI y, x_I = A_II⁻¹ (b_I − A_IT x_T).
  const auto& trailing = impl_->trailing;
  const auto begin = impl_->row_begin, end = impl_->row_end;
  const Eigen::MatrixXd residual = owned_rhs - multiply_owned(mumps_owned(owned_rhs));
  // The trailing rows (trace-sized) gathered from their owners onto every rank.
  Eigen::MatrixXd x_trailing = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(trailing.size()), owned_rhs.cols());
  for (std::size_t k = 0; k < trailing.size(); ++k)
    if (trailing[k] >= begin && trailing[k] < end) x_trailing.row(k) = residual.row(trailing[k] - begin);
  sum_over_ranks(ranks_, x_trailing.data(), x_trailing.size());
  x_trailing = impl_->trailing_schur.solve(x_trailing);
  Eigen::MatrixXd x_hat = Eigen::MatrixXd::Zero(owned_rhs.rows(), owned_rhs.cols());
  for (std::size_t k = 0; k < trailing.size(); ++k)
    if (trailing[k] >= begin && trailing[k] < end) x_hat.row(trailing[k] - begin) = x_trailing.row(k);
  return mumps_owned(owned_rhs - multiply_owned(x_hat)) + x_hat;
}

Eigen::MatrixXd DistributedCholesky::solve(const Eigen::MatrixXd& rhs) const {
  HPC_VERIFY(rhs.rows() == size_, "right-hand side of the wrong size");
  return solve_replicated(ranks_, static_cast<int>(impl_->row_begin), static_cast<int>(impl_->row_end), rhs,
                          [this](const Eigen::MatrixXd& owned) { return solve_owned(owned); });
}

Eigen::MatrixXd DistributedCholesky::solve_local(const Eigen::MatrixXd& partial_rhs) const {
  return impl_->exchange->owned_to_local(solve_owned(impl_->exchange->sum_to_owned(partial_rhs)));
}

Eigen::MatrixXd DistributedCholesky::schur_complement(const Coupling& b) const {
  HPC_VERIFY(b.cols() == size_, "B A⁻¹ Bᵀ: B has the wrong number of columns");
  if (!impl_->trailing.empty())
    // matrixLLT() holds L_T in its lower triangle, the only part read: no dense copy of L_T.
    return schur_complement_through_trailing(
        b, impl_->trailing_schur.matrixLLT(), [this](int j) { return impl_->trailing_position.find(j); },
        [this](const Eigen::MatrixXd& rhs) { return solve(rhs); });
  const auto m = b.rows();
  const PetscInt owned = impl_->row_end - impl_->row_begin;
  const auto b_owned = squeezed<Coupling>(b.middleCols(impl_->row_begin, owned));
  const auto bt_owned = squeezed<Eigen::SparseMatrix<double>>(b_owned.transpose());
  Eigen::MatrixXd result = Eigen::MatrixXd::Zero(m, m);
  constexpr Eigen::Index block = 64;
  for (Eigen::Index first = 0; first < m; first += block) {
    const auto count = std::min<Eigen::Index>(block, m - first);
    result.middleCols(first, count) = b_owned * mumps_owned(Eigen::MatrixXd(bt_owned.middleCols(first, count)));
  }
  sum_over_ranks(ranks_, result.data(), result.size());
  return 0.5 * (result + result.transpose());
}

}  // namespace hpcontact::linalg
