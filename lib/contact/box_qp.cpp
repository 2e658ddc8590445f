// solve_box_qp: PDAS inside proximal steps.
#include "contact/box_qp.hpp"

#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <cmath>

#include "core/error.hpp"

namespace hpcontact::contact {

double box_qp_kkt_residual(const Eigen::MatrixXd& s, const Eigen::VectorXd& d,
                           const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                           const Eigen::VectorXd& x) {
  const Eigen::VectorXd gradient = s * x - d;
  const Eigen::VectorXd projected = (x - gradient).cwiseMax(lo).cwiseMin(hi);
  const double scale = d.lpNorm<Eigen::Infinity>() + s.lpNorm<Eigen::Infinity>() * x.lpNorm<Eigen::Infinity>();
  const double residual = (x - projected).lpNorm<Eigen::Infinity>();
  return scale > 0 ? residual / scale : residual;
}

namespace {

enum class State : signed char { lower = -1, free = 0, upper = 1 };

// PDAS for  min ½ xᵀ A x − bᵀ x, lo ≤ x ≤ hi,  A positive definite. Returns steps taken, or -1.
int primal_dual_active_set(const Eigen::MatrixXd& a, const Eigen::VectorXd& b,
                           const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                           Eigen::VectorXd& x, int max_steps, double tolerance,
                           const Eigen::MatrixXd& s, const Eigen::VectorXd& d,
                           std::vector<BoxQpIteration>& log, int& step_counter) {
  const Eigen::Index n = x.size();
  std::vector<State> state(n, State::free);
  for (int step = 0; step < max_steps; ++step) {
    // Active sets from the complementarity function x − c·∇ (c = 1/max diag A for scale).
    const Eigen::VectorXd gradient = a * x - b;
    const double c = 1.0 / std::max(a.diagonal().maxCoeff(), 1e-300);
    int changes = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double trial = x(i) - c * gradient(i);
      const State next = trial >= hi(i) ? State::upper : (trial <= lo(i) ? State::lower : State::free);
      if (next != state[i]) ++changes;
      state[i] = next;
    }
    // Newton step: fix the active components, solve for the free ones.
    std::vector<Eigen::Index> free;
    for (Eigen::Index i = 0; i < n; ++i) {
      if (state[i] == State::upper) x(i) = hi(i);
      else if (state[i] == State::lower) x(i) = lo(i);
      else free.push_back(i);
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
      const Eigen::VectorXd x_free = a_ff.ldlt().solve(rhs);
      for (Eigen::Index r = 0; r < m; ++r) x(free[r]) = x_free(r);
    }
    ++step_counter;
    const double residual = box_qp_kkt_residual(s, d, lo, hi, x);
    log.push_back({step_counter, changes, residual});
    // Converged for this subproblem: the sets did not change and the free part is feasible.
    if (step > 0 && changes == 0 && box_qp_kkt_residual(a, b, lo, hi, x) <= tolerance) return step + 1;
  }
  return -1;
}

}  // namespace

BoxQpResult solve_box_qp(const Eigen::MatrixXd& s, const Eigen::VectorXd& d,
                         const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                         const BoxQpOptions& options) {
  const Eigen::Index n = d.size();
  HPC_VERIFY(s.rows() == n && s.cols() == n && lo.size() == n && hi.size() == n, "box QP sizes");
  if ((lo.array() > hi.array()).any())
    throw NumericalError("box QP: a lower bound exceeds its upper bound (empty feasible set)");
  BoxQpResult result;
  result.x = Eigen::VectorXd::Zero(n).cwiseMax(lo).cwiseMin(hi);
  if (n == 0) {
    result.converged = true;
    return result;
  }
  const double rho = options.proximal * std::max(s.diagonal().maxCoeff(), 1e-300);
  const Eigen::MatrixXd a = s + rho * Eigen::MatrixXd::Identity(n, n);
  int steps = 0;
  for (int outer = 0; outer < options.max_proximal; ++outer) {
    const Eigen::VectorXd b = d + rho * result.x;
    const int taken = primal_dual_active_set(a, b, lo, hi, result.x, options.max_newton,
                                             0.1 * options.tolerance, s, d, result.log, steps);
    result.proximal_steps = outer + 1;
    result.kkt_residual = box_qp_kkt_residual(s, d, lo, hi, result.x);
    if (taken < 0) break;
    if (result.kkt_residual <= options.tolerance) {
      result.converged = true;
      break;
    }
  }
  result.newton_steps = steps;
  result.method = result.proximal_steps > 1 ? "pdas+proximal" : "pdas";
  if (!result.converged)
    throw NumericalError(fmt::format(
        "contact QP did not converge: KKT residual {:.3e} > tolerance {:.1e} after {} active-set "
        "steps in {} proximal steps",
        result.kkt_residual, options.tolerance, steps, result.proximal_steps));
  return result;
}

}  // namespace hpcontact::contact
