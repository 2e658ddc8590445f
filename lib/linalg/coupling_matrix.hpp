// The storage of a coupling B between the multipliers on Γ_C and a primal space: shape (m, n), m
// trace-sized, n the primal space's length, nonzero only in the trace's columns. Stored by rows, its
// index arrays are trace-sized; stored by columns it carried n + 1 column pointers (4 MB per 1e6
// dofs) on every rank holding a copy.
#pragma once

#include <Eigen/SparseCore>
#include <vector>

namespace hpcontact::linalg {

using Coupling = Eigen::SparseMatrix<double, Eigen::RowMajor>;

/// `matrix` (a block of B, or Bᵀ by columns) stored with its non-zeros only: Eigen's sparse
/// assignments reserve up to 2 max(rows, cols) entries, 24 MB at 1e6 columns for a few thousand
/// non-zeros.
template <class Matrix>
Matrix squeezed(Matrix matrix) {
  matrix.data().squeeze();
  return matrix;
}

/// The columns of B that hold a nonzero: the trailing set that makes B A⁻¹ Bᵀ cheap.
inline std::vector<int> nonzero_columns(const Coupling& b) {
  std::vector<char> used(b.cols(), 0);
  for (int row = 0; row < b.outerSize(); ++row)
    for (Coupling::InnerIterator it(b, row); it; ++it)
      if (it.value() != 0.0) used[it.col()] = 1;
  std::vector<int> out;
  for (int j = 0; j < static_cast<int>(b.cols()); ++j)
    if (used[j]) out.push_back(j);
  return out;
}

}  // namespace hpcontact::linalg
