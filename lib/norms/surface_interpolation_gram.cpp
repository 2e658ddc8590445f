// The interpolation norm on a flat rectangular Γ_C from cosine moments of the tensor multipliers.
#include "norms/surface_interpolation_gram.hpp"

#include <cmath>
#include <numbers>

#include "basis/lobatto.hpp"
#include "basis/quadrature.hpp"
#include "core/error.hpp"

namespace hpcontact::norms {

namespace {

/// Along axis k: (c_j, ℓ_i) for the modes j < n_modes and the 1-D multiplier functions i =
/// cell · (p_C + 1) + a (cell along the axis, a its local Lagrange index), shape (n_modes,
/// cells · (p_C + 1)). Gauss–Legendre per cell with enough points for the cosine's oscillation.
Eigen::MatrixXd cosine_moments(const space::SurfaceMultiplierSpace& multipliers, int axis, int n_modes) {
  const auto& mesh = multipliers.mesh();
  const int cells = mesh.cells_per_axis()[axis], per_axis = multipliers.degree() + 1;
  const double lo = mesh.surface().bounds()[0](axis), length = mesh.surface().bounds()[1](axis) - lo;
  const std::vector<double> nodes = basis::chebyshev_lobatto_points(per_axis);
  // Composite Gauss–Legendre: the phase of the last mode changes by π n_modes / cells over a cell,
  // at most 4 radians over each sub-interval, where 20 points are exact to round-off for the
  // product of the cosine and a Lagrange polynomial. (GSL's tables of many points are accurate
  // to about 1e-10 only.)
  const int pieces = 1 + static_cast<int>(std::ceil(std::numbers::pi * n_modes / (4.0 * cells)));
  const auto& rule = basis::gauss_legendre(std::max(20, multipliers.degree() + 12));
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(n_modes, cells * per_axis);
  for (int cell = 0; cell < cells; ++cell) {
    // (the cell's bounds along the axis, as T_{C,H} has them: cell (cell, 0) or (0, cell))
    const auto [cell_lo, cell_hi] = mesh.cell_bounds(axis == 0 ? cell : cell * mesh.cells_per_axis()[0]);
    const double a = cell_lo(axis), b = cell_hi(axis);
    for (int piece = 0; piece < pieces; ++piece)
      for (std::size_t q = 0; q < rule.points.size(); ++q) {
        const double t = -1.0 + (2.0 * piece + rule.points[q] + 1.0) / pieces;  // in the cell's [-1, 1]
        const double weight = 0.5 * (b - a) * rule.weights[q] / pieces;
        const double x = a + 0.5 * (t + 1.0) * (b - a);
        const Eigen::VectorXd lagrange = basis::lagrange_values(nodes, t);
        for (int j = 0; j < n_modes; ++j) {
          const double mode = j == 0 ? 1.0 / std::sqrt(length)
                                     : std::sqrt(2.0 / length) * std::cos(j * std::numbers::pi * (x - lo) / length);
          out.block(j, cell * per_axis, 1, per_axis) += (weight * mode) * lagrange.transpose();
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

Eigen::MatrixXd surface_interpolation_gram(const space::SurfaceMultiplierSpace& multipliers, std::array<int, 2> modes) {
  HPC_VERIFY(modes[0] >= 1 && modes[1] >= 1, "surface_interpolation_gram: at least one mode per axis");
  const auto& mesh = multipliers.mesh();
  const auto& [lo, hi] = mesh.surface().bounds();
  const Eigen::MatrixXd p1 = cosine_moments(multipliers, 0, modes[0]), p2 = cosine_moments(multipliers, 1, modes[1]);
  Eigen::MatrixXd weights(modes[0], modes[1]);
  for (int k = 0; k < modes[1]; ++k)
    for (int j = 0; j < modes[0]; ++j) {
      const double f1 = j * std::numbers::pi / (hi(0) - lo(0)), f2 = k * std::numbers::pi / (hi(1) - lo(1));
      weights(j, k) = 1.0 / std::sqrt(1.0 + f1 * f1 + f2 * f2);
    }
  // Σ_{j,k} P1(j,a)P1(j,b) w(j,k) P2(k,c)P2(k,d) as two products: by (a, b) rows and (c, d) columns.
  const Eigen::MatrixXd tensor = row_products(p1).transpose() * (weights * row_products(p2));
  const int per_axis = multipliers.degree() + 1, m1 = mesh.cells_per_axis()[0];
  const auto n1 = p1.cols(), n2 = p2.cols();
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
