// The interpolation norm on a flat rectangular Γ_C from cosine moments of the tensor multipliers.
#include "norms/surface_interpolation_gram.hpp"

#include <cmath>
#include <complex>
#include <numbers>

#include "basis/lobatto.hpp"
#include "basis/quadrature.hpp"
#include "core/error.hpp"

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

/// Row j: the products P(j, a) P(j, b) at column a + n b (n = P.cols()).
Eigen::MatrixXd row_products(const Eigen::MatrixXd& p) {
  const auto n = p.cols();
  Eigen::MatrixXd out(p.rows(), n * n);
  for (Eigen::Index b = 0; b < n; ++b)
    for (Eigen::Index a = 0; a < n; ++a) out.col(a + n * b) = p.col(a).cwiseProduct(p.col(b));
  return out;
}

}  // namespace

namespace {

/// The weights (1 + a_j + b_k)^{-1/2} as Σ_r c_r e^{-s_r} e^{-s_r a_j} e^{-s_r b_k}: the trapezoidal
/// rule, step 1/4, for x^{-1/2} = π^{-1/2} ∫ e^{v/2 − x e^v} dv (x = 1 + a + b ∈ [1, largest]).
/// The integrand is analytic in the strip |Im v| < π/2, so the rule's relative error is about
/// 3.3 e^{-2π·1.2·4} ≈ 2.6e-13 at most (measured: 1e-14); the left end is cut where the neglected tail 2 e^{v/2}/√π is
/// 1e-14 of largest^{-1/2}; the terms with largest · e^v < 1e-17 have e^{-x e^v} = 1 to round-off and are summed into
/// one constant term (s = 0).
struct ExponentialSum {
  std::vector<double> coefficient, rate;  ///< c_r, s_r
};
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

/// Pᵀ diag(e^{-s f_j}) P as a column (entry a + n b), f_j = (jπ/L)².
Eigen::VectorXd damped_products(const Eigen::MatrixXd& p, const Eigen::VectorXd& frequencies, double s) {
  const Eigen::VectorXd damping = (-s * frequencies.array()).exp().matrix();
  const Eigen::MatrixXd product = p.transpose() * damping.asDiagonal() * p;
  return Eigen::Map<const Eigen::VectorXd>(product.data(), product.size());
}

}  // namespace

Eigen::MatrixXd surface_interpolation_gram(const space::SurfaceMultiplierSpace& multipliers, std::array<int, 2> modes,
                                           GramSummation summation) {
  HPC_VERIFY(modes[0] >= 1 && modes[1] >= 1, "surface_interpolation_gram: at least one mode per axis");
  const auto& mesh = multipliers.mesh();
  const auto& [lo, hi] = mesh.surface().bounds();
  const Eigen::MatrixXd p1 = cosine_moments(multipliers, 0, modes[0]), p2 = cosine_moments(multipliers, 1, modes[1]);
  const auto n1 = p1.cols(), n2 = p2.cols();
  // (jπ/L)² along each axis: the surface operator's eigenvalues are 1 + f1_j + f2_k
  Eigen::VectorXd f1(modes[0]), f2(modes[1]);
  for (int j = 0; j < modes[0]; ++j) f1(j) = std::pow(j * std::numbers::pi / (hi(0) - lo(0)), 2);
  for (int k = 0; k < modes[1]; ++k) f2(k) = std::pow(k * std::numbers::pi / (hi(1) - lo(1)), 2);
  // tensor(a + n1 b, c + n2 d) = Σ_{j,k} P1(j,a)P1(j,b) w(j,k) P2(k,c)P2(k,d)
  Eigen::MatrixXd tensor;
  const ExponentialSum sum = exponential_sum(1.0 + f1(modes[0] - 1) + f2(modes[1] - 1));
  const double terms = static_cast<double>(sum.rate.size());
  const double direct_cost = double(modes[0]) * modes[1] * n2 * n2 + double(n1) * n1 * n2 * n2 * modes[0];
  const double sum_cost = terms * (double(modes[0]) * n1 * n1 + double(modes[1]) * n2 * n2 + double(n1) * n1 * n2 * n2);
  if (summation == GramSummation::direct || (summation == GramSummation::cheaper && direct_cost <= sum_cost)) {
    // Two products: by (a, b) rows and (c, d) columns.
    Eigen::MatrixXd weights(modes[0], modes[1]);
    for (int k = 0; k < modes[1]; ++k)
      for (int j = 0; j < modes[0]; ++j) weights(j, k) = 1.0 / std::sqrt(1.0 + f1(j) + f2(k));
    tensor = row_products(p1).transpose() * (weights * row_products(p2));
  } else {
    // A sum of R Kronecker products: e^{-s(1 + f1 + f2)} = e^{-s} e^{-s f1} e^{-s f2}.
    const auto r = static_cast<Eigen::Index>(sum.rate.size());
    Eigen::MatrixXd along_1(n1 * n1, r), along_2(n2 * n2, r);
    for (Eigen::Index t = 0; t < r; ++t) {
      const double s = sum.rate[static_cast<std::size_t>(t)];
      along_1.col(t) = (sum.coefficient[static_cast<std::size_t>(t)] * std::exp(-s)) * damped_products(p1, f1, s);
      along_2.col(t) = damped_products(p2, f2, s);
    }
    tensor = along_1 * along_2.transpose();
  }
  const int per_axis = multipliers.degree() + 1, m1 = mesh.cells_per_axis()[0];
  const auto dof = [&](Eigen::Index i1, Eigen::Index i2) {
    const auto cell = i1 / per_axis + m1 * (i2 / per_axis);
    return cell * per_axis * per_axis + i1 % per_axis + per_axis * (i2 % per_axis);
  };
  Eigen::MatrixXd gram(multipliers.n_dofs(), multipliers.n_dofs());
  for (Eigen::Index d = 0; d < n2; ++d)
    for (Eigen::Index c = 0; c < n2; ++c)
      for (Eigen::Index b = 0; b < n1; ++b)
        for (Eigen::Index a = 0; a < n1; ++a) gram(dof(a, c), dof(b, d)) = tensor(a + n1 * b, c + n2 * d);
  return gram;
}

GramLadder surface_interpolation_gram_ladder(const space::SurfaceMultiplierSpace& multipliers) {
  return GramLadder(
      [&multipliers](int level, bool*) {
        const auto& cells = multipliers.mesh().cells_per_axis();
        const int per_axis = multipliers.degree() + 1, factor = 8 << level;
        return surface_interpolation_gram(multipliers, {factor * per_axis * cells[0], factor * per_axis * cells[1]});
      },
      5);
}

}  // namespace hpcontact::norms
