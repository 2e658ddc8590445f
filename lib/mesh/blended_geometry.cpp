// BlendedGeometry: Gordon–Hall blending of curved sides on the square, edge-bubble blending on the
// triangle, and restriction to children.
#include "mesh/blended_geometry.hpp"

#include "core/error.hpp"

namespace hpcontact::mesh {

BlendedGeometry::BlendedGeometry(CellType type, const std::array<Point, 4>& corners) : type_(type), corners_(corners) {}

void BlendedGeometry::set_side(int local_edge, std::shared_ptr<const EdgeCurve> curve, bool reversed) {
  HPC_VERIFY(local_edge >= 0 && local_edge < cell_vertex_count(type_), "local edge out of range");
  sides_[local_edge] = {std::move(curve), reversed, nullptr};
  if (type_ != CellType::triangle) return;
  // φ = δ/(1 − s²) is a polynomial of the curve's degree − 2 (δ vanishes at ±1); sampling it at
  // the Chebyshev–Lobatto points divides by 1 − s² ≥ 1 − cos(π/n)² away from the ends, and at the
  // ends takes the limits φ(±1) = ∓δ'(±1)/2.
  const int degree = sides_[local_edge].curve->degree();
  sides_[local_edge].quotient = std::make_shared<EdgeCurve>(EdgeCurve::interpolate(
      [&](double s) -> Point {
        const auto [delta, slope] = deviation(local_edge, s);
        if (s <= -1.0) return 0.5 * slope;
        if (s >= 1.0) return -0.5 * slope;
        return delta / (1.0 - s * s);
      },
      std::max(degree, 2)));
}

bool BlendedGeometry::has_curved_side() const {
  for (const auto& side : sides_)
    if (side.curve) return true;
  return false;
}

BlendedGeometry BlendedGeometry::restricted(const Eigen::Matrix2d& matrix, const Eigen::Vector2d& offset) const {
  BlendedGeometry part = *this;
  if (part_)
    part.part_ = Part{part_->matrix * matrix, part_->offset + part_->matrix * offset};
  else
    part.part_ = Part{matrix, offset};
  return part;
}

std::pair<Point, Point> BlendedGeometry::deviation(int local_edge, double s) const {
  const Side& side = sides_[local_edge];
  if (!side.curve) return {Point::Zero(), Point::Zero()};
  const auto [start, end] = local_edge_vertices(type_, local_edge);
  const Point &a = corners_[start], &b = corners_[end];
  const double t = side.reversed ? -s : s;
  const Point gamma = side.curve->point(t);
  const Point slope = (side.reversed ? -1.0 : 1.0) * side.curve->derivative(t);
  return {gamma - (0.5 * (1.0 - s) * a + 0.5 * (1.0 + s) * b), slope - 0.5 * (b - a)};
}

std::pair<Point, Eigen::Matrix2d> BlendedGeometry::square_map(double x, double y) const {
  const Point bilinear = 0.25 * ((1 - x) * (1 - y) * corners_[0] + (1 + x) * (1 - y) * corners_[1] +
                                 (1 + x) * (1 + y) * corners_[2] + (1 - x) * (1 + y) * corners_[3]);
  // Local edges: 0 at η = -1 and 2 at η = +1 run along ξ; 1 at ξ = +1 and 3 at ξ = -1 along η.
  const auto [d0, s0] = deviation(0, x);
  const auto [d1, s1] = deviation(1, y);
  const auto [d2, s2] = deviation(2, x);
  const auto [d3, s3] = deviation(3, y);
  const Point point = bilinear + 0.5 * (1 - y) * d0 + 0.5 * (1 + x) * d1 + 0.5 * (1 + y) * d2 + 0.5 * (1 - x) * d3;
  const Point bilinear_x =
      0.25 * (-(1 - y) * corners_[0] + (1 - y) * corners_[1] + (1 + y) * corners_[2] - (1 + y) * corners_[3]);
  const Point bilinear_y =
      0.25 * (-(1 - x) * corners_[0] - (1 + x) * corners_[1] + (1 + x) * corners_[2] + (1 - x) * corners_[3]);
  Eigen::Matrix2d j;
  j.col(0) = bilinear_x + 0.5 * (1 - y) * s0 + 0.5 * d1 + 0.5 * (1 + y) * s2 - 0.5 * d3;
  j.col(1) = bilinear_y - 0.5 * d0 + 0.5 * (1 + x) * s1 + 0.5 * d2 + 0.5 * (1 - x) * s3;
  return {point, j};
}

std::pair<Point, Eigen::Matrix2d> BlendedGeometry::triangle_map(double x, double y) const {
  // Barycentric coordinates and their (constant) gradients in (ξ, η).
  const std::array<double, 3> lambda{-0.5 * (x + y), 0.5 * (1.0 + x), 0.5 * (1.0 + y)};
  const std::array<Eigen::Vector2d, 3> grad{Eigen::Vector2d(-0.5, -0.5), Eigen::Vector2d(0.5, 0.0),
                                            Eigen::Vector2d(0.0, 0.5)};
  Point point = lambda[0] * corners_[0] + lambda[1] * corners_[1] + lambda[2] * corners_[2];
  Eigen::Matrix2d j =
      corners_[0] * grad[0].transpose() + corners_[1] * grad[1].transpose() + corners_[2] * grad[2].transpose();
  for (int e = 0; e < 3; ++e) {
    const Side& side = sides_[e];
    if (!side.quotient) continue;
    const auto [a, b] = local_edge_vertices(CellType::triangle, e);
    const double s = lambda[b] - lambda[a];
    const Point phi = side.quotient->point(s), phi_slope = side.quotient->derivative(s);
    const double bubble = 4.0 * lambda[a] * lambda[b];
    const Eigen::Vector2d bubble_grad = 4.0 * (lambda[b] * grad[a] + lambda[a] * grad[b]);
    point += bubble * phi;
    j += phi * bubble_grad.transpose() + bubble * phi_slope * (grad[b] - grad[a]).transpose();
  }
  return {point, j};
}

std::pair<Point, Eigen::Matrix2d> BlendedGeometry::original(double xi, double eta) const {
  Eigen::Vector2d r(xi, eta);
  if (part_) r = part_->offset + part_->matrix * r;
  auto [point, j] = type_ == CellType::triangle ? triangle_map(r.x(), r.y()) : square_map(r.x(), r.y());
  if (part_) j = j * part_->matrix;  // chain rule for the part
  return {point, j};
}

Point BlendedGeometry::map(double xi, double eta) const { return original(xi, eta).first; }

Eigen::Matrix2d BlendedGeometry::jacobian(double xi, double eta) const { return original(xi, eta).second; }

}  // namespace hpcontact::mesh
