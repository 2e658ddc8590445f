// The interpolation norm on a flat rectangular Γ_C from cosine moments of the tensor multipliers.
#include "norms/surface_interpolation_gram.hpp"

#include <cmath>

#include "core/error.hpp"
#include "norms/cosine_moments.hpp"

namespace hpcontact::norms {

namespace {

/// Row j: the products P(j, a) P(j, b) at column a + n b (n = P.cols()).
Eigen::MatrixXd row_products(const Eigen::MatrixXd& p) {
  const auto n = p.cols();
  Eigen::MatrixXd out(p.rows(), n * n);
  for (Eigen::Index b = 0; b < n; ++b)
    for (Eigen::Index a = 0; a < n; ++a) out.col(a + n * b) = p.col(a).cwiseProduct(p.col(b));
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
  const Eigen::MatrixXd p1 = cosine_moments(multipliers, 0, modes[0]), p2 = cosine_moments(multipliers, 1, modes[1]);
  const auto n1 = p1.cols(), n2 = p2.cols();
  // (jπ/L)² along each axis: the surface operator's eigenvalues are 1 + f1_j + f2_k
  const Eigen::VectorXd f1 = cosine_frequencies(multipliers, 0, modes[0]),
                        f2 = cosine_frequencies(multipliers, 1, modes[1]);
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
  const auto dof = [&](Eigen::Index i1, Eigen::Index i2) { return tensor_dof(multipliers, i1, i2); };
  Eigen::MatrixXd gram(multipliers.n_dofs(), multipliers.n_dofs());
  for (Eigen::Index d = 0; d < n2; ++d)
    for (Eigen::Index c = 0; c < n2; ++c)
      for (Eigen::Index b = 0; b < n1; ++b)
        for (Eigen::Index a = 0; a < n1; ++a) gram(dof(a, c), dof(b, d)) = tensor(a + n1 * b, c + n2 * d);
  return gram;
}

std::array<int, 2> surface_gram_modes(const space::SurfaceMultiplierSpace& multipliers, int level) {
  const auto& cells = multipliers.mesh().cells_per_axis();
  const int per_axis = multipliers.degree() + 1, factor = 8 << level;
  return {factor * per_axis * cells[0], factor * per_axis * cells[1]};
}

GramLadder surface_interpolation_gram_ladder(const space::SurfaceMultiplierSpace& multipliers) {
  return GramLadder(
      [&multipliers](int level, bool*) {
        return surface_interpolation_gram(multipliers, surface_gram_modes(multipliers, level));
      },
      kSurfaceGramTopLevel);
}

}  // namespace hpcontact::norms
