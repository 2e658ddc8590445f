// solve_box_qp: safeguarded active-set steps (block principal pivoting) inside proximal steps.
#include "contact/box_qp.hpp"

#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace hpcontact::contact {

double box_qp_kkt_residual(const Eigen::MatrixXd& s, const Eigen::VectorXd& d, const Eigen::VectorXd& lo,
                           const Eigen::VectorXd& hi, const Eigen::VectorXd& x) {
  // The projected-gradient step with step length c = 1/‖S‖_∞ carries the units of x, so the
  // residual is invariant under scaling (S, d) and the bounds independently.
  const double s_norm = s.lpNorm<Eigen::Infinity>();
  const double c = s_norm > 0 ? 1.0 / s_norm : 1.0;
  const Eigen::VectorXd gradient = s * x - d;
  const Eigen::VectorXd projected = (x - c * gradient).cwiseMax(lo).cwiseMin(hi);
  const double scale = x.lpNorm<Eigen::Infinity>() + c * d.lpNorm<Eigen::Infinity>();
  const double residual = (x - projected).lpNorm<Eigen::Infinity>();
  return scale > 0 ? residual / scale : residual;
}

namespace {

enum class State : signed char { lower = -1, free = 0, upper = 1 };

// Indices whose state contradicts the KKT conditions after a solve: a free component outside its
// bounds, or an active one whose gradient pushes it into the box (∇ > 0 at the upper bound,
// ∇ < 0 at the lower one).
std::vector<Eigen::Index> violations(const std::vector<State>& state, const Eigen::VectorXd& x,
                                     const Eigen::VectorXd& gradient, const Eigen::VectorXd& lo,
                                     const Eigen::VectorXd& hi, double x_tolerance, double gradient_tolerance) {
  std::vector<Eigen::Index> out;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    const bool bad = state[i] == State::free    ? (x(i) > hi(i) + x_tolerance || x(i) < lo(i) - x_tolerance)
                     : state[i] == State::upper ? gradient(i) > gradient_tolerance
                                                : gradient(i) < -gradient_tolerance;
    if (bad) out.push_back(i);
  }
  return out;
}

void flip(std::vector<State>& state, Eigen::Index i, const Eigen::VectorXd& x, const Eigen::VectorXd& hi) {
  if (state[i] != State::free)
    state[i] = State::free;
  else
    state[i] = x(i) > hi(i) ? State::upper : State::lower;
}

// Block principal pivoting (Júdice–Pires) for  min ½ xᵀ A x − bᵀ x, lo ≤ x ≤ hi,  A positive
// definite: the primal-dual active-set (semismooth Newton) step flips every violated index; when
// that stops reducing the number of violations, Murty's least-index single flip takes over, which
// terminates for positive definite A (plain PDAS can cycle, as seen on friction problems).
// Returns the steps taken, or -1.
int block_principal_pivoting(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, const Eigen::VectorXd& lo,
                             const Eigen::VectorXd& hi, Eigen::VectorXd& x, int max_steps, const Eigen::MatrixXd& s,
                             const Eigen::VectorXd& d, std::vector<QpIteration>& log, int& step_counter) {
  const Eigen::Index n = x.size();
  // Start from the active sets the current point suggests (warm start across proximal steps).
  std::vector<State> state(n, State::free);
  {
    const Eigen::VectorXd gradient = a * x - b;
    const double c = 1.0 / std::max(a.diagonal().maxCoeff(), 1e-300);
    for (Eigen::Index i = 0; i < n; ++i) {
      const double trial = x(i) - c * gradient(i);
      state[i] = trial >= hi(i) ? State::upper : (trial <= lo(i) ? State::lower : State::free);
    }
  }
  // Two tolerances in their own units, so that scaling (A, b) and the bounds independently (as
  // friction (13) does: S and d scale with s², the box |λ| ≤ 1 does not) changes no decision:
  // bounds are compared in units of x, gradients in units of b.
  double x_scale = x.lpNorm<Eigen::Infinity>();
  for (Eigen::Index i = 0; i < n; ++i) {
    if (std::isfinite(lo(i))) x_scale = std::max(x_scale, std::abs(lo(i)));
    if (std::isfinite(hi(i))) x_scale = std::max(x_scale, std::abs(hi(i)));
  }
  if (!(x_scale > 0)) x_scale = b.lpNorm<Eigen::Infinity>() / std::max(a.diagonal().maxCoeff(), 1e-300);
  const double x_tolerance = 1e-13 * std::max(x_scale, 1e-300);
  const double gradient_tolerance =
      1e-13 * std::max(b.lpNorm<Eigen::Infinity>() + a.lpNorm<Eigen::Infinity>() * x_scale, 1e-300);
  std::size_t best = std::numeric_limits<std::size_t>::max();
  int stalled = 0;
  for (int step = 0; step < max_steps; ++step) {
    std::vector<Eigen::Index> free;
    for (Eigen::Index i = 0; i < n; ++i) {
      if (state[i] == State::upper)
        x(i) = hi(i);
      else if (state[i] == State::lower)
        x(i) = lo(i);
      else
        free.push_back(i);
    }
    if (!free.empty()) {
      const auto m = static_cast<Eigen::Index>(free.size());
      Eigen::MatrixXd a_ff(m, m);
      Eigen::VectorXd rhs(m);
      for (Eigen::Index r = 0; r < m; ++r) {
        rhs(r) = b(free[r]);
        for (Eigen::Index k = 0; k < n; ++k)
          if (state[k] != State::free) rhs(r) -= a(free[r], k) * x(k);
        for (Eigen::Index q = 0; q < m; ++q) a_ff(r, q) = a(free[r], free[q]);
      }
      const Eigen::VectorXd x_free = a_ff.llt().solve(rhs);
      for (Eigen::Index r = 0; r < m; ++r) x(free[r]) = x_free(r);
    }
    ++step_counter;
    const auto bad = violations(state, x, a * x - b, lo, hi, x_tolerance, gradient_tolerance);
    const int flips = bad.empty() ? 0 : (bad.size() < best || stalled < 2 ? static_cast<int>(bad.size()) : 1);
    log.push_back({step_counter, flips, box_qp_kkt_residual(s, d, lo, hi, x)});
    if (bad.empty()) {
      x = x.cwiseMax(lo).cwiseMin(hi);  // remove round-off excursions beyond the bounds
      return step + 1;
    }
    if (bad.size() < best) {
      best = bad.size();
      stalled = 0;
    } else {
      ++stalled;
    }
    if (stalled < 3) {
      for (Eigen::Index i : bad) flip(state, i, x, hi);
    } else {
      flip(state, bad.front(), x, hi);
    }
  }
  return -1;
}

}  // namespace

namespace {

BoxQpResult solve_scaled_box_qp(const Eigen::MatrixXd& s, const Eigen::VectorXd& d, const Eigen::VectorXd& lo,
                                const Eigen::VectorXd& hi, const BoxQpOptions& options) {
  const Eigen::Index n = d.size();
  HPC_VERIFY(s.rows() == n && s.cols() == n && lo.size() == n && hi.size() == n, "box QP sizes");
  if ((lo.array() > hi.array()).any())
    throw NumericalError("box QP: a lower bound exceeds its upper bound (empty feasible set)");
  BoxQpResult result;
  result.x = Eigen::VectorXd::Zero(n).cwiseMax(lo).cwiseMin(hi);
  if (n == 0) {
    result.report.converged = true;
    return result;
  }
  const double rho = options.proximal * std::max(s.diagonal().maxCoeff(), 1e-300);
  const Eigen::MatrixXd a = s + rho * Eigen::MatrixXd::Identity(n, n);
  int steps = 0;
  for (int outer = 0; outer < options.max_proximal; ++outer) {
    const Eigen::VectorXd b = d + rho * result.x;
    const int taken =
        block_principal_pivoting(a, b, lo, hi, result.x, options.max_newton, s, d, result.report.log, steps);
    result.report.proximal_steps = outer + 1;
    result.report.kkt_residual = box_qp_kkt_residual(s, d, lo, hi, result.x);
    if (taken < 0) break;
    if (result.report.kkt_residual <= options.tolerance) {
      result.report.converged = true;
      break;
    }
  }
  result.report.iterations = steps;
  result.report.method = result.report.proximal_steps > 1 ? "active-set+proximal" : "active-set";
  if (!result.report.converged)
    throw NumericalError(
        fmt::format("contact QP did not converge: KKT residual {:.3e} > tolerance {:.1e} after {} active-set "
                    "steps in {} proximal steps",
                    result.report.kkt_residual, options.tolerance, steps, result.report.proximal_steps));
  return result;
}

}  // namespace

BoxQpResult solve_box_qp(const Eigen::MatrixXd& s, const Eigen::VectorXd& d, const Eigen::VectorXd& lo,
                         const Eigen::VectorXd& hi, const BoxQpOptions& options) {
  const Eigen::Index n = d.size();
  HPC_VERIFY(s.rows() == n && s.cols() == n && lo.size() == n && hi.size() == n, "box QP sizes");
  // Jacobi scaling x = D y, D = diag(S)^{-1/2}: on geometric meshes the multipliers of the
  // smallest and largest segments differ in curvature S_ii by 1e10 and more, and without it the
  // proximal term and the residual, both relative to the largest, would not see the small ones.
  // D > 0 keeps the box a box.
  const double largest = n > 0 ? std::max(s.diagonal().maxCoeff(), 1e-300) : 1.0;
  Eigen::VectorXd scale(n);
  for (Eigen::Index i = 0; i < n; ++i) scale[i] = 1.0 / std::sqrt(s(i, i) > 1e-14 * largest ? s(i, i) : largest);
  const Eigen::MatrixXd scaled = scale.asDiagonal() * s * scale.asDiagonal();
  auto result =
      solve_scaled_box_qp(scaled, scale.cwiseProduct(d), lo.cwiseQuotient(scale), hi.cwiseQuotient(scale), options);
  result.x = scale.cwiseProduct(result.x);
  return result;
}

}  // namespace hpcontact::contact
