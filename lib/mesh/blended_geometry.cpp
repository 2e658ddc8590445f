// BlendedGeometry: Gordon–Hall blending of curved sides.
#include "mesh/blended_geometry.hpp"

#include "core/error.hpp"

namespace hpcontact::mesh {

BlendedGeometry::BlendedGeometry(const std::array<Point, 4>& corners) : corners_(corners) {}

void BlendedGeometry::set_side(int local_edge, std::shared_ptr<const EdgeCurve> curve, bool reversed) {
  HPC_VERIFY(local_edge >= 0 && local_edge < 4, "local edge out of range");
  sides_[local_edge] = {std::move(curve), reversed};
}

bool BlendedGeometry::has_curved_side() const {
  for (const auto& side : sides_)
    if (side.curve) return true;
  return false;
}

BlendedGeometry BlendedGeometry::restricted(double xi0, double xi1, double eta0, double eta1) const {
  BlendedGeometry part = *this;
  const auto at_xi = [&](double xi) { return xi0_ + 0.5 * (xi + 1.0) * (xi1_ - xi0_); };
  const auto at_eta = [&](double eta) { return eta0_ + 0.5 * (eta + 1.0) * (eta1_ - eta0_); };
  part.xi0_ = at_xi(xi0);
  part.xi1_ = at_xi(xi1);
  part.eta0_ = at_eta(eta0);
  part.eta1_ = at_eta(eta1);
  return part;
}

std::pair<Point, Point> BlendedGeometry::deviation(int local_edge, double s) const {
  const Side& side = sides_[local_edge];
  if (!side.curve) return {Point::Zero(), Point::Zero()};
  const Point& a = corners_[local_edge_vertices(CellType::quadrilateral, local_edge)[0]];
  const Point& b = corners_[local_edge_vertices(CellType::quadrilateral, local_edge)[1]];
  const double t = side.reversed ? -s : s;
  const Point gamma = side.curve->point(t);
  const Point slope = (side.reversed ? -1.0 : 1.0) * side.curve->derivative(t);
  return {gamma - (0.5 * (1.0 - s) * a + 0.5 * (1.0 + s) * b), slope - 0.5 * (b - a)};
}

Point BlendedGeometry::map(double xi, double eta) const {
  const double x = xi0_ + 0.5 * (xi + 1.0) * (xi1_ - xi0_), y = eta0_ + 0.5 * (eta + 1.0) * (eta1_ - eta0_);
  const Point bilinear = 0.25 * ((1 - x) * (1 - y) * corners_[0] + (1 + x) * (1 - y) * corners_[1] +
                                 (1 + x) * (1 + y) * corners_[2] + (1 - x) * (1 + y) * corners_[3]);
  // Local edges: 0 at η = -1 and 2 at η = +1 run along ξ; 1 at ξ = +1 and 3 at ξ = -1 along η.
  return bilinear + 0.5 * (1 - y) * deviation(0, x).first + 0.5 * (1 + x) * deviation(1, y).first +
         0.5 * (1 + y) * deviation(2, x).first + 0.5 * (1 - x) * deviation(3, y).first;
}

Eigen::Matrix2d BlendedGeometry::jacobian(double xi, double eta) const {
  const double x = xi0_ + 0.5 * (xi + 1.0) * (xi1_ - xi0_), y = eta0_ + 0.5 * (eta + 1.0) * (eta1_ - eta0_);
  const auto [d0, s0] = deviation(0, x);
  const auto [d1, s1] = deviation(1, y);
  const auto [d2, s2] = deviation(2, x);
  const auto [d3, s3] = deviation(3, y);
  const Point bilinear_x =
      0.25 * (-(1 - y) * corners_[0] + (1 - y) * corners_[1] + (1 + y) * corners_[2] - (1 + y) * corners_[3]);
  const Point bilinear_y =
      0.25 * (-(1 - x) * corners_[0] - (1 + x) * corners_[1] + (1 + x) * corners_[2] + (1 - x) * corners_[3]);
  Eigen::Matrix2d j;
  j.col(0) = bilinear_x + 0.5 * (1 - y) * s0 + 0.5 * d1 + 0.5 * (1 + y) * s2 - 0.5 * d3;
  j.col(1) = bilinear_y - 0.5 * d0 + 0.5 * (1 + x) * s1 + 0.5 * d2 + 0.5 * (1 - x) * s3;
  // Chain rule for the sub-square.
  j.col(0) *= 0.5 * (xi1_ - xi0_);
  j.col(1) *= 0.5 * (eta1_ - eta0_);
  return j;
}

}  // namespace hpcontact::mesh
