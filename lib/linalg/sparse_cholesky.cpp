// SparseCholesky on CHOLMOD's C interface (supernodal LLᵀ, interior-first AMD ordering for a trailing
// set, the trailing block read straight out of the supernodes). CHOLMOD's headers stay in here.
#include "linalg/sparse_cholesky.hpp"

#include <cholmod.h>
#include <fmt/format.h>

#include <algorithm>
#include <numeric>

#include "core/error.hpp"
#include "core/memory_limit.hpp"
#include "linalg/schur_complement.hpp"

namespace hpcontact::linalg {

struct SparseCholesky::Impl {
  cholmod_common common;
  cholmod_factor* factor = nullptr;
  /// The trailing block L_tt of the factor (dense, lower triangular) and, for every original
  /// index, its position in that block (−1 outside).
  Eigen::MatrixXd trailing_factor;
  std::vector<int> trailing_position;
  int n_trailing = 0;

  Impl() {
    cholmod_start(&common);
    common.print = 0;  // failures are reported by status, in the exception's message
  }
  ~Impl() {
    if (factor) cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
};

namespace {

// A failed CHOLMOD step: out of memory names the memory limit; a factor too large for CHOLMOD's
// 32-bit indices, and any other status, is a numerical failure.
[[noreturn]] void throw_cholmod_failure(const char* step, int status, long long size) {
  if (status == CHOLMOD_OUT_OF_MEMORY)
    throw OutOfMemory(out_of_memory_message(fmt::format("in CHOLMOD's {} of a {}x{} matrix", step, size, size)));
  if (status == CHOLMOD_TOO_LARGE)
    throw NumericalError(
        fmt::format("CHOLMOD's {} of a {}x{} matrix: its factor has more entries than 32-bit "
                    "indices count (2^31): use fewer cells or a lower p, or distribute the run",
                    step, size, size));
  throw NumericalError(fmt::format("CHOLMOD {} failed on a {}x{} matrix, status {}", step, size, size, status));
}

// A CHOLMOD view (no copy) of a compressed Eigen matrix, as symmetric with its lower triangle
// stored (CHOLMOD ignores the upper one).
cholmod_sparse view_lower(Eigen::SparseMatrix<double>& lower) {
  HPC_VERIFY(lower.isCompressed(), "CHOLMOD view of an uncompressed matrix");
  cholmod_sparse a{};
  a.nrow = static_cast<std::size_t>(lower.rows());
  a.ncol = static_cast<std::size_t>(lower.cols());
  a.nzmax = static_cast<std::size_t>(lower.nonZeros());
  a.p = lower.outerIndexPtr();
  a.i = lower.innerIndexPtr();
  a.x = lower.valuePtr();
  a.stype = -1;  // symmetric, lower triangle stored
  a.itype = CHOLMOD_INT;
  a.xtype = CHOLMOD_REAL;
  a.dtype = CHOLMOD_DOUBLE;
  a.sorted = 1;  // Eigen keeps the row indices of each column sorted
  a.packed = 1;
  return a;
}

cholmod_dense view_dense(Eigen::MatrixXd& matrix) {
  cholmod_dense d{};
  d.nrow = static_cast<std::size_t>(matrix.rows());
  d.ncol = static_cast<std::size_t>(matrix.cols());
  d.nzmax = d.nrow * d.ncol;
  d.d = d.nrow;
  d.x = matrix.data();
  d.xtype = CHOLMOD_REAL;
  d.dtype = CHOLMOD_DOUBLE;
  return d;
}

// The ordering (AMD or METIS) of the block of A outside `trailing`, followed by `trailing` (in index order).
// The interior block's lower triangle is built in one pass: the index map is monotone, so columns
// and rows stay sorted.
std::vector<int> interior_first_ordering(const Eigen::SparseMatrix<double>& a, const std::vector<int>& trailing,
                                         FillOrdering ordering, cholmod_common& c) {
  const int n = static_cast<int>(a.rows());
  std::vector<int> position(n, 0);
  for (int index : trailing) {
    HPC_VERIFY(index >= 0 && index < n, "trailing index out of range");
    position[index] = -1;
  }
  std::vector<int> interior;
  for (int j = 0; j < n; ++j)
    if (position[j] == 0) position[j] = static_cast<int>(interior.size()), interior.push_back(j);
  const auto n_interior = static_cast<int>(interior.size());
  std::vector<int> column_start(n_interior + 1, 0), rows;
  std::vector<double> values;
  rows.reserve(a.nonZeros() / 2 + n);
  values.reserve(a.nonZeros() / 2 + n);
  for (int k = 0; k < n_interior; ++k) {
    const int col = interior[k];
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, col); it; ++it)
      if (it.row() >= col && position[it.row()] >= 0) {
        rows.push_back(position[it.row()]);
        values.push_back(it.value());
      }
    column_start[k + 1] = static_cast<int>(rows.size());
  }
  cholmod_sparse block{};
  block.nrow = block.ncol = static_cast<std::size_t>(n_interior);
  block.nzmax = rows.size();
  block.p = column_start.data();
  block.i = rows.data();
  block.x = values.data();
  block.stype = -1;
  block.itype = CHOLMOD_INT;
  block.xtype = CHOLMOD_REAL;
  block.dtype = CHOLMOD_DOUBLE;
  block.sorted = 1;
  block.packed = 1;
  std::vector<int> order(n_interior);
  if (ordering == FillOrdering::nested_dissection) {
    // (postordered, as AMD's order is)
    if (!cholmod_metis(&block, nullptr, 0, 1, order.data(), &c))
      throw_cholmod_failure("METIS ordering", c.status, n_interior);
  } else if (!cholmod_amd(&block, nullptr, 0, order.data(), &c)) {
    throw_cholmod_failure("AMD ordering", c.status, n_interior);
  }
  std::vector<int> permutation;
  permutation.reserve(n);
  for (int k : order) permutation.push_back(interior[k]);
  for (int j = 0; j < n; ++j)
    if (position[j] < 0) permutation.push_back(j);
  return permutation;
}

}  // namespace

SparseCholesky::SparseCholesky(const Eigen::SparseMatrix<double>& matrix, const std::vector<int>& trailing,
                               FillOrdering ordering)
    : impl_(std::make_unique<Impl>()), size_(static_cast<int>(matrix.rows())), all_unknowns_(size_) {
  HPC_VERIFY(matrix.rows() == matrix.cols(), "Cholesky of a non-square matrix");
  std::iota(all_unknowns_.begin(), all_unknowns_.end(), 0);
  // CHOLMOD reads only the lower triangle of a matrix marked symmetric-lower, so the whole matrix
  // is handed over without a copy when it is compressed (CHOLMOD does not write to it).
  Eigen::SparseMatrix<double> compressed;
  const Eigen::SparseMatrix<double>* source = &matrix;
  if (!matrix.isCompressed()) {
    compressed = matrix;
    compressed.makeCompressed();
    source = &compressed;
  }
  cholmod_sparse a = view_lower(const_cast<Eigen::SparseMatrix<double>&>(*source));
  cholmod_common& c = impl_->common;
  c.supernodal = CHOLMOD_SUPERNODAL;
  std::vector<int> permutation;
  if (!trailing.empty() && static_cast<int>(trailing.size()) < size_) {
    // AMD on the interior block alone, the trailing unknowns appended. (Constrained AMD on the
    // whole matrix factorized 30 % slower at 1e6 dofs; METIS cost more than it saved.)
    // No postordering: it would move unknowns past the trailing set whenever the trailing set is
    // not connected through the interior (a rank's part in SubstructuredCholesky), and AMD's
    // order is postordered already (1e6 dofs: the factorization takes the same time).
    permutation = interior_first_ordering(*source, trailing, ordering, c);
    c.nmethods = 1;
    c.method[0].ordering = CHOLMOD_GIVEN;
    c.postorder = 0;
  } else {
    // AMD alone: CHOLMOD's default also tries METIS when AMD's fill is high, which on the 2D
    // finite element matrices here costs more time than its smaller factor saves (1e6 dofs of
    // degree 4, condensed: 10.2 s against 7.1 s).
    c.nmethods = 1;
    c.method[0].ordering = ordering == FillOrdering::nested_dissection ? CHOLMOD_METIS : CHOLMOD_AMD;
  }
  impl_->factor = cholmod_analyze_p(&a, permutation.empty() ? nullptr : permutation.data(), nullptr, 0, &c);
  if (!impl_->factor) throw_cholmod_failure("analysis", c.status, size_);
  cholmod_factorize(&a, impl_->factor, &c);
  if (c.status == CHOLMOD_NOT_POSDEF || impl_->factor->minor < impl_->factor->n)
    throw NumericalError(
        fmt::format("sparse Cholesky (CHOLMOD) failed on a {0}x{0} matrix: not positive definite at column {1} "
                    "(is Γ_D empty or a cell degenerate?)",
                    size_, impl_->factor->minor));
  if (c.status < CHOLMOD_OK) throw_cholmod_failure("factorization", c.status, size_);

  if (permutation.empty()) return;
  // The trailing block, from the supernodes whose columns lie in it. Supernode s holds columns
  // super[s] .. super[s+1]-1 as a dense column-major block over the rows s_rows[pi[s] .. pi[s+1]-1].
  const int n_t = static_cast<int>(trailing.size()), offset = size_ - n_t;
  const int* perm = static_cast<const int*>(impl_->factor->Perm);
  impl_->trailing_position.assign(size_, -1);
  for (int k = offset; k < size_; ++k) impl_->trailing_position[perm[k]] = k - offset;
  for (int index : trailing)
    HPC_VERIFY(impl_->trailing_position[index] >= 0, "the factorization did not keep the trailing set last");
  const auto* factor = impl_->factor;
  const int* super = static_cast<const int*>(factor->super);
  const int* pi = static_cast<const int*>(factor->pi);
  const int* px = static_cast<const int*>(factor->px);
  const int* rows = static_cast<const int*>(factor->s);
  const double* values = static_cast<const double*>(factor->x);
  impl_->trailing_factor = Eigen::MatrixXd::Zero(n_t, n_t);
  for (std::size_t s = 0; s < factor->nsuper; ++s) {
    const int first = super[s], last = super[s + 1];
    if (last <= offset) continue;
    const int n_rows = pi[s + 1] - pi[s];
    for (int j = std::max(first, offset); j < last; ++j)
      for (int r = 0; r < n_rows; ++r) {
        const int i = rows[pi[s] + r];
        if (i >= j) impl_->trailing_factor(i - offset, j - offset) = values[px[s] + r + (j - first) * n_rows];
      }
  }
  impl_->n_trailing = n_t;
}

SparseCholesky::~SparseCholesky() = default;
SparseCholesky::SparseCholesky(SparseCholesky&&) noexcept = default;
SparseCholesky& SparseCholesky::operator=(SparseCholesky&&) noexcept = default;

int SparseCholesky::n_trailing() const { return impl_->n_trailing; }
const Eigen::MatrixXd& SparseCholesky::trailing_factor() const { return impl_->trailing_factor; }
const std::vector<int>& SparseCholesky::trailing_position() const { return impl_->trailing_position; }

long long SparseCholesky::factor_nonzeros() const {
  const auto* factor = impl_->factor;
  if (!factor->is_super) return static_cast<long long>(factor->nzmax);
  // Supernodal: the lower trapezoid of every supernode's block.
  long long count = 0;
  const int* super = static_cast<const int*>(factor->super);
  const int* pi = static_cast<const int*>(factor->pi);
  for (std::size_t s = 0; s < factor->nsuper; ++s) {
    const long long columns = super[s + 1] - super[s], rows = pi[s + 1] - pi[s];
    count += columns * rows - columns * (columns - 1) / 2;
  }
  return count;
}

Eigen::MatrixXd SparseCholesky::solve(const Eigen::MatrixXd& rhs) const {
  HPC_VERIFY(rhs.rows() == size_, "right-hand side of the wrong size");
  if (rhs.cols() == 0) return rhs;
  Eigen::MatrixXd copy = rhs;
  cholmod_dense b = view_dense(copy);
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, impl_->factor, &b, &impl_->common);
  if (!x) throw_cholmod_failure("solve", impl_->common.status, size_);
  Eigen::MatrixXd out = Eigen::Map<const Eigen::MatrixXd>(static_cast<const double*>(x->x), size_, rhs.cols());
  cholmod_free_dense(&x, &impl_->common);
  return out;
}

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& rhs) const { return solve(Eigen::MatrixXd(rhs)).col(0); }

Eigen::MatrixXd SparseCholesky::schur_complement(const Coupling& b) const {
  HPC_VERIFY(b.cols() == size_, "B A⁻¹ Bᵀ: B has the wrong number of columns");
  return schur_complement_through_trailing(
      b, impl_->trailing_factor, [this](int j) { return impl_->trailing_position[j]; },
      [this](const Eigen::MatrixXd& rhs) { return solve(rhs); });
}

}  // namespace hpcontact::linalg
