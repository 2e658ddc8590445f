// Dense Schur complements B A⁻¹ Bᵀ of a factorized sparse SPD matrix A, the form shared by the
// inf-sup matrix S_G, the extension-norm Gram matrix and the contact dual problem.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "linalg/sparse_cholesky.hpp"

namespace hpcontact::linalg {

/// B A⁻¹ Bᵀ for B of shape (m, n), A of size n (factorized). Solves in blocks of columns so that
/// memory stays at n × block doubles. Returns a dense symmetric (m, m) matrix (symmetrized).
Eigen::MatrixXd schur_complement(const SparseCholesky& a, const Eigen::SparseMatrix<double>& b,
                                 int block = 64);

}  // namespace hpcontact::linalg
