// Sparse matrices stacked on top of each other, [A; B] (the normal and tangential couplings of
// the elastic problems).
#pragma once

#include <Eigen/SparseCore>
#include <vector>

#include "linalg/coupling_matrix.hpp"

namespace hpcontact::linalg {

/// [a; b], shape (a.rows() + b.rows(), a.cols()). @pre a.cols() == b.cols().
inline Coupling stack_rows(const Coupling& a, const Coupling& b) {
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(static_cast<std::size_t>(a.nonZeros() + b.nonZeros()));
  for (const auto* part : {&a, &b}) {
    const Eigen::Index first = part == &a ? 0 : a.rows();
    for (int k = 0; k < part->outerSize(); ++k)
      for (Coupling::InnerIterator it(*part, k); it; ++it)
        triplets.emplace_back(first + it.row(), it.col(), it.value());
  }
  Coupling out(a.rows() + b.rows(), a.cols());
  out.setFromTriplets(triplets.begin(), triplets.end());
  return out;
}

}  // namespace hpcontact::linalg
