// smallest_on_products_ladder.
#include "infsup/surface_products_ladder.hpp"

#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <optional>

#include "core/error.hpp"
#include "core/timer.hpp"
#include "infsup/products_eigen.hpp"
#include "norms/surface_gram_products.hpp"
#include "norms/surface_interpolation_gram.hpp"

namespace hpcontact::infsup {

namespace {

/// x ↦ Rᵀ diag(A, …, A) R x for an operator A on one copy of the multipliers (A and R must
/// outlive the product).
template <class Operator>
PencilProducts::Product restricted_copies(const Operator& a, const Eigen::SparseMatrix<double>& basis, int copies,
                                          Eigen::Index n) {
  return [&a, &basis, copies, n](const Eigen::VectorXd& x) {
    const Eigen::VectorXd full = basis * x;
    Eigen::VectorXd out(full.size());
    for (int k = 0; k < copies; ++k) out.segment(k * n, n) = a(Eigen::VectorXd(full.segment(k * n, n)));
    return Eigen::VectorXd(basis.transpose() * out);
  };
}
template <class Operator>
PencilProducts::Product restricted_copies(const Operator&&, const Eigen::SparseMatrix<double>&, int,
                                          Eigen::Index) = delete;

}  // namespace

LadderSolution smallest_on_products_ladder(const contact::TraceOperator& s, const Eigen::SparseMatrix<double>& basis,
                                           int gram_copies, const space::SurfaceMultiplierSpace& multipliers,
                                           double tolerance) {
  const Eigen::Index n = multipliers.n_dofs();
  const norms::SurfaceGramPreconditioner preconditioner(multipliers);
  PencilProducts pencil;
  pencil.size = basis.cols();
  pencil.s = [&s, &basis](const Eigen::VectorXd& x) { return Eigen::VectorXd(basis.transpose() * s(basis * x)); };
  pencil.preconditioner = restricted_copies(preconditioner, basis, gram_copies, n);
  std::optional<RitzEstimate> estimate;
  auto coarse = std::make_unique<norms::SurfaceGramProducts>(multipliers, norms::surface_gram_modes(multipliers, 0));
  LadderSolution out;
  for (int level = 1;; ++level) {
    Stopwatch eigen_clock;
    auto fine =
        std::make_unique<norms::SurfaceGramProducts>(multipliers, norms::surface_gram_modes(multipliers, level));
    pencil.g = restricted_copies(*fine, basis, gram_copies, n);
    // (λ_max and ‖G‖, scales, from the first level: the levels' G differ by less than their few digits)
    if (!estimate) estimate = krylov_ritz_estimate(pencil);
    out.pair = smallest_eigenpair_products(pencil, *estimate, out.pair.eigenvector);
    out.lambda_min = std::max(out.pair.eigenvalue, 0.0);
    out.alpha = std::sqrt(out.lambda_min);
    const Eigen::VectorXd& x = out.pair.eigenvector;  // G_ℓ-normalized
    const double coarse_norm = x.dot(restricted_copies(*coarse, basis, gram_copies, n)(x));
    if (!(coarse_norm > 0.0))
      throw NumericalError(
          fmt::format("α by products: xᵀ G x = {:.3e} on level {} of the ladder", coarse_norm, level - 1));
    out.alpha_error = out.alpha * std::abs(std::sqrt(1.0 / coarse_norm) - 1.0);
    out.reference_level = level;
    out.alpha_converged = out.alpha_error <= tolerance * out.alpha;
    out.seconds_eigen += eigen_clock.seconds();
    if (out.alpha_converged || level == norms::kSurfaceGramTopLevel) return out;
    coarse = std::move(fine);
  }
}

}  // namespace hpcontact::infsup
