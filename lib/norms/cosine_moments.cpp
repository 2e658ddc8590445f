// Cosine moments of tensor multipliers along one axis, the frequencies of the surface operator,
// and the exponential sum of its inverse square root.
#include "norms/cosine_moments.hpp"

#include <cmath>
#include <complex>
#include <numbers>

#include "basis/lobatto.hpp"
#include "basis/quadrature.hpp"

namespace hpcontact::norms {

namespace {

/// Row k: the k-th derivatives of the Lagrange polynomials of `nodes` at t = `at`, shape
/// (nodes, nodes) (k = 0 … nodes − 1), from their monomial coefficients.
Eigen::MatrixXd lagrange_derivatives(const std::vector<double>& nodes, double at) {
  const auto n = static_cast<Eigen::Index>(nodes.size());
  Eigen::MatrixXd out(n, n);
  for (Eigen::Index a = 0; a < n; ++a) {
    Eigen::VectorXd c = Eigen::VectorXd::Zero(n);  // ℓ_a = Σ c_k t^k
    c(0) = 1.0;
    for (Eigen::Index m = 0, degree = 0; m < n; ++m) {
      if (m == a) continue;
      const double scale = 1.0 / (nodes[a] - nodes[m]);
      for (Eigen::Index k = ++degree; k >= 0; --k) c(k) = scale * ((k > 0 ? c(k - 1) : 0.0) - nodes[m] * c(k));
    }
    for (Eigen::Index order = 0; order < n; ++order) {  // d^order/dt^order Σ c_k t^k at t
      double value = 0.0;
      for (Eigen::Index k = n - 1; k >= order; --k) {
        double falling = 1.0;
        for (Eigen::Index q = 0; q < order; ++q) falling *= static_cast<double>(k - q);
        value = value * at + falling * c(k);
      }
      // (Horner above runs over k from the top; the powers are t^(k − order))
      out(order, a) = value;
    }
  }
  return out;
}

}  // namespace

/// Along axis k: (c_j, ℓ_i) for the modes j < n_modes and the 1-D multiplier functions i =
/// cell · (p_C + 1) + a (cell along the axis, a its local Lagrange index), shape (n_modes,
/// cells · (p_C + 1)). On a cell [c − H/2, c + H/2], cos(ω(x − lo)) = Re e^{iω(c − lo)} e^{iκt},
/// κ = ωH/2, and ∫ ℓ(t) e^{iκt} dt over [−1, 1] is summed exactly by parts,
///     [e^{iκt} Σ_k (−1)^k ℓ^{(k)}(t) / (iκ)^{k+1}]_{−1}^{1},
/// where κ is large enough that its terms do not cancel (κ ≥ max(8, p_C²): the derivatives grow at
/// most like p_C^{2k}); below, by Gauss–Legendre with more points than the phase needs. A cost
/// linear in the modes.
Eigen::MatrixXd cosine_moments(const space::SurfaceMultiplierSpace& multipliers, int axis, int n_modes) {
  const auto& mesh = multipliers.mesh();
  const int cells = mesh.cells_per_axis()[axis], per_axis = multipliers.degree() + 1;
  const double lo = mesh.surface().bounds()[0](axis), length = mesh.surface().bounds()[1](axis) - lo;
  const std::vector<double> nodes = basis::chebyshev_lobatto_points(per_axis);
  const Eigen::MatrixXd at_right = lagrange_derivatives(nodes, 1.0), at_left = lagrange_derivatives(nodes, -1.0);
  const double switch_kappa = std::max(8.0, double(multipliers.degree() * multipliers.degree()));
  const auto& rule = basis::gauss_legendre(per_axis + 24 + static_cast<int>(std::ceil(switch_kappa)));
  std::vector<Eigen::VectorXd> lagrange_at_points;
  for (const double t : rule.points) lagrange_at_points.push_back(basis::lagrange_values(nodes, t));
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(n_modes, cells * per_axis);
  using Complex = std::complex<double>;
  for (int cell = 0; cell < cells; ++cell) {
    // (the cell's bounds along the axis, as T_{C,H} has them: cell (cell, 0) or (0, cell))
    const auto [cell_lo, cell_hi] = mesh.cell_bounds(axis == 0 ? cell : cell * mesh.cells_per_axis()[0]);
    const double width = cell_hi(axis) - cell_lo(axis), centre = 0.5 * (cell_lo(axis) + cell_hi(axis));
    for (int j = 0; j < n_modes; ++j) {
      const double omega = j * std::numbers::pi / length, kappa = 0.5 * omega * width;
      const double norm = j == 0 ? 1.0 / std::sqrt(length) : std::sqrt(2.0 / length);
      auto row = out.block(j, cell * per_axis, 1, per_axis);
      if (kappa < switch_kappa) {
        for (std::size_t q = 0; q < rule.points.size(); ++q) {
          const double x = centre + 0.5 * width * rule.points[q];
          row +=
              (0.5 * width * rule.weights[q] * norm * std::cos(omega * (x - lo))) * lagrange_at_points[q].transpose();
        }
        continue;
      }
      const Complex phase = std::polar(1.0, omega * (centre - lo)), right = std::polar(1.0, kappa),
                    left = std::conj(right), step = 1.0 / Complex(0.0, kappa);
      for (int a = 0; a < per_axis; ++a) {
        Complex integral = 0.0, power = step;  // power = (−1)^k / (iκ)^{k+1}
        for (int k = 0; k < per_axis; ++k, power *= -step)
          integral += power * (right * at_right(k, a) - left * at_left(k, a));
        row(0, a) = 0.5 * width * norm * (phase * integral).real();
      }
    }
  }
  return out;
}

Eigen::VectorXd cosine_frequencies(const space::SurfaceMultiplierSpace& multipliers, int axis, int n_modes) {
  const auto& [lo, hi] = multipliers.mesh().surface().bounds();
  const double length = hi(axis) - lo(axis);
  Eigen::VectorXd out(n_modes);
  for (int j = 0; j < n_modes; ++j) out(j) = std::pow(j * std::numbers::pi / length, 2);
  return out;
}

Eigen::Index tensor_dof(const space::SurfaceMultiplierSpace& multipliers, Eigen::Index i1, Eigen::Index i2) {
  const int per_axis = multipliers.degree() + 1, m1 = multipliers.mesh().cells_per_axis()[0];
  const auto cell = i1 / per_axis + m1 * (i2 / per_axis);
  return cell * per_axis * per_axis + i1 % per_axis + per_axis * (i2 % per_axis);
}

ExponentialSum exponential_sum(double largest) {
  constexpr double step = 0.25, right = 4.0;  // (e^{-e^4} = 2e-24: nothing beyond)
  const double left = 2.0 * std::log(1e-14 * std::sqrt(std::numbers::pi) / 2.0) - std::log(largest);
  const double constant_below = std::log(1e-17 / largest);
  ExponentialSum out{{0.0}, {0.0}};
  for (double v = right; v >= left; v -= step) {
    const double c = step * std::exp(0.5 * v) / std::sqrt(std::numbers::pi);
    if (v < constant_below) {
      out.coefficient[0] += c;
    } else {
      out.coefficient.push_back(c);
      out.rate.push_back(std::exp(v));
    }
  }
  return out;
}

}  // namespace hpcontact::norms
