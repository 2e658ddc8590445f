// The condensed contact operator S = B K⁻¹ Bᵀ as products only: each product one solve with K's
// factor, S never formed. The dense path (S from the factor's trailing block) costs |Γ_C|
// multipliers squared in memory and their cube in time; this one costs a solve per product.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <functional>
#include <utility>

namespace hpcontact::contact {

/// x ↦ S x for a symmetric positive semi-definite S of `size` rows; `products` counts the calls.
class TraceOperator {
 public:
  using Product = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;
  TraceOperator(Eigen::Index size, Product product) : size_(size), product_(std::move(product)) {}
  /// A dense S (tests, and the dense path's callers of the product solvers).
  /// (The operator refers to `s`, which must outlive it.)
  static TraceOperator dense(const Eigen::MatrixXd& s) {
    return {s.rows(), [&s](const Eigen::VectorXd& x) { return Eigen::VectorXd(s * x); }};
  }
  static TraceOperator dense(Eigen::MatrixXd&&) = delete;

  Eigen::Index size() const { return size_; }
  /// S x, shape (size).
  Eigen::VectorXd operator()(const Eigen::VectorXd& x) const {
    ++products_;
    return product_(x);
  }
  long products() const { return products_; }

 private:
  Eigen::Index size_;
  Product product_;
  mutable long products_ = 0;
};

/// How a 3-D solve applies S: formed densely from the factor's trailing block, or by products; or
/// (`saddle_point`, frictionless contact on an iterative K) not at all: a primal–dual active set on
/// the saddle point whose steps are K's conjugate gradients projected onto the active constraints
/// (contact/active_set_contact.hpp).
enum class SchurPath { automatic, dense, products, saddle_point };

/// `automatic` takes products where they are measured to cost less: above a quarter of
/// n_unknowns^{2/3} multipliers, on K of 1e4 unknowns and more (below, either path takes well
/// under a second, and the dense one gives the exact active set). The dense path's extra work grows with the
/// multipliers' cube (the trailing block, the active-set steps), the products' with the factor's size; on cubes of p =
/// 2 the two cost the same at 144 multipliers and 1.5e4 unknowns, 576 and 1.1e5 (docs/three_d.md, "S by products"), and
/// the rule puts 3-D Hertz (144 and 1.9e5) on the dense path.
inline bool uses_products(SchurPath path, Eigen::Index multipliers, Eigen::Index unknowns) {
  if (path != SchurPath::automatic) return path == SchurPath::products;
  return unknowns >= 10000 &&
         static_cast<double>(multipliers) > 0.25 * std::cbrt(static_cast<double>(unknowns) * unknowns);
}

/// An estimate of λ_max(S) from above: `steps` ≥ 1 Lanczos steps from a fixed vector with every
/// component, the largest Ritz value θ plus the norm of its residual. θ ≤ λ_max always; the
/// residual covers the distance to the nearest eigenvalue, which is λ_max once θ has converged to
/// it (S's top mode is smooth and well separated on a trace), not a guarantee. Zero for S = 0.
double largest_eigenvalue_bound(const TraceOperator& s, int steps = 30);

}  // namespace hpcontact::contact
