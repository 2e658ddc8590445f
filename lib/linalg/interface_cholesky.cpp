// InterfaceCholesky: A_HH assembled from the ranks' blocks into a MATSCALAPACK matrix and
// factorized in place (pdpotrf); right-hand sides and Y move between row blocks (MATDENSE, the
// layout ScaLAPACK's conversions expect) and the 2D block-cyclic layout by MatConvert.
#include "linalg/interface_cholesky.hpp"

#include <fmt/format.h>
#include <petscmat.h>

#include <Eigen/Cholesky>
#include <algorithm>

#include "core/error.hpp"
#include "core/petsc_check.hpp"
#include "core/petsc_handle.hpp"
#include "core/petsc_session.hpp"

namespace hpcontact::linalg {

namespace {

using MatHandle = PetscHandle<Mat, MatDestroy>;

// PETSc 3.18's MATSCALAPACK wants equal local sizes on every rank (but the last): every dimension
// is padded to a multiple of the ranks (A_HH with unit diagonal entries, the others with zeros).
int padded(int n, int ranks) { return (n + ranks - 1) / ranks * ranks; }

// An n_rows × k MATDENSE in ScaLAPACK's row blocks (PetscSplitOwnershipEqual), unset.
MatHandle row_blocks(MPI_Comm ranks, PetscInt n_rows, PetscInt k) {
  MatHandle out;
  PetscInt local_rows = PETSC_DECIDE, local_cols = PETSC_DECIDE;
  HPC_PETSC_CALL(PetscSplitOwnershipEqual(ranks, &local_rows, &n_rows));
  HPC_PETSC_CALL(PetscSplitOwnershipEqual(ranks, &local_cols, &k));
  HPC_PETSC_CALL(MatCreate(ranks, out.out()));
  HPC_PETSC_CALL(MatSetSizes(out.get(), local_rows, local_cols, n_rows, k));
  HPC_PETSC_CALL(MatSetType(out.get(), MATDENSE));
  HPC_PETSC_CALL(MatSetUp(out.get()));
  return out;
}

// This rank's rows of a MATDENSE (all its columns).
Eigen::MatrixXd owned_rows(Mat dense) {
  PetscInt begin = 0, end = 0, cols = 0, lda = 0;
  HPC_PETSC_CALL(MatGetOwnershipRange(dense, &begin, &end));
  HPC_PETSC_CALL(MatGetSize(dense, nullptr, &cols));
  HPC_PETSC_CALL(MatDenseGetLDA(dense, &lda));
  const PetscScalar* values = nullptr;
  HPC_PETSC_CALL(MatDenseGetArrayRead(dense, &values));
  Eigen::MatrixXd out(end - begin, cols);
  for (PetscInt j = 0; j < cols; ++j)
    for (PetscInt i = 0; i < end - begin; ++i) out(i, j) = values[i + j * lda];
  HPC_PETSC_CALL(MatDenseRestoreArrayRead(dense, &values));
  return out;
}

// rows (this rank's row block of an n_rows × k matrix) into MATSCALAPACK.
MatHandle scalapack_from_rows(MPI_Comm ranks, PetscInt n_rows, const Eigen::MatrixXd& rows) {
  MatHandle dense = row_blocks(ranks, n_rows, rows.cols());
  PetscInt begin = 0, end = 0, lda = 0;
  HPC_PETSC_CALL(MatGetOwnershipRange(dense.get(), &begin, &end));
  HPC_VERIFY(end - begin == rows.rows(), "interface Cholesky: rows of another layout");
  HPC_PETSC_CALL(MatDenseGetLDA(dense.get(), &lda));
  PetscScalar* values = nullptr;
  HPC_PETSC_CALL(MatDenseGetArrayWrite(dense.get(), &values));
  for (Eigen::Index j = 0; j < rows.cols(); ++j)
    for (Eigen::Index i = 0; i < rows.rows(); ++i) values[i + j * lda] = rows(i, j);
  HPC_PETSC_CALL(MatDenseRestoreArrayWrite(dense.get(), &values));
  HPC_PETSC_CALL(MatAssemblyBegin(dense.get(), MAT_FINAL_ASSEMBLY));
  HPC_PETSC_CALL(MatAssemblyEnd(dense.get(), MAT_FINAL_ASSEMBLY));
  MatHandle out;
  HPC_PETSC_CALL(MatConvert(dense.get(), MATSCALAPACK, MAT_INITIAL_MATRIX, out.out()));
  return out;
}

// Adds `block` at rows `rows` and columns `cols` (interface positions shifted into the matrix).
void add_block(Mat matrix, const std::vector<PetscInt>& rows, const std::vector<PetscInt>& cols,
               const Eigen::MatrixXd& block) {
  if (rows.empty() || cols.empty()) return;
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> row_major = block;
  HPC_PETSC_CALL(MatSetValues(matrix, static_cast<PetscInt>(rows.size()), rows.data(),
                              static_cast<PetscInt>(cols.size()), cols.data(), row_major.data(), ADD_VALUES));
}

}  // namespace

struct InterfaceCholesky::Impl {
  int n_h = 0;             ///< |H|: the interface between the parts, without the trailing set
  int n_h_padded = 0;      ///< |H| padded to a multiple of the ranks
  MatHandle factor;        ///< A_HH, factorized in place (MATSCALAPACK)
  int row_begin = 0;       ///< this rank's row block of the padded H: its first row
  int row_count = 0;       ///< and its length
  Eigen::MatrixXd y_rows;  ///< this rank's rows of Y = A_HH⁻¹ A_HC (zero in the padding)

  /// A_HH⁻¹ x, x and the result as this rank's row block (row_count rows; the columns a multiple
  /// of the ranks). Collective on `ranks`.
  Eigen::MatrixXd solve_rows(MPI_Comm ranks, const Eigen::MatrixXd& rows) const {
    MatHandle x = scalapack_from_rows(ranks, n_h_padded, rows);
    MatHandle solution, solution_rows;
    HPC_PETSC_CALL(MatDuplicate(x.get(), MAT_DO_NOT_COPY_VALUES, solution.out()));
    HPC_PETSC_CALL(MatMatSolve(factor.get(), x.get(), solution.get()));
    HPC_PETSC_CALL(MatConvert(solution.get(), MATDENSE, MAT_INITIAL_MATRIX, solution_rows.out()));
    return owned_rows(solution_rows.get());
  }
};

InterfaceCholesky::InterfaceCholesky(MPI_Comm ranks, int n, int n_trailing, const std::vector<int>& positions,
                                     const Eigen::MatrixXd& block)
    : impl_(std::make_unique<Impl>()), ranks_(ranks), size_(n), n_trailing_(n_trailing) {
  HPC_VERIFY(0 <= n_trailing && n_trailing <= n && block.rows() == static_cast<Eigen::Index>(positions.size()) &&
                 block.cols() == block.rows(),
             "interface Cholesky: a block of another size than its positions");
  Impl& d = *impl_;
  d.n_h = n - n_trailing;
  const int m = n_trailing;
  // The rank's positions split into H and C, as indices of `block`.
  std::vector<int> in_h, in_c;
  std::vector<PetscInt> rows_h, rows_c;
  for (std::size_t k = 0; k < positions.size(); ++k) {
    HPC_VERIFY(positions[k] >= 0 && positions[k] < n, "interface Cholesky: a position outside the interface");
    if (positions[k] < d.n_h)
      in_h.push_back(static_cast<int>(k)), rows_h.push_back(positions[k]);
    else
      in_c.push_back(static_cast<int>(k)), rows_c.push_back(positions[k] - d.n_h);
  }
  Eigen::MatrixXd s_cc = Eigen::MatrixXd::Zero(m, m);
  for (std::size_t i = 0; i < in_c.size(); ++i)
    for (std::size_t j = 0; j < in_c.size(); ++j) s_cc(rows_c[i], rows_c[j]) += block(in_c[i], in_c[j]);
  sum_over_ranks(ranks, s_cc.data(), s_cc.size());
  const int ranks_count = rank_and_size(ranks).second;
  stored_entries_ = static_cast<double>(m) * m;  // L_CC
  if (d.n_h > 0) {
    HPC_VERIFY(ensure_petsc_initialized(), "interface Cholesky: PETSc is not initialized");
    const int rank = rank_and_size(ranks).first;
    d.n_h_padded = padded(d.n_h, ranks_count);
    d.row_count = d.n_h_padded / ranks_count;
    d.row_begin = rank * d.row_count;
    // A_HH over the ranks (ScaLAPACK's 2D blocks), factorized in place.
    HPC_PETSC_CALL(MatCreate(ranks, d.factor.out()));
    HPC_PETSC_CALL(MatSetSizes(d.factor.get(), d.row_count, d.row_count, d.n_h_padded, d.n_h_padded));
    HPC_PETSC_CALL(MatSetType(d.factor.get(), MATSCALAPACK));
    HPC_PETSC_CALL(MatSetUp(d.factor.get()));
    add_block(d.factor.get(), rows_h, rows_h, block(in_h, in_h));
    if (rank == 0)
      for (PetscInt i = d.n_h; i < d.n_h_padded; ++i)
        HPC_PETSC_CALL(MatSetValue(d.factor.get(), i, i, 1.0, ADD_VALUES));
    HPC_PETSC_CALL(MatAssemblyBegin(d.factor.get(), MAT_FINAL_ASSEMBLY));
    HPC_PETSC_CALL(MatAssemblyEnd(d.factor.get(), MAT_FINAL_ASSEMBLY));
    MatFactorInfo info;
    HPC_PETSC_CALL(MatFactorInfoInitialize(&info));
    try {
      HPC_PETSC_CALL(MatCholeskyFactor(d.factor.get(), nullptr, &info));
    } catch (const NumericalError& error) {
      throw NumericalError(fmt::format(
          "substructured Cholesky: the {0}x{0} interface problem between the parts is not positive definite ({1})",
          d.n_h, error.what()));
    }
    stored_entries_ += static_cast<double>(d.n_h_padded) * d.n_h_padded / ranks_count;
    if (m > 0) {
      // A_HC in row blocks, Y = A_HH⁻¹ A_HC, and S_CC = A_CC − A_HCᵀ Y summed over the row blocks.
      Eigen::MatrixXd coupling_rows;  // the sum of the ranks' blocks, this rank's row block
      {
        MatHandle coupling = row_blocks(ranks, d.n_h_padded, padded(m, ranks_count));
        add_block(coupling.get(), rows_h, rows_c, block(in_h, in_c));
        HPC_PETSC_CALL(MatAssemblyBegin(coupling.get(), MAT_FINAL_ASSEMBLY));
        HPC_PETSC_CALL(MatAssemblyEnd(coupling.get(), MAT_FINAL_ASSEMBLY));
        coupling_rows = owned_rows(coupling.get());
      }
      d.y_rows = d.solve_rows(ranks, coupling_rows).leftCols(m);
      HPC_VERIFY(d.y_rows.rows() == d.row_count, "interface Cholesky: rows of another layout");
      Eigen::MatrixXd product = coupling_rows.leftCols(m).transpose() * d.y_rows;
      sum_over_ranks(ranks, product.data(), product.size());
      s_cc -= product;
      stored_entries_ += static_cast<double>(d.y_rows.size());
    }
  }
  if (m > 0) {
    s_cc = 0.5 * (s_cc + s_cc.transpose());
    Eigen::LLT<Eigen::MatrixXd> llt(s_cc);
    if (llt.info() != Eigen::Success)
      throw NumericalError(fmt::format(
          "substructured Cholesky: the {0}x{0} interface problem is not positive definite on its trailing set", n));
    trailing_factor_ = llt.matrixL();
  }
}

InterfaceCholesky::~InterfaceCholesky() = default;
InterfaceCholesky::InterfaceCholesky(InterfaceCholesky&&) noexcept = default;
InterfaceCholesky& InterfaceCholesky::operator=(InterfaceCholesky&&) noexcept = default;

Eigen::MatrixXd InterfaceCholesky::solve(const Eigen::MatrixXd& rhs) const {
  HPC_VERIFY(rhs.rows() == size_, "interface Cholesky: right-hand side of the wrong size");
  const Impl& d = *impl_;
  const auto k = rhs.cols();
  if (k == 0) return Eigen::MatrixXd(size_, 0);
  const int m = n_trailing_;
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(size_, k);
  Eigen::MatrixXd y_local, c = rhs.bottomRows(m);
  if (d.n_h > 0) {
    // y = A_HH⁻¹ g, this rank's row block (g padded with zeros).
    const int ranks_count = rank_and_size(ranks_).second;
    Eigen::MatrixXd g = Eigen::MatrixXd::Zero(d.row_count, padded(static_cast<int>(k), ranks_count));
    const int rows_here = std::clamp(d.n_h - d.row_begin, 0, d.row_count);
    g.topLeftCorner(rows_here, k) = rhs.middleRows(std::min(d.row_begin, d.n_h), rows_here);
    y_local = d.solve_rows(ranks_, g).leftCols(k);
    if (m > 0) {
      Eigen::MatrixXd product = d.y_rows.transpose() * g.leftCols(k);  // Yᵀ g over this rank's rows
      sum_over_ranks(ranks_, product.data(), product.size());
      c -= product;
    }
  }
  if (m > 0) {
    trailing_factor_.triangularView<Eigen::Lower>().solveInPlace(c);
    trailing_factor_.triangularView<Eigen::Lower>().transpose().solveInPlace(c);
    out.bottomRows(m) = c;
  }
  if (d.n_h > 0) {
    // x_H = y − Y x_C in row blocks, then on every rank.
    if (m > 0) y_local -= d.y_rows * c;
    Eigen::MatrixXd x_h = Eigen::MatrixXd::Zero(d.n_h, k);
    const int rows_here = std::clamp(d.n_h - d.row_begin, 0, d.row_count);
    x_h.middleRows(std::min(d.row_begin, d.n_h), rows_here) = y_local.topRows(rows_here);
    sum_over_ranks(ranks_, x_h.data(), x_h.size());  // each row is one rank's
    out.topRows(d.n_h) = x_h;
  }
  return out;
}

}  // namespace hpcontact::linalg
