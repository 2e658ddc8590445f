// Legendre polynomials and the hierarchical integrated-Legendre (Lobatto) shape functions on
// [-1,1], the 1-D building blocks of the H¹-conforming tensor-product basis.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace hpcontact::basis {

/// Legendre polynomials P_0..P_n at t: shape (n+1).
Eigen::VectorXd legendre_values(int n, double t);

/// The p + 1 Gauss–Lobatto points of degree p ≥ 1 on [-1,1], ascending: ±1 and the roots of P_p'
/// (from the eigenvalues of the Jacobi matrix of the Jacobi polynomials P^{(1,1)}).
std::vector<double> gauss_lobatto_points(int p);

/// Lobatto shape functions up to degree p at t, shape (p+1):
///   N_0 = (1 - t)/2,  N_1 = (1 + t)/2,
///   N_k = (P_k - P_{k-2}) / sqrt(2(2k - 1)) = sqrt((2k-1)/2) ∫_{-1}^t P_{k-1},  k ≥ 2.
/// The bubbles N_k (k ≥ 2) vanish at ±1, have H¹₀-orthonormal derivatives
/// (∫ N_j' N_k' = δ_jk), and parity N_k(-t) = (-1)^k N_k(t), which is how edge orientation
/// is handled. Their conditioning grows only mildly with p (tested up to p = 16).
void lobatto_values(int p, double t, Eigen::Ref<Eigen::VectorXd> values, Eigen::Ref<Eigen::VectorXd> derivatives);

/// The q Chebyshev–Lobatto points −cos(πk/(q − 1)), k = 0 … q − 1, on [-1,1] (ascending), or the
/// midpoint for q = 1: the nodal and constraint points of the multipliers (the paper's Remark 3).
std::vector<double> chebyshev_lobatto_points(int q);

/// The Lagrange polynomials of `nodes` (distinct) at t: ℓ_i(t), shape (nodes.size()).
Eigen::VectorXd lagrange_values(const std::vector<double>& nodes, double t);

/// Tabulation at a set of points. Both outputs shape (n_points, p+1), row = point.
struct Tabulation1D {
  Eigen::MatrixXd values;
  Eigen::MatrixXd derivatives;
};
Tabulation1D tabulate_lobatto(int p, const std::vector<double>& points);

}  // namespace hpcontact::basis
