// Tabulation of hexahedral Lobatto shapes at mapped tensor Gauss points and of tetrahedral shapes
// at mapped collapsed Gauss points.
#include "assembly/solid_cell_values.hpp"

#include <fmt/format.h>

#include <Eigen/LU>
#include <cmath>

#include "basis/lobatto.hpp"
#include "basis/quadrature.hpp"
#include "basis/tetrahedron_basis.hpp"
#include "core/error.hpp"
#include "space/solid_shape_values.hpp"

namespace hpcontact::assembly {

namespace {

SolidCellValues tetrahedron_values(const space::SolidH1Space& space, int cell, int points_per_axis) {
  const mesh::SolidMesh& mesh = space.mesh();
  const basis::QuadratureRule3D& rule = basis::collapsed_tetrahedron_rule(points_per_axis);
  const auto shapes = space.cell_shapes(cell);
  const int n_shapes = static_cast<int>(shapes.size()), n_points = static_cast<int>(rule.weights.size());
  SolidCellValues out;
  out.values.resize(n_shapes, n_points);
  for (auto& gradient : out.gradients) gradient.resize(n_shapes, n_points);
  out.weights.resize(n_points);
  out.points.resize(n_points);
  // Affine: one Jacobian; the ascending vertex order may make its determinant negative.
  const Eigen::Matrix3d jacobian = mesh.jacobian(cell, Eigen::Vector3d::Zero());
  const double volume_factor = std::abs(jacobian.determinant());
  const Eigen::Matrix3d inverse_transpose = jacobian.inverse().transpose();
  for (int q = 0; q < n_points; ++q) {
    const Eigen::Vector3d xi(rule.xi[q], rule.eta[q], rule.zeta[q]);
    out.weights(q) = rule.weights[q] * volume_factor;
    out.points[q] = mesh.map(cell, xi);
    const basis::TetrahedronShapes all(space.cell_degree(cell), xi(0), xi(1), xi(2));
    for (int s = 0; s < n_shapes; ++s) {
      const basis::SolidShapeValue& mode = space::tetrahedron_mode(all, shapes[s]);
      out.values(s, q) = mode.v;
      const Eigen::Vector3d gradient = inverse_transpose * Eigen::Vector3d(mode.d[0], mode.d[1], mode.d[2]);
      for (int d = 0; d < 3; ++d) out.gradients[d](s, q) = gradient(d);
    }
  }
  return out;
}

}  // namespace

SolidCellValues solid_cell_values(const space::SolidH1Space& space, int cell, int points_per_axis) {
  const mesh::SolidMesh& mesh = space.mesh();
  if (mesh.is_tetrahedral()) return tetrahedron_values(space, cell, points_per_axis);
  const int p = space.cell_degree(cell), n = points_per_axis;
  const basis::QuadratureRule1D& rule = basis::gauss_legendre(n);
  const basis::Tabulation1D table = basis::tabulate_lobatto(p, rule.points);
  const auto shapes = space.cell_shapes(cell);
  const int n_shapes = static_cast<int>(shapes.size()), n_points = n * n * n;
  SolidCellValues out;
  out.values.resize(n_shapes, n_points);
  for (auto& gradient : out.gradients) gradient.resize(n_shapes, n_points);
  out.weights.resize(n_points);
  out.points.resize(n_points);
  for (int q = 0; q < n_points; ++q) {
    const std::array<int, 3> at{q % n, (q / n) % n, q / (n * n)};
    const Eigen::Vector3d xi(rule.points[at[0]], rule.points[at[1]], rule.points[at[2]]);
    const Eigen::Matrix3d jacobian = mesh.jacobian(cell, xi);
    const double det = jacobian.determinant();
    if (!(det > 0.0))
      throw NumericalError(fmt::format("hexahedron {} is inverted inside (Jacobian determinant {:.3g})", cell, det));
    const Eigen::Matrix3d inverse_transpose = jacobian.inverse().transpose();
    out.weights(q) = rule.weights[at[0]] * rule.weights[at[1]] * rule.weights[at[2]] * det;
    out.points[q] = mesh.map(cell, xi);
    for (int s = 0; s < n_shapes; ++s) {
      std::array<double, 3> value{}, slope{};
      for (int d = 0; d < 3; ++d) {
        value[d] = table.values(at[d], shapes[s].index[d]);
        slope[d] = table.derivatives(at[d], shapes[s].index[d]);
      }
      out.values(s, q) = value[0] * value[1] * value[2];
      const Eigen::Vector3d reference(slope[0] * value[1] * value[2], value[0] * slope[1] * value[2],
                                      value[0] * value[1] * slope[2]);
      const Eigen::Vector3d gradient = inverse_transpose * reference;
      for (int d = 0; d < 3; ++d) out.gradients[d](s, q) = gradient(d);
    }
  }
  return out;
}

}  // namespace hpcontact::assembly
