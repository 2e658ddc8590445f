// solve_inequality_qp: Mehrotra predictor-corrector interior-point method on the one-sided form
//     minimise ½ xᵀ S x − dᵀ x   subject to   G x + σ = h, σ ≥ 0 (rows of C with a finite bound,
//     ±C_j),  E x = e (rows with lo_j = hi_j, e.g. λ = 0 where s vanishes),
// with the reduced Newton system   [S + Gᵀ Z Σ⁻¹ G   Eᵀ] [Δx]
//                                  [E                0 ] [Δw] = …   factored once per iteration.
#include "contact/inequality_qp.hpp"

#include <fmt/format.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace hpcontact::contact {

double InequalityKkt::max() const { return std::max({stationarity, feasibility, complementarity, sign}); }

InequalityKkt inequality_qp_kkt(const Eigen::MatrixXd& s, const Eigen::VectorXd& d,
                                const Eigen::MatrixXd& c, const Eigen::VectorXd& lo,
                                const Eigen::VectorXd& hi, const Eigen::VectorXd& x,
                                const Eigen::VectorXd& y) {
  InequalityKkt kkt;
  const Eigen::VectorXd cx = c * x;
  const double c_norm = c.lpNorm<Eigen::Infinity>(), x_norm = x.lpNorm<Eigen::Infinity>();
  const double y_norm = y.lpNorm<Eigen::Infinity>();
  double bound_norm = 0.0;
  for (Eigen::Index j = 0; j < c.rows(); ++j) {
    if (std::isfinite(lo(j))) bound_norm = std::max(bound_norm, std::abs(lo(j)));
    if (std::isfinite(hi(j))) bound_norm = std::max(bound_norm, std::abs(hi(j)));
  }
  // Scales that make every part invariant under (d, lo, hi) → t (d, lo, hi). ‖C‖ ‖d‖/‖S‖ is the size
  // of C x the data ask for; it keeps the scale meaningful when x and the bounds are all zero.
  auto relative = [](double value, double scale) { return scale > 0 ? value / scale : value; };
  const double s_norm = s.lpNorm<Eigen::Infinity>();
  const double value_scale =
      c_norm * x_norm + bound_norm + (s_norm > 0 ? c_norm * d.lpNorm<Eigen::Infinity>() / s_norm : 0.0);
  const double stationarity_scale =
      d.lpNorm<Eigen::Infinity>() + s.lpNorm<Eigen::Infinity>() * x_norm + c.transpose().lpNorm<Eigen::Infinity>() * y_norm;
  kkt.stationarity = relative((s * x - d + c.transpose() * y).lpNorm<Eigen::Infinity>(), stationarity_scale);
  if (!std::isfinite(kkt.stationarity)) kkt.stationarity = std::numeric_limits<double>::infinity();
  double infeasible = 0.0, complementary = 0.0, wrong_sign = 0.0;
  for (Eigen::Index j = 0; j < c.rows(); ++j) {
    infeasible = std::max({infeasible, cx(j) - hi(j), lo(j) - cx(j)});
    if (y(j) > 0) {  // pushes C x down: only an active upper bound may do that
      if (std::isfinite(hi(j))) complementary = std::max(complementary, y(j) * std::abs(hi(j) - cx(j)));
      else wrong_sign = std::max(wrong_sign, y(j));
    } else if (y(j) < 0) {
      if (std::isfinite(lo(j))) complementary = std::max(complementary, -y(j) * std::abs(cx(j) - lo(j)));
      else wrong_sign = std::max(wrong_sign, -y(j));
    }
  }
  kkt.feasibility = relative(std::max(infeasible, 0.0), value_scale);
  kkt.complementarity = relative(complementary, y_norm * value_scale);
  kkt.sign = relative(wrong_sign, y_norm);
  return kkt;
}

namespace {

// Largest α ≤ 1 with v + α Δv ≥ 0.
double step_to_boundary(const Eigen::VectorXd& v, const Eigen::VectorXd& dv) {
  double alpha = 1.0;
  for (Eigen::Index i = 0; i < v.size(); ++i)
    if (dv(i) < 0) alpha = std::min(alpha, -v(i) / dv(i));
  return alpha;
}

}  // namespace

InequalityQpResult solve_inequality_qp(const Eigen::MatrixXd& s, const Eigen::VectorXd& d,
                                       const Eigen::MatrixXd& c, const Eigen::VectorXd& lo,
                                       const Eigen::VectorXd& hi, const InequalityQpOptions& options) {
  const Eigen::Index n = d.size(), rows = c.rows();
  HPC_VERIFY(s.rows() == n && s.cols() == n && c.cols() == n && lo.size() == rows && hi.size() == rows,
             "inequality QP sizes");
  // 1. Split the rows of C into one-sided inequalities G x ≤ h and equalities E x = e.
  std::vector<Eigen::Index> g_row, e_row;
  std::vector<double> g_sign;
  for (Eigen::Index j = 0; j < rows; ++j) {
    if (!(lo(j) <= hi(j)))
      throw NumericalError(fmt::format("inequality QP: row {} has lower bound {} above upper bound {}", j, lo(j), hi(j)));
    if (lo(j) == hi(j)) {
      e_row.push_back(j);
      continue;
    }
    if (std::isfinite(hi(j))) g_row.push_back(j), g_sign.push_back(1.0);
    if (std::isfinite(lo(j))) g_row.push_back(j), g_sign.push_back(-1.0);
  }
  const auto m = static_cast<Eigen::Index>(g_row.size()), k = static_cast<Eigen::Index>(e_row.size());
  Eigen::MatrixXd g(m, n), e(k, n);
  Eigen::VectorXd h(m), e_value(k);
  for (Eigen::Index i = 0; i < m; ++i) {
    g.row(i) = g_sign[i] * c.row(g_row[i]);
    h(i) = g_sign[i] > 0 ? hi(g_row[i]) : -lo(g_row[i]);
  }
  for (Eigen::Index i = 0; i < k; ++i) e.row(i) = c.row(e_row[i]), e_value(i) = lo(e_row[i]);

  InequalityQpResult result;
  result.report.method = "interior-point";
  auto multipliers = [&](const Eigen::VectorXd& z, const Eigen::VectorXd& w) {
    Eigen::VectorXd y = Eigen::VectorXd::Zero(rows);
    for (Eigen::Index i = 0; i < m; ++i) y(g_row[i]) += g_sign[i] * z(i);
    for (Eigen::Index i = 0; i < k; ++i) y(e_row[i]) += w(i);
    return y;
  };

  // 2. Starting point: a regularized least-squares x (S + γ GᵀG + γ EᵀE is definite because C has
  //    full column rank), slacks and multipliers of the problem's own scale, so that multiplying
  //    the data by t multiplies every iterate by t and the iteration count does not change.
  const double gamma = std::max(s.trace(), 1e-300) / std::max(c.squaredNorm(), 1e-300);
  Eigen::VectorXd x = (s + gamma * (g.transpose() * g + e.transpose() * e))
                          .partialPivLu()
                          .solve(d + gamma * (g.transpose() * h + e.transpose() * e_value));
  const double g_norm = std::max(c.lpNorm<Eigen::Infinity>(), 1e-300);
  double value_scale = g_norm * x.lpNorm<Eigen::Infinity>();
  for (Eigen::Index i = 0; i < m; ++i) value_scale = std::max(value_scale, std::abs(h(i)));
  if (!(value_scale > 0)) value_scale = 1.0;
  double force_scale = std::max(d.lpNorm<Eigen::Infinity>(), (s * x - d).lpNorm<Eigen::Infinity>()) / g_norm;
  if (!(force_scale > 0)) force_scale = 1.0;
  Eigen::VectorXd slack = (h - g * x).cwiseMax(0.0).array() + value_scale;
  Eigen::VectorXd z = Eigen::VectorXd::Constant(m, force_scale);
  Eigen::VectorXd w = Eigen::VectorXd::Zero(k);
  // Predicted active set: rows whose slack is small against their multiplier, both in the
  // problem's scale; its changes are the interior-point analogue of active-set flips.
  auto predicted_active = [&] {
    std::vector<bool> active(m);
    for (Eigen::Index i = 0; i < m; ++i) active[i] = slack(i) * force_scale < z(i) * value_scale;
    return active;
  };
  std::vector<bool> active = predicted_active();

  // 3. Predictor-corrector iterations.
  auto evaluate = [&] {
    result.x = x;
    result.y = multipliers(z, w);
    result.kkt = inequality_qp_kkt(s, d, c, lo, hi, x, result.y);
    result.report.kkt_residual = result.kkt.max();
    result.report.converged = result.report.kkt_residual <= options.tolerance;
  };
  evaluate();
  for (int iteration = 1; iteration <= options.max_iterations && !result.report.converged; ++iteration) {
    const Eigen::VectorXd r_dual = s * x - d + g.transpose() * z + e.transpose() * w;
    const Eigen::VectorXd r_primal = g * x + slack - h;
    const Eigen::VectorXd r_equality = e * x - e_value;
    const double mu = m > 0 ? slack.dot(z) / static_cast<double>(m) : 0.0;
    const Eigen::VectorXd weight = z.cwiseQuotient(slack);  // Z Σ⁻¹
    Eigen::MatrixXd kkt_matrix = Eigen::MatrixXd::Zero(n + k, n + k);
    kkt_matrix.topLeftCorner(n, n) = s + g.transpose() * weight.asDiagonal() * g;
    kkt_matrix.topRightCorner(n, k) = e.transpose();
    kkt_matrix.bottomLeftCorner(k, n) = e;
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(kkt_matrix);
    // Newton direction for residuals (r_d, r_p, r_e, r_sz) of the four KKT blocks
    //   S Δx + Gᵀ Δz + Eᵀ Δw = −r_d,  G Δx + Δσ = −r_p,  E Δx = −r_e,  Z Δσ + Σ Δz = −r_sz,
    // through the reduced system. Two rounds of iterative refinement on the full system: near the
    // solution Z Σ⁻¹ spans many orders of magnitude and Δz = Σ⁻¹(…) + Z Σ⁻¹ G Δx amplifies the
    // error of Δx; refinement restores the stationarity residual to round-off.
    struct Step { Eigen::VectorXd dx, dw, dslack, dz; };
    auto reduced_solve = [&](const Eigen::VectorXd& rd, const Eigen::VectorXd& rp, const Eigen::VectorXd& re,
                             const Eigen::VectorXd& rsz) {
      const Eigen::VectorXd t = (z.cwiseProduct(rp) - rsz).cwiseQuotient(slack);
      Eigen::VectorXd rhs(n + k);
      rhs.head(n) = -rd - g.transpose() * t;
      rhs.tail(k) = -re;
      const Eigen::VectorXd solution = lu.solve(rhs);
      Step step{solution.head(n), solution.tail(k), Eigen::VectorXd(), Eigen::VectorXd()};
      step.dslack = -rp - g * step.dx;
      step.dz = t + weight.cwiseProduct(g * step.dx);
      return step;
    };
    auto direction = [&](const Eigen::VectorXd& rsz) {
      Step step = reduced_solve(r_dual, r_primal, r_equality, rsz);
      for (int round = 0; round < 2; ++round) {
        // Residuals of the full system at the current direction, as r's of a correction.
        const Step c = reduced_solve(r_dual + s * step.dx + g.transpose() * step.dz + e.transpose() * step.dw,
                                     r_primal + g * step.dx + step.dslack, r_equality + e * step.dx,
                                     rsz + z.cwiseProduct(step.dslack) + slack.cwiseProduct(step.dz));
        step.dx += c.dx, step.dw += c.dw, step.dslack += c.dslack, step.dz += c.dz;
      }
      return step;
    };
    // Predictor (affine scaling), then Mehrotra's centring and second-order correction.
    const Eigen::VectorXd sz = slack.cwiseProduct(z);
    const Step affine = direction(sz);
    const double alpha_affine =
        std::min(step_to_boundary(slack, affine.dslack), step_to_boundary(z, affine.dz));
    const double mu_affine = m > 0 ? (slack + alpha_affine * affine.dslack).dot(z + alpha_affine * affine.dz) /
                                         static_cast<double>(m)
                                   : 0.0;
    const double sigma = mu > 0 ? std::pow(mu_affine / mu, 3) : 0.0;
    const auto [dx, dw, dslack, dz] =
        direction(sz + affine.dslack.cwiseProduct(affine.dz) - Eigen::VectorXd::Constant(m, sigma * mu));
    const double alpha =
        std::min(1.0, 0.995 * std::min(step_to_boundary(slack, dslack), step_to_boundary(z, dz)));
    x += alpha * dx;
    w += alpha * dw;
    slack += alpha * dslack;
    z += alpha * dz;
    result.report.iterations = iteration;
    const auto now_active = predicted_active();
    int changes = 0;
    for (Eigen::Index i = 0; i < m; ++i) changes += now_active[i] != active[i];
    active = now_active;
    evaluate();
    result.report.log.push_back({iteration, changes, result.report.kkt_residual});
  }
  if (!result.report.converged)
    throw NumericalError(fmt::format(
        "contact QP (interior point) did not converge in {} iterations: relative KKT residuals "
        "stationarity {:.2e}, feasibility {:.2e}, complementarity {:.2e}, sign {:.2e} (tolerance {:.1e})",
        options.max_iterations, result.kkt.stationarity, result.kkt.feasibility,
        result.kkt.complementarity, result.kkt.sign, options.tolerance));
  return result;
}

}  // namespace hpcontact::contact
