// CellMap: the geometry of one cell, bilinear or blended.
#include "mesh/cell_map.hpp"

#include <Eigen/LU>
#include <cmath>

namespace hpcontact::mesh {

CellMap::CellMap(const Mesh& mesh, int cell) : type_(mesh.cell_type(cell)) {
  const auto v = mesh.cell(cell);
  const Point &p0 = mesh.vertex(v[0]), &p1 = mesh.vertex(v[1]), &p2 = mesh.vertex(v[2]);
  if (type_ == CellType::triangle) {
    // Ψ(-1,-1) = p0, Ψ(1,-1) = p1, Ψ(-1,1) = p2.
    a_ = 0.5 * (p1 + p2);
    b_ = 0.5 * (p1 - p0);
    c_ = 0.5 * (p2 - p0);
    d_ = Point::Zero();
  } else {
    const Point& p3 = mesh.vertex(v[3]);
    a_ = 0.25 * (p0 + p1 + p2 + p3);
    b_ = 0.25 * (-p0 + p1 + p2 - p3);
    c_ = 0.25 * (-p0 - p1 + p2 + p3);
    d_ = 0.25 * (p0 - p1 + p2 - p3);
  }
  curved_ = mesh.cell_geometry(cell);
}

Point CellMap::map(double xi, double eta) const {
  if (curved_) return curved_->map(xi, eta);
  return a_ + b_ * xi + c_ * eta + d_ * xi * eta;
}

bool CellMap::is_affine() const { return !curved_ && d_.norm() <= 1e-13 * (b_.norm() + c_.norm()); }

Eigen::Matrix2d CellMap::jacobian(double xi, double eta) const {
  if (curved_) return curved_->jacobian(xi, eta);
  Eigen::Matrix2d j;
  j.col(0) = b_ + d_ * eta;
  j.col(1) = c_ + d_ * xi;
  return j;
}

std::optional<Eigen::Vector2d> CellMap::inverse(const Point& x, double tolerance) const {
  Eigen::Vector2d ref = reference_centre(type_);
  const double scale = b_.norm() + c_.norm();
  for (int iteration = 0; iteration < 30; ++iteration) {
    const Point residual = map(ref.x(), ref.y()) - x;
    if (residual.norm() <= 1e-14 * scale) break;
    ref -= jacobian(ref.x(), ref.y()).lu().solve(residual);
    // Far outside the cell the Newton iterate may wander off; stop early.
    if (ref.cwiseAbs().maxCoeff() > 10.0) return std::nullopt;
  }
  if (!reference_contains(type_, ref, tolerance)) return std::nullopt;
  return clamp_to_reference(type_, ref);
}

Point CellMap::edge_tangent(int local_edge, double t) const {
  const Eigen::Vector2d ref = local_edge_point(type_, local_edge, t);
  return jacobian(ref.x(), ref.y()) * local_edge_direction(type_, local_edge);
}

}  // namespace hpcontact::mesh
