// FISTA with adaptive restart for the sign-and-disc constrained dual of 3-D Tresca contact.
#include "contact/disc_qp.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "contact/trace_operator.hpp"
#include "core/error.hpp"

namespace hpcontact::contact {

namespace {

/// The nearest point of the set: P_i clamped at 0, (t₁_i, t₂_i) scaled into the disc of radius s_i.
void project(Eigen::Ref<Eigen::VectorXd> x, const Eigen::VectorXd& radius) {
  const Eigen::Index m = radius.size();
  for (Eigen::Index i = 0; i < m; ++i) {
    x(i) = std::max(x(i), 0.0);
    const double length = std::hypot(x(m + i), x(2 * m + i));
    if (length > radius(i)) {
      const double scale = length > 0.0 ? radius(i) / length : 0.0;
      x(m + i) *= scale;
      x(2 * m + i) *= scale;
    }
  }
}

/// FISTA with adaptive restart from x = 0; `s_scale` sets the residual's scale, max(‖d‖_∞, s_scale ‖x‖_∞).
/// `estimated`: L is an estimate, raised to 1.01 × any Rayleigh quotient of S that exceeds it.
DiscQpSolution accelerated_projected_gradient(const TraceOperator& s, const Eigen::VectorXd& d,
                                              const Eigen::VectorXd& radius, double lipschitz, double s_scale,
                                              bool estimated, const DiscQpOptions& options) {
  const Eigen::Index m = radius.size();
  DiscQpSolution out;
  out.report.method = "projected-gradient";
  Eigen::VectorXd x = Eigen::VectorXd::Zero(3 * m);
  if (!(lipschitz > 0.0)) {  // S = 0: nothing couples the multipliers to the body
    out.x = x;
    out.report.converged = true;
    return out;
  }
  const auto residual = [&](const Eigen::VectorXd& at) {
    Eigen::VectorXd step = at - (s(at) - d);
    project(step, radius);
    const double scale = std::max({d.lpNorm<Eigen::Infinity>(), s_scale * at.lpNorm<Eigen::Infinity>(), 1e-300});
    return (at - step).lpNorm<Eigen::Infinity>() / scale;
  };
  Eigen::VectorXd y = x, previous = x;
  double momentum = 1.0;
  for (int k = 1; k <= options.max_iterations; ++k) {
    previous = x;
    const Eigen::VectorXd sy = s(y);
    if (estimated && y.squaredNorm() > 0.0) lipschitz = std::max(lipschitz, 1.01 * y.dot(sy) / y.squaredNorm());
    const Eigen::VectorXd gradient = sy - d;
    x = y - gradient / lipschitz;
    project(x, radius);
    // Restart where the step goes against the gradient at y: the momentum overshot.
    if (gradient.dot(x - previous) > 0.0) {
      momentum = 1.0;
      y = x;
    } else {
      const double next = 0.5 * (1.0 + std::sqrt(1.0 + 4.0 * momentum * momentum));
      y = x + ((momentum - 1.0) / next) * (x - previous);
      momentum = next;
    }
    if (k % 25 != 0 && k != options.max_iterations) continue;
    const double r = residual(x);
    if (!std::isfinite(r))
      throw NumericalError(fmt::format("Tresca's multiplier problem: the KKT residual is {} after {} steps", r, k));
    out.report.iterations = k;
    out.report.kkt_residual = r;
    if (k % 100 == 0 || r <= options.tolerance) out.report.log.push_back({k, 0, r});
    if (r <= options.tolerance) {
      out.report.converged = true;
      out.x = std::move(x);
      return out;
    }
  }
  throw NumericalError(
      fmt::format("Tresca's multiplier problem: the projected gradient method reached a KKT "
                  "residual of {:.3e} after {} steps, not {:.1e}",
                  out.report.kkt_residual, options.max_iterations, options.tolerance));
}

void check_radius(const Eigen::VectorXd& radius) {
  if ((radius.array() < 0.0).any() || !radius.allFinite())
    throw InputError("Tresca's threshold s must be finite and ≥ 0 at every nodal point of T_{C,H}");
}

}  // namespace

DiscQpSolution solve_disc_qp(const Eigen::MatrixXd& s, const Eigen::VectorXd& d, const Eigen::VectorXd& radius,
                             const DiscQpOptions& options) {
  const Eigen::Index m = radius.size();
  HPC_VERIFY(s.rows() == 3 * m && s.cols() == 3 * m && d.size() == 3 * m, "solve_disc_qp: sizes");
  check_radius(radius);
  const double lipschitz =
      m == 0 ? 0.0 : Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(s, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
  const double s_max = m == 0 ? 0.0 : s.cwiseAbs().maxCoeff();
  return accelerated_projected_gradient(TraceOperator::dense(s), d, radius, lipschitz, s_max, false, options);
}

DiscQpSolution solve_disc_qp_by_products(const TraceOperator& s, const Eigen::VectorXd& d,
                                         const Eigen::VectorXd& radius, const DiscQpOptions& options) {
  const Eigen::Index m = radius.size();
  HPC_VERIFY(s.size() == 3 * m && d.size() == 3 * m, "solve_disc_qp_by_products: sizes");
  check_radius(radius);
  const double lipschitz = 1.01 * largest_eigenvalue_bound(s);
  if (!std::isfinite(lipschitz)) throw NumericalError("Tresca's multiplier problem: S x is not finite");
  return accelerated_projected_gradient(s, d, radius, lipschitz, lipschitz, true, options);
}

}  // namespace hpcontact::contact
