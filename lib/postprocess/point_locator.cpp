// PointLocator: each cell is listed in every bucket its bounding box touches.
#include "postprocess/point_locator.hpp"

#include <algorithm>
#include <cmath>

#include "mesh/cell_map.hpp"

namespace hpcontact::postprocess {

PointLocator::PointLocator(const mesh::Mesh& mesh) : mesh_(&mesh) {
  lower_ = upper_ = mesh.vertex(0);
  for (const auto& v : mesh.vertices()) {
    lower_ = lower_.cwiseMin(v);
    upper_ = upper_.cwiseMax(v);
  }
  const int side = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(mesh.n_cells()))));
  n_x_ = n_y_ = side;
  buckets_.assign(static_cast<std::size_t>(n_x_) * n_y_, {});
  for (int c = 0; c < mesh.n_cells(); ++c) {
    mesh::Point lo = mesh.vertex(mesh.cell(c)[0]), hi = lo;
    for (int v : mesh.cell(c)) {
      lo = lo.cwiseMin(mesh.vertex(v));
      hi = hi.cwiseMax(mesh.vertex(v));
    }
    const int b0 = bucket_of(lo.x(), lo.y()), b1 = bucket_of(hi.x(), hi.y());
    for (int j = b0 / n_x_; j <= b1 / n_x_; ++j)
      for (int i = b0 % n_x_; i <= b1 % n_x_; ++i) buckets_[j * n_x_ + i].push_back(c);
  }
}

int PointLocator::bucket_of(double x, double y) const {
  const mesh::Point extent = (upper_ - lower_).cwiseMax(1e-300);
  const int i = std::clamp(static_cast<int>((x - lower_.x()) / extent.x() * n_x_), 0, n_x_ - 1);
  const int j = std::clamp(static_cast<int>((y - lower_.y()) / extent.y() * n_y_), 0, n_y_ - 1);
  return j * n_x_ + i;
}

std::optional<CellPoint> PointLocator::locate(const mesh::Point& x) const {
  const double slack = 1e-12 * (upper_ - lower_).norm();
  if ((x.array() < lower_.array() - slack).any() || (x.array() > upper_.array() + slack).any()) return std::nullopt;
  for (int c : buckets_[bucket_of(x.x(), x.y())]) {
    if (const auto ref = mesh::CellMap(*mesh_, c).inverse(x)) return CellPoint{c, ref->x(), ref->y()};
  }
  return std::nullopt;
}

}  // namespace hpcontact::postprocess
