// Factorization of A = a K + b M on S^p(T_h) by static condensation: every cell's interior modes
// are eliminated cell by cell, and the Schur complement on the skeleton (vertex and edge dofs) is
// factorized by CHOLMOD, optionally with a trailing set (the Γ_C trace) last.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "linalg/sparse_cholesky.hpp"
#include "space/h1_space.hpp"

namespace hpcontact::assembly {

/// With the skeleton dofs s first and the interior modes i last (H1Space numbers them so),
///
///     [A_ss A_si] [u_s]   [f_s]      S u_s = f_s − A_si A_ii⁻¹ f_i,   S = A_ss − A_si A_ii⁻¹ A_is,
///     [A_is A_ii] [u_i] = [f_i]  ⇔   u_i = A_ii⁻¹ (f_i − A_is u_s).
///
/// A_ii is block diagonal, one block of (p_T − 1)² modes per cell, so S is assembled from element
/// Schur complements S_T and never needs A itself: (4p)² entries per cell instead of (p + 1)⁴.
/// Parallelogram cells with equal Jacobian and degrees share their elimination (uniform meshes
/// eliminate one cell). Since a trace coupling B has no interior columns, B A⁻¹ Bᵀ = B_s S⁻¹ B_sᵀ:
/// the Steklov–Poincaré condensation of SparseCholesky applies to S unchanged.
class CondensedFactor {
 public:
  /// `trailing`: dofs (skeleton dofs only) ordered last in the factorization of S.
  /// @throws NumericalError if A is not positive definite.
  CondensedFactor(const space::H1Space& space, double stiffness_weight, double mass_weight,
                  const std::vector<int>& trailing = {});
  ~CondensedFactor();
  CondensedFactor(CondensedFactor&&) noexcept;
  CondensedFactor& operator=(CondensedFactor&&) noexcept;

  /// Number of unknowns of A: space.n_dofs().
  int size() const { return size_; }
  int n_skeleton() const { return skeleton_.size(); }
  int n_trailing() const { return skeleton_.n_trailing(); }
  /// Distinct interior eliminations: 1 on a uniform mesh of one degree, n_cells on a general mesh.
  int n_eliminations() const { return static_cast<int>(blocks_.size()); }
  /// Nonzeros of the skeleton factor plus those of the distinct interior factors.
  long long factor_nonzeros() const;

  /// A⁻¹ rhs, shape (n) or (n, k).
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const;
  Eigen::MatrixXd solve(const Eigen::MatrixXd& rhs) const;
  /// B A⁻¹ Bᵀ, dense symmetric (m, m), for B of shape (m, n): on the skeleton factor's trailing
  /// block when B has no interior columns (any trace coupling), otherwise by solves.
  Eigen::MatrixXd schur_complement(const Eigen::SparseMatrix<double>& b) const;
  /// uᵀ A u, cell by cell from the eliminated blocks (a sum of non-negative terms, so as accurate
  /// as u itself), without A.
  double quadratic_form(const Eigen::VectorXd& u) const;

 private:
  struct CellBlock;
  /// Fills blocks_ and block_of_cell_; returns the lower triangle of S.
  Eigen::SparseMatrix<double> eliminate_interiors(double stiffness_weight, double mass_weight);
  static const std::vector<int>& checked_trailing(const space::H1Space& space, const std::vector<int>& trailing);
  /// f_s − A_si A_ii⁻¹ f_i, shape (n_skeleton, k).
  Eigen::MatrixXd condense(const Eigen::MatrixXd& rhs) const;

  const space::H1Space* space_;
  int size_ = 0;
  std::vector<std::unique_ptr<CellBlock>> blocks_;
  std::vector<int> block_of_cell_;
  linalg::SparseCholesky skeleton_;
};

}  // namespace hpcontact::assembly
