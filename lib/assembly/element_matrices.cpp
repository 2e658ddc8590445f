// Parallelogram cells (DΨ_T = J constant) take their element matrices from Kronecker products of
// 1D Lobatto matrices: O(p⁴) per cell instead of the O(p⁶) of quadrature, which is what makes
// degree 10 affordable (the extension norm's reference). Other cells (triangles among them) use
// their reference cell's Gauss rule and dense products K_T = Gxᵀ W Gx + Gyᵀ W Gy, M_T = Φᵀ W Φ.
#include "assembly/element_matrices.hpp"

#include <Eigen/LU>
#include <array>

#include "assembly/cell_values.hpp"
#include "basis/lobatto.hpp"
#include "basis/quadrature.hpp"
#include "mesh/cell_map.hpp"

namespace hpcontact::assembly {
namespace {

// The cell's shapes at its Gauss points and the weights w_q · det DΨ_T there.
std::pair<CellValues, Eigen::VectorXd> quadrature_values(const space::H1Space& space, int cell) {
  const CellQuadrature rule = cell_rule(space, cell);
  CellValues values = tabulate_cell(space, cell, rule.points);
  Eigen::VectorXd weights(values.jacobians.size());
  for (int q = 0; q < rule.points.size(); ++q) weights(q) = rule.weights[q] * values.jacobians(q);
  return {std::move(values), std::move(weights)};
}

}  // namespace

ElementMatrices::ElementMatrices(const space::H1Space& space, bool kronecker_parallelograms)
    : space_(&space), kronecker_parallelograms_(kronecker_parallelograms) {}

/// 1D matrices of the Lobatto shapes l_0…l_p on [-1, 1]: stiffness ∫ l_a' l_b', mass ∫ l_a l_b,
/// mixed ∫ l_a' l_b (p + 1 Gauss points integrate all three exactly).
const ElementMatrices::LineMatrices& ElementMatrices::line(int degree) {
  auto found = lines_.find(degree);
  if (found != lines_.end()) return found->second;
  const auto& rule = basis::gauss_legendre(degree + 1);
  const auto table = basis::tabulate_lobatto(degree, rule.points);
  const Eigen::VectorXd weights =
      Eigen::Map<const Eigen::VectorXd>(rule.weights.data(), static_cast<Eigen::Index>(rule.weights.size()));
  const auto w = weights.asDiagonal();
  return lines_
      .emplace(degree, LineMatrices{table.derivatives.transpose() * w * table.derivatives,
                                    table.values.transpose() * w * table.values,
                                    table.derivatives.transpose() * w * table.values})
      .first->second;
}

bool ElementMatrices::constant_jacobian(int cell, Eigen::Matrix2d& jacobian) const {
  if (!kronecker_parallelograms_) return false;
  const mesh::CellMap map(space_->mesh(), cell);
  if (map.type() != mesh::CellType::quadrilateral || !map.is_affine()) return false;
  jacobian = map.jacobian(0.0, 0.0);
  return true;
}

void ElementMatrices::compute(int cell, Eigen::MatrixXd* stiffness, Eigen::MatrixXd* mass) {
  const auto& shapes = space_->cell_shapes(cell);
  const int n = static_cast<int>(shapes.size());
  Eigen::Matrix2d jacobian;
  if (constant_jacobian(cell, jacobian)) {
    // Shape s = sign_s l_{i_s}(ξ) l_{j_s}(η), ∇φ = J⁻ᵀ ∇_ξ φ, G = J⁻¹ J⁻ᵀ, A, M, C the line matrices:
    //   M_st = det J · M[i_s,i_t] M[j_s,j_t]
    //   K_st = det J · (G₀₀ A[i_s,i_t] M[j_s,j_t] + G₁₁ M[i_s,i_t] A[j_s,j_t]
    //                   + G₀₁ (C[i_s,i_t] C[j_t,j_s] + C[i_t,i_s] C[j_s,j_t]))
    const double det = jacobian.determinant();
    const Eigen::Matrix2d inverse = jacobian.inverse();
    const Eigen::Matrix2d g = inverse * inverse.transpose();
    const auto& lines = line(space_->cell_degree(cell));
    const auto &a = lines.stiffness, &m = lines.mass, &c = lines.mixed;
    if (stiffness) stiffness->resize(n, n);
    if (mass) mass->resize(n, n);
    for (int t = 0; t < n; ++t) {
      const int it = shapes[t].i, jt = shapes[t].j;
      for (int s = 0; s < n; ++s) {
        const int is = shapes[s].i, js = shapes[s].j;
        const double scale = det * shapes[s].sign * shapes[t].sign;
        if (stiffness)
          (*stiffness)(s, t) = scale * (g(0, 0) * a(is, it) * m(js, jt) + g(1, 1) * m(is, it) * a(js, jt) +
                                        g(0, 1) * (c(is, it) * c(jt, js) + c(it, is) * c(js, jt)));
        if (mass) (*mass)(s, t) = scale * m(is, it) * m(js, jt);
      }
    }
    return;
  }
  const auto [values, weights] = quadrature_values(*space_, cell);
  const auto w = weights.asDiagonal();
  if (stiffness)
    *stiffness = values.grad_x.transpose() * w * values.grad_x + values.grad_y.transpose() * w * values.grad_y;
  if (mass) *mass = values.values.transpose() * w * values.values;
}

ElementMatrices::Directional ElementMatrices::directional(int cell) {
  const auto& shapes = space_->cell_shapes(cell);
  const int n = static_cast<int>(shapes.size());
  Eigen::Matrix2d jacobian;
  if (constant_jacobian(cell, jacobian)) {
    // ∂_a φ = Σ_k T_ak ∂_k φ̂ with T = J⁻ᵀ, so D_ab = det J · Σ_kl T_ak T_bl R_kl with the reference
    // products R_ξξ = A⊗M, R_ηη = M⊗A, R_ξη[s,t] = C[i_s,i_t] C[j_t,j_s], R_ηξ[s,t] = C[i_t,i_s] C[j_s,j_t].
    const double det = jacobian.determinant();
    const Eigen::Matrix2d t = jacobian.inverse().transpose();
    const auto& lines = line(space_->cell_degree(cell));
    const auto &a = lines.stiffness, &m = lines.mass, &c = lines.mixed;
    Directional out{Eigen::MatrixXd(n, n), Eigen::MatrixXd(n, n), Eigen::MatrixXd(n, n), Eigen::MatrixXd(n, n)};
    std::array<Eigen::MatrixXd*, 4> blocks{&out.xx, &out.xy, &out.yx, &out.yy};
    for (int q = 0; q < n; ++q) {
      const int iq = shapes[q].i, jq = shapes[q].j;
      for (int s = 0; s < n; ++s) {
        const int is = shapes[s].i, js = shapes[s].j;
        const double scale = det * shapes[s].sign * shapes[q].sign;
        const Eigen::Matrix2d r{{a(is, iq) * m(js, jq), c(is, iq) * c(jq, js)},
                                {c(iq, is) * c(js, jq), m(is, iq) * a(js, jq)}};
        const Eigen::Matrix2d d = t * r * t.transpose();  // d(a, b) = Σ_kl T_ak R_kl T_bl
        for (int k = 0; k < 4; ++k) (*blocks[k])(s, q) = scale * d(k / 2, k % 2);
      }
    }
    return out;
  }
  const auto [values, weights] = quadrature_values(*space_, cell);
  const auto w = weights.asDiagonal();
  return {values.grad_x.transpose() * w * values.grad_x, values.grad_x.transpose() * w * values.grad_y,
          values.grad_y.transpose() * w * values.grad_x, values.grad_y.transpose() * w * values.grad_y};
}

}  // namespace hpcontact::assembly
