// B A⁻¹ Bᵀ from a factorization with a trailing set: the one mechanism behind SparseCholesky's and
// SubstructuredCholesky's schur_complement (through the trailing block, or by solves).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <vector>

#include "linalg/coupling_matrix.hpp"

namespace hpcontact::linalg {

/// B A⁻¹ Bᵀ, dense symmetric (m, m), for B of shape (m, n). `trailing_factor` is L_tt, the lower
/// triangular trailing block of a factor of A (L_tt L_ttᵀ the Schur complement onto the trailing
/// set), `trailing_position(j)` the row of L_tt of unknown j (−1 outside the set). When every
/// nonzero column of B lies in the set, B A⁻¹ Bᵀ = Wᵀ W with W = L_tt⁻¹ (B P_tᵀ)ᵀ; otherwise it
/// comes from `solve` (A⁻¹ on shape (n, k)) in blocks of 64 columns of Bᵀ.
Eigen::MatrixXd schur_complement_through_trailing(const Coupling& b,
                                                  const Eigen::Ref<const Eigen::MatrixXd>& trailing_factor,
                                                  const std::function<int(int)>& trailing_position,
                                                  const std::function<Eigen::MatrixXd(const Eigen::MatrixXd&)>& solve);

}  // namespace hpcontact::linalg
