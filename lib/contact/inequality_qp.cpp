// solve_inequality_qp: Mehrotra predictor-corrector interior-point method on the one-sided form
//     minimise ½ xᵀ S x − dᵀ x   subject to   G x + σ = h, σ ≥ 0 (rows of C with a finite bound,
//     ±C_j),  E x = e (rows with lo_j = hi_j, e.g. λ = 0 where s vanishes),
// with the reduced Newton system   [S + Gᵀ Z Σ⁻¹ G   Eᵀ] [Δx]
//                                  [E                0 ] [Δw] = …   factored once per iteration.
#include "contact/inequality_qp.hpp"

#include <fmt/format.h>

#include <Eigen/LU>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace hpcontact::contact {

double InequalityKkt::max() const { return std::max({stationarity, feasibility, complementarity, sign}); }

InequalityKkt inequality_qp_kkt(const Eigen::MatrixXd& s, const Eigen::VectorXd& d, const Eigen::MatrixXd& c,
                                const Eigen::VectorXd& lo, const Eigen::VectorXd& hi, const Eigen::VectorXd& x,
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
  const double stationarity_scale = d.lpNorm<Eigen::Infinity>() + s.lpNorm<Eigen::Infinity>() * x_norm +
                                    c.transpose().lpNorm<Eigen::Infinity>() * y_norm;
  kkt.stationarity = relative((s * x - d + c.transpose() * y).lpNorm<Eigen::Infinity>(), stationarity_scale);
  if (!std::isfinite(kkt.stationarity)) kkt.stationarity = std::numeric_limits<double>::infinity();
  double infeasible = 0.0, complementary = 0.0, wrong_sign = 0.0;
  for (Eigen::Index j = 0; j < c.rows(); ++j) {
    infeasible = std::max({infeasible, cx(j) - hi(j), lo(j) - cx(j)});
    if (y(j) > 0) {  // pushes C x down: only an active upper bound may do that
      if (std::isfinite(hi(j)))
        complementary = std::max(complementary, y(j) * std::abs(hi(j) - cx(j)));
      else
        wrong_sign = std::max(wrong_sign, y(j));
    } else if (y(j) < 0) {
      if (std::isfinite(lo(j)))
        complementary = std::max(complementary, -y(j) * std::abs(cx(j) - lo(j)));
      else
        wrong_sign = std::max(wrong_sign, -y(j));
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

namespace {

// The rows of C split into one-sided inequalities G x ≤ h (±C_j for each finite bound) and
// equalities E x = e (rows with lo_j = hi_j). Equality rows that depend on others (a bound
// s ≡ 0 on a segment with more constraint points than coefficients: q rows on p_C + 1 unknowns)
// would make the Newton system [S + …, Eᵀ; E, 0] singular: E is then replaced by an orthonormal
// basis Q_rᵀ of its row space (Eᵀ = Q R Π, rank r) with e → Q_rᵀ x₀, x₀ the least-squares solution
// of E x = e, and the multipliers w of these rows map back to C's rows by the least-norm solution
// of Eᵀ y_E = Q_r w (`equality_rows`).
struct OneSidedForm {
  Eigen::MatrixXd g, e;
  Eigen::VectorXd h, e_value;
  Eigen::MatrixXd equality_rows;  ///< (original equality rows, rows of e): y_E = equality_rows · w
  std::vector<Eigen::Index> g_row, e_row;
  std::vector<double> g_sign;
  Eigen::Index rows = 0;

  OneSidedForm(const Eigen::MatrixXd& c, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi) : rows(c.rows()) {
    for (Eigen::Index j = 0; j < rows; ++j) {
      if (!(lo(j) <= hi(j)))
        throw NumericalError(
            fmt::format("inequality QP: row {} has lower bound {} above upper bound {}", j, lo(j), hi(j)));
      if (lo(j) == hi(j)) {
        e_row.push_back(j);
        continue;
      }
      if (std::isfinite(hi(j))) g_row.push_back(j), g_sign.push_back(1.0);
      if (std::isfinite(lo(j))) g_row.push_back(j), g_sign.push_back(-1.0);
    }
    const auto m = static_cast<Eigen::Index>(g_row.size()), k = static_cast<Eigen::Index>(e_row.size());
    g.resize(m, c.cols());
    e.resize(k, c.cols());
    h.resize(m);
    e_value.resize(k);
    for (Eigen::Index i = 0; i < m; ++i) {
      g.row(i) = g_sign[i] * c.row(g_row[i]);
      h(i) = g_sign[i] > 0 ? hi(g_row[i]) : -lo(g_row[i]);
    }
    for (Eigen::Index i = 0; i < k; ++i) e.row(i) = c.row(e_row[i]), e_value(i) = lo(e_row[i]);
    equality_rows = Eigen::MatrixXd::Identity(k, k);
    if (k == 0) return;
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(e.transpose());
    const Eigen::Index rank = qr.rank();
    if (rank == k) return;
    const Eigen::MatrixXd basis = qr.householderQ() * Eigen::MatrixXd::Identity(c.cols(), rank);
    const Eigen::VectorXd x0 = e.completeOrthogonalDecomposition().solve(e_value);
    equality_rows = e.transpose().completeOrthogonalDecomposition().pseudoInverse() * basis;
    e = basis.transpose();
    e_value = basis.transpose() * x0;
  }
  /// The multipliers y of the rows of C from those of G (z) and E (w).
  Eigen::VectorXd multipliers(const Eigen::VectorXd& z, const Eigen::VectorXd& w) const {
    Eigen::VectorXd y = Eigen::VectorXd::Zero(rows);
    for (std::size_t i = 0; i < g_row.size(); ++i) y(g_row[i]) += g_sign[i] * z(static_cast<Eigen::Index>(i));
    const Eigen::VectorXd w_rows = equality_rows * w;
    for (std::size_t i = 0; i < e_row.size(); ++i) y(e_row[i]) += w_rows(static_cast<Eigen::Index>(i));
    return y;
  }
};

// The primal-dual iterate: x, slacks σ of G x ≤ h, their multipliers z, those of E x = e (w), and
// the problem's scales of values (C x, h) and forces (multipliers).
struct Iterate {
  Eigen::VectorXd x, slack, z, w;
  double value_scale = 1.0, force_scale = 1.0;
  /// Rows whose slack is small against their multiplier, both in the problem's scale: the
  /// interior-point analogue of an active set, whose changes the log reports.
  std::vector<bool> predicted_active() const {
    std::vector<bool> active(static_cast<std::size_t>(z.size()));
    for (Eigen::Index i = 0; i < z.size(); ++i)
      active[static_cast<std::size_t>(i)] = slack(i) * force_scale < z(i) * value_scale;
    return active;
  }
};

// A regularized least-squares x (S + γ GᵀG + γ EᵀE is definite because C has full column rank),
// slacks and multipliers of the problem's own scale, so that multiplying the data by t multiplies
// every iterate by t and the iteration count does not change.
Iterate starting_point(const Eigen::MatrixXd& s, const Eigen::VectorXd& d, const Eigen::MatrixXd& c,
                       const OneSidedForm& form) {
  const auto& g = form.g;
  const auto& e = form.e;
  Iterate it;
  const double gamma = std::max(s.trace(), 1e-300) / std::max(c.squaredNorm(), 1e-300);
  it.x = (s + gamma * (g.transpose() * g + e.transpose() * e))
             .partialPivLu()
             .solve(d + gamma * (g.transpose() * form.h + e.transpose() * form.e_value));
  const double g_norm = std::max(c.lpNorm<Eigen::Infinity>(), 1e-300);
  double value_scale = g_norm * it.x.lpNorm<Eigen::Infinity>();
  for (Eigen::Index i = 0; i < form.h.size(); ++i) value_scale = std::max(value_scale, std::abs(form.h(i)));
  it.value_scale = value_scale > 0 ? value_scale : 1.0;
  const double force_scale = std::max(d.lpNorm<Eigen::Infinity>(), (s * it.x - d).lpNorm<Eigen::Infinity>()) / g_norm;
  it.force_scale = force_scale > 0 ? force_scale : 1.0;
  it.slack = (form.h - g * it.x).cwiseMax(0.0).array() + it.value_scale;
  it.z = Eigen::VectorXd::Constant(g.rows(), it.force_scale);
  it.w = Eigen::VectorXd::Zero(e.rows());
  return it;
}

struct Step {
  Eigen::VectorXd dx, dw, dslack, dz;
};

// The Newton system at one iterate for residuals (r_d, r_p, r_e, r_sz) of the four KKT blocks
//   S Δx + Gᵀ Δz + Eᵀ Δw = −r_d,  G Δx + Δσ = −r_p,  E Δx = −r_e,  Z Δσ + Σ Δz = −r_sz,
// solved through the reduced system [S + Gᵀ Z Σ⁻¹ G, Eᵀ; E, 0], factored once. Two rounds of
// iterative refinement on the full system: near the solution Z Σ⁻¹ spans many orders of magnitude
// and Δz = Σ⁻¹(…) + Z Σ⁻¹ G Δx amplifies the error of Δx; refinement restores the stationarity
// residual to round-off.
class NewtonSystem {
 public:
  NewtonSystem(const Eigen::MatrixXd& s, const Eigen::VectorXd& d, const OneSidedForm& form, const Iterate& it)
      : s_(s), form_(form), it_(it), weight_(it.z.cwiseQuotient(it.slack)) {
    const auto& g = form.g;
    const auto& e = form.e;
    const Eigen::Index n = s.rows(), k = e.rows();
    Eigen::MatrixXd matrix = Eigen::MatrixXd::Zero(n + k, n + k);
    matrix.topLeftCorner(n, n) = s + g.transpose() * weight_.asDiagonal() * g;
    matrix.topRightCorner(n, k) = e.transpose();
    matrix.bottomLeftCorner(k, n) = e;
    lu_.compute(matrix);
    r_dual_ = s * it.x - d + g.transpose() * it.z + e.transpose() * it.w;
    r_primal_ = g * it.x + it.slack - form.h;
    r_equality_ = e * it.x - form.e_value;
  }

  Step direction(const Eigen::VectorXd& rsz) const {
    const auto& g = form_.g;
    const auto& e = form_.e;
    Step step = reduced_solve(r_dual_, r_primal_, r_equality_, rsz);
    for (int round = 0; round < 2; ++round) {
      // Residuals of the full system at the current direction, as r's of a correction.
      const Step c = reduced_solve(r_dual_ + s_ * step.dx + g.transpose() * step.dz + e.transpose() * step.dw,
                                   r_primal_ + g * step.dx + step.dslack, r_equality_ + e * step.dx,
                                   rsz + it_.z.cwiseProduct(step.dslack) + it_.slack.cwiseProduct(step.dz));
      step.dx += c.dx, step.dw += c.dw, step.dslack += c.dslack, step.dz += c.dz;
    }
    return step;
  }

 private:
  Step reduced_solve(const Eigen::VectorXd& rd, const Eigen::VectorXd& rp, const Eigen::VectorXd& re,
                     const Eigen::VectorXd& rsz) const {
    const auto& g = form_.g;
    const Eigen::Index n = s_.rows(), k = form_.e.rows();
    const Eigen::VectorXd t = (it_.z.cwiseProduct(rp) - rsz).cwiseQuotient(it_.slack);
    Eigen::VectorXd rhs(n + k);
    rhs.head(n) = -rd - g.transpose() * t;
    rhs.tail(k) = -re;
    const Eigen::VectorXd solution = lu_.solve(rhs);
    Step step{solution.head(n), solution.tail(k), Eigen::VectorXd(), Eigen::VectorXd()};
    step.dslack = -rp - g * step.dx;
    step.dz = t + weight_.cwiseProduct(g * step.dx);
    return step;
  }

  const Eigen::MatrixXd& s_;
  const OneSidedForm& form_;
  const Iterate& it_;
  Eigen::VectorXd weight_;  // Z Σ⁻¹
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  Eigen::VectorXd r_dual_, r_primal_, r_equality_;
};

// One predictor-corrector step: the affine-scaling predictor, then Mehrotra's centring and
// second-order correction, taken to 0.995 of the distance to the boundary.
void predictor_corrector_step(const NewtonSystem& newton, Iterate& it) {
  const Eigen::Index m = it.z.size();
  const double mu = m > 0 ? it.slack.dot(it.z) / static_cast<double>(m) : 0.0;
  const Eigen::VectorXd sz = it.slack.cwiseProduct(it.z);
  const Step affine = newton.direction(sz);
  const double alpha_affine = std::min(step_to_boundary(it.slack, affine.dslack), step_to_boundary(it.z, affine.dz));
  const double mu_affine =
      m > 0 ? (it.slack + alpha_affine * affine.dslack).dot(it.z + alpha_affine * affine.dz) / static_cast<double>(m)
            : 0.0;
  const double sigma = mu > 0 ? std::pow(mu_affine / mu, 3) : 0.0;
  const auto [dx, dw, dslack, dz] =
      newton.direction(sz + affine.dslack.cwiseProduct(affine.dz) - Eigen::VectorXd::Constant(m, sigma * mu));
  const double alpha = std::min(1.0, 0.995 * std::min(step_to_boundary(it.slack, dslack), step_to_boundary(it.z, dz)));
  it.x += alpha * dx;
  it.w += alpha * dw;
  it.slack += alpha * dslack;
  it.z += alpha * dz;
}

}  // namespace

InequalityQpResult solve_inequality_qp(const Eigen::MatrixXd& s, const Eigen::VectorXd& d, const Eigen::MatrixXd& c,
                                       const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                                       const InequalityQpOptions& options) {
  const Eigen::Index n = d.size(), rows = c.rows();
  HPC_VERIFY(s.rows() == n && s.cols() == n && c.cols() == n && lo.size() == rows && hi.size() == rows,
             "inequality QP sizes");
  const OneSidedForm form(c, lo, hi);
  Iterate it = starting_point(s, d, c, form);
  std::vector<bool> active = it.predicted_active();
  InequalityQpResult result;
  result.report.method = "interior-point";
  auto evaluate = [&] {
    result.x = it.x;
    result.y = form.multipliers(it.z, it.w);
    result.kkt = inequality_qp_kkt(s, d, c, lo, hi, it.x, result.y);
    result.report.kkt_residual = result.kkt.max();
    result.report.converged = result.report.kkt_residual <= options.tolerance;
  };
  evaluate();
  for (int iteration = 1; iteration <= options.max_iterations && !result.report.converged; ++iteration) {
    predictor_corrector_step(NewtonSystem(s, d, form, it), it);
    result.report.iterations = iteration;
    const auto now_active = it.predicted_active();
    int changes = 0;
    for (std::size_t i = 0; i < now_active.size(); ++i) changes += now_active[i] != active[i];
    active = now_active;
    evaluate();
    result.report.log.push_back({iteration, changes, result.report.kkt_residual});
  }
  if (!result.report.converged)
    throw NumericalError(
        fmt::format("contact QP (interior point) did not converge in {} iterations: relative KKT residuals "
                    "stationarity {:.2e}, feasibility {:.2e}, complementarity {:.2e}, sign {:.2e} (tolerance {:.1e})",
                    options.max_iterations, result.kkt.stationarity, result.kkt.feasibility, result.kkt.complementarity,
                    result.kkt.sign, options.tolerance));
  return result;
}

}  // namespace hpcontact::contact
