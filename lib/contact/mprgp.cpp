// MPRGP for the bound-constrained trace QP: CG, expansion and proportioning steps.
#include "contact/mprgp.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/error.hpp"

namespace hpcontact::contact {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

/// The box and the gradient splittings of Dostál's method at a point.
struct Box {
  const Eigen::VectorXd& lo;
  const Eigen::VectorXd& hi;

  bool is_free(const Eigen::VectorXd& x, Eigen::Index i) const { return lo(i) < x(i) && x(i) < hi(i); }
  /// φ: the gradient on the free set.
  Eigen::VectorXd free_gradient(const Eigen::VectorXd& x, const Eigen::VectorXd& g) const {
    Eigen::VectorXd out = Eigen::VectorXd::Zero(x.size());
    for (Eigen::Index i = 0; i < x.size(); ++i)
      if (is_free(x, i)) out(i) = g(i);
    return out;
  }
  /// β: the part of the gradient at an active bound that points into the box (a fixed unknown,
  /// lo = hi, has none).
  Eigen::VectorXd chopped_gradient(const Eigen::VectorXd& x, const Eigen::VectorXd& g) const {
    Eigen::VectorXd out = Eigen::VectorXd::Zero(x.size());
    for (Eigen::Index i = 0; i < x.size(); ++i) {
      const bool at_lower = x(i) <= lo(i), at_upper = x(i) >= hi(i);
      if (at_lower && !at_upper) out(i) = std::min(g(i), 0.0);
      if (at_upper && !at_lower) out(i) = std::max(g(i), 0.0);
    }
    return out;
  }
  /// φ̃_ᾱ · φ: the free gradient reduced so that a step of length ᾱ stays in the box, against φ.
  double reduced_dot_free(const Eigen::VectorXd& x, const Eigen::VectorXd& g, double step) const {
    double sum = 0.0;
    for (Eigen::Index i = 0; i < x.size(); ++i) {
      if (!is_free(x, i)) continue;
      const double reduced = g(i) > 0.0 ? std::min((x(i) - lo(i)) / step, g(i)) : std::max((x(i) - hi(i)) / step, g(i));
      sum += reduced * g(i);
    }
    return sum;
  }
  /// The largest t ≥ 0 with lo ≤ x − t v ≤ hi.
  double feasible_step(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const {
    double t = infinity;
    for (Eigen::Index i = 0; i < x.size(); ++i) {
      if (v(i) > 0.0) t = std::min(t, (x(i) - lo(i)) / v(i));
      if (v(i) < 0.0) t = std::min(t, (x(i) - hi(i)) / v(i));
    }
    return std::max(t, 0.0);
  }
  Eigen::VectorXd project(const Eigen::VectorXd& x) const { return x.cwiseMax(lo).cwiseMin(hi); }
  std::vector<char> free_mask(const Eigen::VectorXd& x) const {
    std::vector<char> out(static_cast<std::size_t>(x.size()));
    for (Eigen::Index i = 0; i < x.size(); ++i) out[static_cast<std::size_t>(i)] = is_free(x, i) ? 1 : 0;
    return out;
  }
};

const char* const kUnbounded =
    "contact QP: the objective is unbounded below (S has a null direction with a slope that no bound stops)";

/// MPRGP's iterate: the point, its gradient S x − d, the search direction.
struct Iterate {
  Eigen::VectorXd x, g, p;
};

/// A conjugate gradient step along p where it stays in the box; else an expansion step: to the
/// box's boundary along p, then a projected step of length ᾱ along the free gradient.
/// Curvature vᵀSv at or below round-off of the products (relative to L ‖v‖², L = 1/step) counts
/// as none: a null direction of S carries noise, and a CG step of 1e16 along it is no step.
bool has_curvature(double curvature, const Eigen::VectorXd& v, double step) {
  return curvature > 1e-14 * v.squaredNorm() / step;
}

void free_step(const TraceOperator& s, const Eigen::VectorXd& d, const Box& box, double step, Iterate& it) {
  // (round-off can turn p against the gradient after many steps: restart from the free gradient)
  if (!(it.g.dot(it.p) > 0.0)) it.p = box.free_gradient(it.x, it.g);
  const Eigen::VectorXd sp = s(it.p);
  const double curvature = it.p.dot(sp);
  const bool curved = has_curvature(curvature, it.p, step);
  const double cg_step = curved ? it.g.dot(it.p) / curvature : infinity;
  const double feasible = box.feasible_step(it.x, it.p);
  if (cg_step <= feasible) {
    it.x = box.project(it.x - cg_step * it.p);
    it.g -= cg_step * sp;
    const Eigen::VectorXd free = box.free_gradient(it.x, it.g);
    it.p = free - (free.dot(sp) / curvature) * it.p;
    return;
  }
  if (!std::isfinite(feasible)) throw NumericalError(kUnbounded);
  it.x = box.project(it.x - feasible * it.p);
  it.g -= feasible * sp;
  it.x = box.project(it.x - step * box.free_gradient(it.x, it.g));
  it.g = s(it.x) - d;
  it.p = box.free_gradient(it.x, it.g);
}

/// A proportioning step off the active bounds along −β (exact line search, kept in the box).
void proportioning_step(const TraceOperator& s, const Box& box, double step, const Eigen::VectorXd& chopped,
                        Iterate& it) {
  const Eigen::VectorXd sb = s(chopped);
  const double curvature = chopped.dot(sb);
  const double exact = has_curvature(curvature, chopped, step) ? it.g.dot(chopped) / curvature : infinity;
  const double t = std::min(exact, box.feasible_step(it.x, chopped));
  if (!std::isfinite(t)) throw NumericalError(kUnbounded);
  it.x = box.project(it.x - t * chopped);
  it.g -= t * sb;
  it.p = box.free_gradient(it.x, it.g);
}

}  // namespace

BoxQpResult solve_box_qp_by_products(const TraceOperator& s, const Eigen::VectorXd& d, const Eigen::VectorXd& lo,
                                     const Eigen::VectorXd& hi, const MprgpOptions& options) {
  const Eigen::Index n = d.size();
  HPC_VERIFY(s.size() == n && lo.size() == n && hi.size() == n, "MPRGP: sizes");
  if ((lo.array() > hi.array()).any())
    throw NumericalError("contact QP: a lower bound exceeds its upper bound (empty feasible set)");
  const Box box{lo, hi};
  BoxQpResult result;
  result.report.method = "mprgp";
  Iterate it;
  it.x = box.project(Eigen::VectorXd::Zero(n));
  const long first_products = s.products();
  const double lipschitz = 1.01 * largest_eigenvalue_bound(s);
  if (!std::isfinite(lipschitz)) throw NumericalError("contact QP (MPRGP): S x is not finite");
  if (!(lipschitz > 0.0)) {  // S = 0: min −dᵀx, each x_i at the bound d_i points to
    for (Eigen::Index i = 0; i < n; ++i)
      if (d(i) != 0.0) it.x(i) = d(i) > 0.0 ? hi(i) : lo(i);
    if (!it.x.allFinite()) throw NumericalError(kUnbounded);
    result.x = it.x;
    result.report.converged = true;
    result.report.products = s.products() - first_products;
    return result;
  }
  const double step = 1.0 / lipschitz;  // ᾱ ∈ (0, 2/‖S‖]
  const double d_scale = step * d.lpNorm<Eigen::Infinity>();
  const auto residual = [&](const Eigen::VectorXd& at, const Eigen::VectorXd& gradient) {
    const double scale = at.lpNorm<Eigen::Infinity>() + d_scale;
    const double r = (at - box.project(at - step * gradient)).lpNorm<Eigen::Infinity>();
    return scale > 0.0 ? r / scale : r;
  };
  it.g = s(it.x) - d;
  it.p = box.free_gradient(it.x, it.g);
  const double gamma2 = options.proportioning * options.proportioning;
  std::vector<char> was_free = box.free_mask(it.x);
  int flips = 0;  // bounds taken or released since the last log entry
  long k = 1;
  for (;; ++k) {
    double r = residual(it.x, it.g);
    if (!std::isfinite(r))
      throw NumericalError(fmt::format("contact QP (MPRGP): the KKT residual is {} at step {}", r, k));
    if (r <= options.tolerance) {
      it.g = s(it.x) - d;  // the recurrence's gradient drifts: confirm on the true one
      r = residual(it.x, it.g);
      if (r <= options.tolerance) {
        result.report.converged = true;
        result.report.kkt_residual = r;
        result.report.log.push_back({static_cast<int>(k), flips, r});
        break;
      }
      it.p = box.free_gradient(it.x, it.g);
    }
    result.report.kkt_residual = r;
    if (s.products() - first_products >= options.max_products) break;
    const Eigen::VectorXd chopped = box.chopped_gradient(it.x, it.g);
    if (chopped.squaredNorm() <= gamma2 * box.reduced_dot_free(it.x, it.g, step))
      free_step(s, d, box, step, it);
    else
      proportioning_step(s, box, step, chopped, it);
    const std::vector<char> now_free = box.free_mask(it.x);
    for (std::size_t i = 0; i < now_free.size(); ++i) flips += now_free[i] != was_free[i];
    was_free = now_free;
    if (k % 50 == 0) {
      result.report.log.push_back({static_cast<int>(k), flips, r});
      flips = 0;
    }
  }
  result.report.iterations = static_cast<int>(k);
  result.report.products = s.products() - first_products;
  if (!result.report.converged)
    throw NumericalError(
        fmt::format("contact QP (MPRGP, products by S): the KKT residual is {:.3e} after {} products, not {:.1e}",
                    result.report.kkt_residual, result.report.products, options.tolerance));
  result.x = std::move(it.x);
  return result;
}

}  // namespace hpcontact::contact
