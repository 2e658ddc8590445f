// Trace-multiplier couplings on flat contact surfaces of solid meshes.
#include "assembly/surface_coupling.hpp"

#include <fmt/format.h>

#include <Eigen/LU>
#include <Eigen/SparseCore>
#include <cmath>

#include "basis/quadrature.hpp"
#include "core/error.hpp"
#include "space/solid_shape_values.hpp"

namespace hpcontact::assembly {

namespace {

/// The local coordinates (u, v) ∈ [-1,1]² of the plane point a on a face whose corners (tensor
/// order of its free axes) are `corners`: the inverse of the bilinear map by Newton's method
/// (one step on a parallelogram).
Eigen::Vector2d face_coordinates(const std::array<Eigen::Vector2d, 4>& corners, const Eigen::Vector2d& a) {
  Eigen::Vector2d t = Eigen::Vector2d::Zero();
  for (int step = 0; step < 30; ++step) {
    Eigen::Vector2d x = Eigen::Vector2d::Zero();
    Eigen::Matrix2d jacobian = Eigen::Matrix2d::Zero();
    for (int k = 0; k < 4; ++k) {
      const double su = (k & 1) ? 1.0 : -1.0, sv = (k & 2) ? 1.0 : -1.0;
      const double fu = 0.5 * (1.0 + su * t(0)), fv = 0.5 * (1.0 + sv * t(1));
      x += fu * fv * corners[k];
      jacobian.col(0) += 0.5 * su * fv * corners[k];
      jacobian.col(1) += 0.5 * sv * fu * corners[k];
    }
    const Eigen::Vector2d update = jacobian.inverse() * (a - x);
    t += update;
    if (update.lpNorm<Eigen::Infinity>() < 1e-15) break;
  }
  return t;
}

/// The corners of a trace face in plane coordinates, in the tensor order of its free axes.
std::array<Eigen::Vector2d, 4> face_corners(const mesh::FlatContactSurface& surface, const mesh::BoundaryFace& face) {
  const mesh::SolidMesh& mesh = surface.mesh();
  std::array<Eigen::Vector2d, 4> corners;
  for (int k = 0; k < 4; ++k)
    corners[k] = surface.to_plane(mesh.vertex(mesh.cell(face.cell)[mesh::kHexFaceVertices[face.local_face][k]]));
  return corners;
}

/// Points (plane coordinates) and weights of a rule on cell c of T_{C,H}: the n × n Gauss rule on
/// a rectangle, the n² collapsed rule on a triangle.
std::vector<std::pair<Eigen::Vector2d, double>> cell_quadrature(const mesh::SurfaceMultiplierMesh& mesh, int c, int n) {
  std::vector<std::pair<Eigen::Vector2d, double>> out;
  if (!mesh.is_grid()) {
    const std::vector<Eigen::Vector2d> v = mesh.cell_polygon(c);
    return basis::plane_triangle_rule(v[0], v[1], v[2], n);
  }
  const auto [lo, hi] = mesh.cell_bounds(c);
  const Eigen::Vector2d half = 0.5 * (hi - lo);
  const basis::QuadratureRule1D& rule = basis::gauss_legendre(n);
  for (std::size_t i = 0; i < rule.points.size(); ++i)
    for (std::size_t j = 0; j < rule.points.size(); ++j)
      out.emplace_back(lo + (Eigen::Array2d(rule.points[i] + 1.0, rule.points[j] + 1.0) * half.array()).matrix(),
                       rule.weights[i] * rule.weights[j] * half.prod());
  return out;
}

}  // namespace

Eigen::Vector3d face_point_in_cell(const mesh::FlatContactSurface& surface, const mesh::BoundaryFace& face,
                                   const Eigen::Vector2d& a) {
  const mesh::SolidMesh& mesh = surface.mesh();
  if (mesh.is_tetrahedral()) {
    // The barycentric coordinates of a in the face's triangle are the cell's λ of its corners.
    const auto& corners = mesh::kTetFaceVertices[face.local_face];
    std::array<Eigen::Vector2d, 3> x;
    for (int k = 0; k < 3; ++k) x[k] = surface.to_plane(mesh.vertex(mesh.cell(face.cell)[corners[k]]));
    Eigen::Matrix2d edges;
    edges << x[1] - x[0], x[2] - x[0];
    const Eigen::Vector2d mu = edges.inverse() * (a - x[0]);
    std::array<double, 4> lambda{};
    lambda[corners[0]] = 1.0 - mu(0) - mu(1);
    lambda[corners[1]] = mu(0);
    lambda[corners[2]] = mu(1);
    return {2.0 * lambda[1] - 1.0, 2.0 * lambda[2] - 1.0, 2.0 * lambda[3] - 1.0};
  }
  const Eigen::Vector2d t = face_coordinates(face_corners(surface, face), a);
  Eigen::Vector3d xi;
  xi(face.local_face / 2) = face.local_face % 2 == 0 ? -1.0 : 1.0;
  xi(mesh::kHexFaceAxes[face.local_face][0]) = t(0);
  xi(mesh::kHexFaceAxes[face.local_face][1]) = t(1);
  return xi;
}

linalg::Coupling surface_coupling(const space::SolidH1Space& space, const space::SurfaceMultiplierSpace& multipliers,
                                  const SolidFunction& weight) {
  const mesh::SurfaceMultiplierMesh& multiplier_mesh = multipliers.mesh();
  const mesh::FlatContactSurface& surface = multiplier_mesh.surface();
  HPC_VERIFY(&surface.mesh() == &space.mesh(), "multipliers on Γ_C of the space's mesh");
  std::vector<Eigen::Triplet<double>> entries;
  for (const auto& overlap : multiplier_mesh.overlaps()) {
    const mesh::BoundaryFace& face = surface.faces()[overlap.face];
    const int cell = face.cell;
    // The cell's shapes that do not vanish on the face.
    const auto shapes = space.cell_shapes(cell);
    std::vector<int> on_face;
    for (int s = 0; s < static_cast<int>(shapes.size()); ++s)
      if (shapes[s].dof >= 0 && space::shape_on_face(space.mesh(), shapes[s], face.local_face)) on_face.push_back(s);
    const int p = space.cell_degree(cell);
    Eigen::MatrixXd local = Eigen::MatrixXd::Zero(multipliers.per_cell(), static_cast<Eigen::Index>(on_face.size()));
    const auto& polygon = overlap.polygon;
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
      for (auto [a, w] :
           basis::plane_triangle_rule(polygon[0], polygon[k], polygon[k + 1], p + multipliers.degree() + 2)) {
        if (weight) w *= weight(surface.from_plane(a));
        const Eigen::VectorXd phi = space::local_shape_values(space, cell, face_point_in_cell(surface, face, a));
        const Eigen::VectorXd ell = multipliers.values(overlap.cell, a);
        for (std::size_t j = 0; j < on_face.size(); ++j)
          local.col(static_cast<Eigen::Index>(j)) += w * shapes[on_face[j]].sign * phi(on_face[j]) * ell;
      }
    }
    const int first = multipliers.first_dof(overlap.cell);
    for (Eigen::Index i = 0; i < local.rows(); ++i)
      for (std::size_t j = 0; j < on_face.size(); ++j)
        entries.emplace_back(first + static_cast<int>(i), shapes[on_face[j]].dof,
                             local(i, static_cast<Eigen::Index>(j)));
  }
  linalg::Coupling b(multipliers.n_dofs(), space.n_dofs());
  b.setFromTriplets(entries.begin(), entries.end());
  return linalg::squeezed(std::move(b));
}

linalg::Coupling directional_coupling(const space::SolidVectorSpace& space, const linalg::Coupling& scalar,
                                      const Eigen::Vector3d& direction) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int row = 0; row < scalar.outerSize(); ++row)
    for (linalg::Coupling::InnerIterator it(scalar, row); it; ++it)
      for (int c = 0; c < 3; ++c) {
        const int dof = space.dof(static_cast<int>(it.col()), c);
        // (components along which d vanishes add nothing: keep them out of the trace)
        if (dof >= 0 && direction(c) != 0.0) entries.emplace_back(row, dof, direction(c) * it.value());
      }
  linalg::Coupling b(scalar.rows(), space.n_dofs());
  b.setFromTriplets(entries.begin(), entries.end());
  return linalg::squeezed(std::move(b));
}

bool cell_meets_support(const mesh::SurfaceMultiplierMesh& mesh, int cell, const SolidFunction& s) {
  for (const auto& [a, w] : cell_quadrature(mesh, cell, 12))
    if (s(mesh.surface().from_plane(a)) > 0.0) return true;
  return false;
}

Eigen::VectorXd surface_multiplier_load(const space::SurfaceMultiplierSpace& multipliers, const SolidFunction& g) {
  const mesh::SurfaceMultiplierMesh& multiplier_mesh = multipliers.mesh();
  Eigen::VectorXd load = Eigen::VectorXd::Zero(multipliers.n_dofs());
  for (int c = 0; c < multiplier_mesh.n_cells(); ++c)
    for (const auto& [a, w] : cell_quadrature(multiplier_mesh, c, multipliers.degree() + 6))
      load.segment(multipliers.first_dof(c), multipliers.per_cell()) +=
          w * g(multiplier_mesh.surface().from_plane(a)) * multipliers.values(c, a);
  return load;
}

}  // namespace hpcontact::assembly
