// G x and T x ≈ G⁻¹ x of the interpolation norm on a grid T_{C,H} by one-dimensional moments.
#include "norms/surface_gram_products.hpp"

#include <Eigen/LU>
#include <cmath>

#include "basis/lobatto.hpp"
#include "basis/quadrature.hpp"
#include "core/error.hpp"
#include "norms/cosine_moments.hpp"

namespace hpcontact::norms {

namespace {

/// 1-D functions along each axis: (p_C + 1) per cell.
std::array<Eigen::Index, 2> functions_per_axis(const space::SurfaceMultiplierSpace& multipliers) {
  const auto& cells = multipliers.mesh().cells_per_axis();
  return {Eigen::Index(multipliers.degree() + 1) * cells[0], Eigen::Index(multipliers.degree() + 1) * cells[1]};
}

Eigen::MatrixXd as_tensor(const space::SurfaceMultiplierSpace& multipliers, const Eigen::VectorXd& x) {
  const auto [n1, n2] = functions_per_axis(multipliers);
  Eigen::MatrixXd out(n1, n2);
  for (Eigen::Index i2 = 0; i2 < n2; ++i2)
    for (Eigen::Index i1 = 0; i1 < n1; ++i1) out(i1, i2) = x(tensor_dof(multipliers, i1, i2));
  return out;
}

Eigen::VectorXd as_vector(const space::SurfaceMultiplierSpace& multipliers, const Eigen::MatrixXd& tensor) {
  Eigen::VectorXd out(multipliers.n_dofs());
  for (Eigen::Index i2 = 0; i2 < tensor.cols(); ++i2)
    for (Eigen::Index i1 = 0; i1 < tensor.rows(); ++i1) out(tensor_dof(multipliers, i1, i2)) = tensor(i1, i2);
  return out;
}

/// The 1-D multipliers' mass matrix along `axis`, inverted: block diagonal, one block per cell.
Eigen::MatrixXd inverse_mass(const space::SurfaceMultiplierSpace& multipliers, int axis) {
  const auto& mesh = multipliers.mesh();
  const int per_axis = multipliers.degree() + 1, cells = mesh.cells_per_axis()[axis];
  const std::vector<double> nodes = basis::chebyshev_lobatto_points(per_axis);
  const auto& rule = basis::gauss_legendre(per_axis + 1);
  Eigen::MatrixXd reference = Eigen::MatrixXd::Zero(per_axis, per_axis);
  for (std::size_t q = 0; q < rule.points.size(); ++q) {
    const Eigen::VectorXd values = basis::lagrange_values(nodes, rule.points[q]);
    reference += rule.weights[q] * values * values.transpose();
  }
  const Eigen::MatrixXd reference_inverse = reference.inverse();
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(Eigen::Index(per_axis) * cells, Eigen::Index(per_axis) * cells);
  for (int cell = 0; cell < cells; ++cell) {
    const auto [lo, hi] = mesh.cell_bounds(axis == 0 ? cell : cell * mesh.cells_per_axis()[0]);
    out.block(cell * per_axis, cell * per_axis, per_axis, per_axis) = (2.0 / (hi(axis) - lo(axis))) * reference_inverse;
  }
  return out;
}

/// Terms e^{-s f_j} below e^{-40} ≈ 4e-18 are dropped: relative 1e-17 of the constant term.
constexpr double kNegligibleExponent = 40.0;
/// W's memory above which the exponential sum is taken whatever the operation counts (200 MB).
constexpr double kLargestWeightEntries = 2.5e7;

}  // namespace

SurfaceGramProducts::SurfaceGramProducts(const space::SurfaceMultiplierSpace& multipliers, std::array<int, 2> modes,
                                         GramSummation summation)
    : multipliers_(&multipliers), size_(multipliers.n_dofs()) {
  HPC_VERIFY(multipliers.mesh().is_grid(), "SurfaceGramProducts: T_{C,H} must be a grid");
  HPC_VERIFY(modes[0] >= 1 && modes[1] >= 1, "SurfaceGramProducts: at least one mode per axis");
  const Eigen::MatrixXd p1 = cosine_moments(multipliers, 0, modes[0]), p2 = cosine_moments(multipliers, 1, modes[1]);
  const Eigen::VectorXd f1 = cosine_frequencies(multipliers, 0, modes[0]),
                        f2 = cosine_frequencies(multipliers, 1, modes[1]);
  const double n1 = double(p1.cols()), n2 = double(p2.cols()), m1 = modes[0], m2 = modes[1];
  const ExponentialSum sum = exponential_sum(1.0 + f1(modes[0] - 1) + f2(modes[1] - 1));
  const double direct_cost = 2.0 * (m1 * n1 * n2 + m1 * m2 * n2);
  const double sum_cost = 2.0 * double(sum.rate.size()) * (n1 * n1 * n2 + n1 * n2 * n2);
  const bool direct =
      summation == GramSummation::direct ||
      (summation == GramSummation::cheaper && direct_cost <= sum_cost && m1 * m2 <= kLargestWeightEntries);
  if (direct) {
    p1_ = p1;
    p2_ = p2;
    weights_.resize(modes[0], modes[1]);
    for (int k = 0; k < modes[1]; ++k)
      for (int j = 0; j < modes[0]; ++j) weights_(j, k) = 1.0 / std::sqrt(1.0 + f1(j) + f2(k));
    return;
  }
  // A_r = Pᵀ diag(e^{-s f}) P over the modes whose factor is not negligible (f ascends).
  const auto damped = [](const Eigen::MatrixXd& p, const Eigen::VectorXd& f, double s) {
    Eigen::Index kept = 0;
    while (kept < f.size() && s * f(kept) <= kNegligibleExponent) ++kept;
    const Eigen::VectorXd damping = (-s * f.head(kept).array()).exp().matrix();
    return Eigen::MatrixXd(p.topRows(kept).transpose() * damping.asDiagonal() * p.topRows(kept));
  };
  for (std::size_t r = 0; r < sum.rate.size(); ++r) {
    const double s = sum.rate[r];
    along_1_.push_back(sum.coefficient[r] * std::exp(-s) * damped(p1, f1, s));
    along_2_.push_back(damped(p2, f2, s));
  }
}

Eigen::VectorXd SurfaceGramProducts::operator()(const Eigen::VectorXd& x) const {
  HPC_VERIFY(x.size() == size_, "SurfaceGramProducts: x has the wrong length");
  const Eigen::MatrixXd tensor = as_tensor(*multipliers_, x);
  if (!by_exponential_sum()) {
    const Eigen::MatrixXd moments = (p1_ * tensor) * p2_.transpose();
    return as_vector(*multipliers_, p1_.transpose() * moments.cwiseProduct(weights_) * p2_);
  }
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(tensor.rows(), tensor.cols());
  for (std::size_t r = 0; r < along_1_.size(); ++r) out.noalias() += along_1_[r] * tensor * along_2_[r].transpose();
  return as_vector(*multipliers_, out);
}

SurfaceGramPreconditioner::SurfaceGramPreconditioner(const space::SurfaceMultiplierSpace& multipliers)
    : multipliers_(&multipliers) {
  HPC_VERIFY(multipliers.mesh().is_grid(), "SurfaceGramPreconditioner: T_{C,H} must be a grid");
  const auto [n1, n2] = functions_per_axis(multipliers);
  const int modes_1 = 8 * static_cast<int>(n1), modes_2 = 8 * static_cast<int>(n2);
  q1_ = cosine_moments(multipliers, 0, modes_1) * inverse_mass(multipliers, 0);
  q2_ = cosine_moments(multipliers, 1, modes_2) * inverse_mass(multipliers, 1);
  const Eigen::VectorXd f1 = cosine_frequencies(multipliers, 0, modes_1),
                        f2 = cosine_frequencies(multipliers, 1, modes_2);
  root_weights_.resize(modes_1, modes_2);
  for (int k = 0; k < modes_2; ++k)
    for (int j = 0; j < modes_1; ++j) root_weights_(j, k) = std::sqrt(1.0 + f1(j) + f2(k));
}

Eigen::VectorXd SurfaceGramPreconditioner::operator()(const Eigen::VectorXd& x) const {
  const Eigen::MatrixXd moments = (q1_ * as_tensor(*multipliers_, x)) * q2_.transpose();
  return as_vector(*multipliers_, q1_.transpose() * moments.cwiseProduct(root_weights_) * q2_);
}

}  // namespace hpcontact::norms
