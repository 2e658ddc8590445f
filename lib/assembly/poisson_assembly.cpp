// Cell-by-cell assembly. Parallelogram cells (DΨ_T = J constant) take their element matrices from
// Kronecker products of 1D Lobatto matrices: O(p⁴) per cell instead of the O(p⁶) of quadrature,
// which is what makes degree 10 affordable (the extension norm's reference). Other cells use tensor
// Gauss rules and dense products K_T = Gxᵀ W Gx + Gyᵀ W Gy, M_T = Φᵀ W Φ.
#include "assembly/poisson_assembly.hpp"

#include <Eigen/LU>
#include <map>
#include <vector>

#include "assembly/cell_values.hpp"
#include "basis/lobatto.hpp"
#include "basis/quadrature.hpp"
#include "mesh/cell_map.hpp"

namespace hpcontact::assembly {
namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

void scatter_matrix(const std::vector<space::LocalShape>& shapes, const Eigen::MatrixXd& local,
                    Triplets& triplets) {
  const int n = static_cast<int>(shapes.size());
  for (int s = 0; s < n; ++s) {
    if (shapes[s].dof < 0) continue;
    for (int t = 0; t < n; ++t)
      if (shapes[t].dof >= 0 && local(s, t) != 0.0)
        triplets.emplace_back(shapes[s].dof, shapes[t].dof, local(s, t));
  }
}

/// 1D matrices of the Lobatto shapes l_0…l_p on [-1, 1]: stiffness ∫ l_a' l_b', mass ∫ l_a l_b,
/// mixed ∫ l_a' l_b (p + 1 Gauss points integrate all three exactly).
struct LineMatrices {
  Eigen::MatrixXd stiffness, mass, mixed;
};

LineMatrices line_matrices(int p) {
  const auto& rule = basis::gauss_legendre(p + 1);
  const auto table = basis::tabulate_lobatto(p, rule.points);
  const Eigen::VectorXd weights = Eigen::Map<const Eigen::VectorXd>(rule.weights.data(), static_cast<Eigen::Index>(rule.weights.size()));
  const auto w = weights.asDiagonal();
  return {table.derivatives.transpose() * w * table.derivatives, table.values.transpose() * w * table.values,
          table.derivatives.transpose() * w * table.values};
}

/// Element matrices of a parallelogram with constant Jacobian J, shape s = sign_s l_{i_s}(ξ) l_{j_s}(η):
///   M_st = det J · M[i_s,i_t] M[j_s,j_t]
///   K_st = det J · (G₀₀ A[i_s,i_t] M[j_s,j_t] + G₁₁ M[i_s,i_t] A[j_s,j_t]
///                  + G₀₁ (C[i_s,i_t] C[j_t,j_s] + C[i_t,i_s] C[j_s,j_t])),   G = J⁻¹ J⁻ᵀ
/// (∇φ = J⁻ᵀ ∇_ξ φ), with A, M, C the line matrices.
void parallelogram_matrices(const std::vector<space::LocalShape>& shapes, const LineMatrices& line,
                            const Eigen::Matrix2d& jacobian, Eigen::MatrixXd* stiffness, Eigen::MatrixXd* mass) {
  const int n = static_cast<int>(shapes.size());
  const double det = jacobian.determinant();
  const Eigen::Matrix2d inverse = jacobian.inverse();
  const Eigen::Matrix2d g = inverse * inverse.transpose();
  const auto &a = line.stiffness, &m = line.mass, &c = line.mixed;
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
}

}  // namespace

VolumeMatrices assemble_volume_matrices(const space::H1Space& space,
                                        const VolumeMatrixRequest& request) {
  Triplets stiffness, mass;
  const int n = space.n_dofs();
  std::map<int, LineMatrices> lines;  // per degree
  Eigen::MatrixXd local_stiffness, local_mass;
  for (int c = 0; c < space.mesh().n_cells(); ++c) {
    const mesh::CellMap map(space.mesh(), c);
    if (request.kronecker_parallelograms && map.is_parallelogram()) {
      const int p = space.cell_degree(c);
      auto line = lines.find(p);
      if (line == lines.end()) line = lines.emplace(p, line_matrices(p)).first;
      parallelogram_matrices(space.cell_shapes(c), line->second, map.jacobian(0.0, 0.0),
                             request.stiffness ? &local_stiffness : nullptr, request.mass ? &local_mass : nullptr);
      if (request.stiffness) scatter_matrix(space.cell_shapes(c), local_stiffness, stiffness);
      if (request.mass) scatter_matrix(space.cell_shapes(c), local_mass, mass);
      continue;
    }
    const auto& rule = basis::gauss_legendre(cell_quadrature_points(space.cell_degree(c)));
    const CellValues cell = tabulate_cell(space, c, rule.points, rule.points);
    Eigen::VectorXd weights(cell.jacobians.size());
    for (std::size_t b = 0; b < rule.points.size(); ++b)
      for (std::size_t a = 0; a < rule.points.size(); ++a) {
        const auto q = a + rule.points.size() * b;
        weights(q) = rule.weights[a] * rule.weights[b] * cell.jacobians(q);
      }
    const auto w = weights.asDiagonal();
    if (request.stiffness) {
      local_stiffness = cell.grad_x.transpose() * w * cell.grad_x + cell.grad_y.transpose() * w * cell.grad_y;
      scatter_matrix(space.cell_shapes(c), local_stiffness, stiffness);
    }
    if (request.mass) {
      local_mass = cell.values.transpose() * w * cell.values;
      scatter_matrix(space.cell_shapes(c), local_mass, mass);
    }
  }
  VolumeMatrices out;
  if (request.stiffness) {
    out.stiffness.resize(n, n);
    out.stiffness.setFromTriplets(stiffness.begin(), stiffness.end());
  }
  if (request.mass) {
    out.mass.resize(n, n);
    out.mass.setFromTriplets(mass.begin(), mass.end());
  }
  return out;
}

Eigen::VectorXd assemble_volume_load(const space::H1Space& space,
                                     const std::function<double(const mesh::Point&)>& f) {
  Eigen::VectorXd load = Eigen::VectorXd::Zero(space.n_dofs());
  for (int c = 0; c < space.mesh().n_cells(); ++c) {
    // Two extra points beyond the matrices: f is general data, not a polynomial.
    const auto& rule = basis::gauss_legendre(cell_quadrature_points(space.cell_degree(c)) + 2);
    const CellValues cell = tabulate_cell(space, c, rule.points, rule.points);
    Eigen::VectorXd weighted_f(cell.jacobians.size());
    for (std::size_t b = 0; b < rule.points.size(); ++b)
      for (std::size_t a = 0; a < rule.points.size(); ++a) {
        const auto q = a + rule.points.size() * b;
        weighted_f(q) = rule.weights[a] * rule.weights[b] * cell.jacobians(q) *
                        f(mesh::Point(cell.points(q, 0), cell.points(q, 1)));
      }
    const Eigen::VectorXd local = cell.values.transpose() * weighted_f;
    const auto& shapes = space.cell_shapes(c);
    for (std::size_t s = 0; s < shapes.size(); ++s)
      if (shapes[s].dof >= 0) load(shapes[s].dof) += local(s);
  }
  return load;
}

Eigen::VectorXd assemble_boundary_load(
    const space::H1Space& space, const std::set<mesh::BoundaryPart>& parts,
    const std::function<double(const mesh::Point& x, const mesh::Point& normal)>& g) {
  const auto& mesh = space.mesh();
  Eigen::VectorXd load = Eigen::VectorXd::Zero(space.n_dofs());
  for (int e : mesh.boundary_edges()) {
    if (!parts.contains(mesh.edge_part(e))) continue;
    const int c = mesh.edge_cells(e)[0];
    const int local_edge = mesh.local_edge_of(e, 0);
    const auto& rule = basis::gauss_legendre(space.cell_degree(c) + 4);
    const auto [xi, eta] = edge_reference_points(local_edge, rule.points);
    const CellValues values = tabulate_cell(space, c, xi, eta);
    const mesh::Point normal = mesh.boundary_normal(e);
    // Straight edges: ds = (|edge| / 2) dt.
    const double half_length = 0.5 * mesh.edge_length(e);
    Eigen::VectorXd weighted_g(rule.points.size());
    for (std::size_t q = 0; q < rule.points.size(); ++q)
      weighted_g(q) = rule.weights[q] * half_length *
                      g(mesh::Point(values.points(q, 0), values.points(q, 1)), normal);
    const Eigen::VectorXd local = values.values.transpose() * weighted_g;
    const auto& shapes = space.cell_shapes(c);
    for (std::size_t s = 0; s < shapes.size(); ++s)
      if (shapes[s].dof >= 0) load(shapes[s].dof) += local(s);
  }
  return load;
}

}  // namespace hpcontact::assembly
