// The storage of a coupling B between the multipliers on Γ_C and a primal space: shape (m, n), m
// trace-sized, n the primal space's length, nonzero only in the trace's columns. Stored by rows, its
// index arrays are trace-sized; stored by columns it carried n + 1 column pointers (4 MB per 1e6
// dofs) on every rank holding a copy.
#pragma once

#include <Eigen/SparseCore>

namespace hpcontact::linalg {

using Coupling = Eigen::SparseMatrix<double, Eigen::RowMajor>;

}  // namespace hpcontact::linalg
