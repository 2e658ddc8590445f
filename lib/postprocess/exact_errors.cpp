// displacement_deviation, pressure_deviation.
#include "postprocess/exact_errors.hpp"

#include <algorithm>
#include <limits>
#include <vector>

#include "postprocess/boundary_samples.hpp"
#include "postprocess/point_locator.hpp"

namespace hpcontact::postprocess {

void MaxDeviation::add(const MaxDeviation& other) {
  error = std::max(error, other.error);
  scale = std::max(scale, other.scale);
}

double MaxDeviation::relative() const { return scale > 0.0 ? error / scale : error; }

MaxDeviation displacement_deviation(const assembly::CellField& u, const mesh::Mesh& mesh,
                                    const std::function<Eigen::Vector2d(const mesh::Point&)>& exact, int per_side) {
  mesh::Point lower = mesh.vertex(0), upper = mesh.vertex(0);
  for (const auto& vertex : mesh.vertices()) {
    lower = lower.cwiseMin(vertex);
    upper = upper.cwiseMax(vertex);
  }
  const PointLocator locator(mesh);
  std::vector<CellPoint> points;
  std::vector<mesh::Point> xs;
  for (int i = 0; i < per_side; ++i)
    for (int j = 0; j < per_side; ++j) {
      const mesh::Point x(lower.x() + (upper.x() - lower.x()) * i / (per_side - 1),
                          lower.y() + (upper.y() - lower.y()) * j / (per_side - 1));
      if (const auto located = locator.locate(x)) {
        points.push_back(*located);
        xs.push_back(x);
      }
    }
  const Eigen::MatrixXd values = values_at(u, points, {});
  MaxDeviation out;
  for (std::size_t k = 0; k < xs.size(); ++k) {
    const Eigen::Vector2d expected = exact(xs[k]);
    out.error = std::max(out.error,
                         (values.row(static_cast<Eigen::Index>(k)).transpose() - expected).lpNorm<Eigen::Infinity>());
    out.scale = std::max(out.scale, expected.lpNorm<Eigen::Infinity>());
  }
  return out;
}

MaxDeviation pressure_deviation(const space::MultiplierSpace& multipliers, const Eigen::VectorXd& pressure,
                                const mesh::ContactBoundary& contact,
                                const std::function<double(const mesh::Point&)>& exact, int per_segment) {
  MaxDeviation out;
  const auto& boundary = multipliers.boundary_mesh();
  for (int k = 0; k < multipliers.n_segments(); ++k)
    for (int j = 0; j < per_segment; ++j) {
      const double s =
          boundary.segment_begin(k) + (boundary.segment_end(k) - boundary.segment_begin(k)) * j / (per_segment - 1);
      const double expected = exact(contact.point_at(s));
      const Eigen::VectorXd basis = multipliers.basis_values(k, multipliers.local_coordinate(k, s));
      const int first = multipliers.first_dof(k), n = multipliers.segment_degree(k) + 1;
      out.error = std::max(out.error, std::abs(basis.dot(pressure.segment(first, n)) - expected));
      out.scale = std::max(out.scale, std::abs(expected));
    }
  return out;
}

}  // namespace hpcontact::postprocess
