// Finds the cell and reference coordinates of a physical point (bucket grid over cell boxes).
#pragma once

#include <optional>
#include <vector>

#include "mesh/mesh.hpp"

namespace hpcontact::postprocess {

struct CellPoint {
  int cell = -1;
  double xi = 0.0;
  double eta = 0.0;
};

class PointLocator {
 public:
  explicit PointLocator(const mesh::Mesh& mesh);
  /// A cell containing x (the first one found for points on shared edges), or nothing if x is
  /// outside the mesh.
  std::optional<CellPoint> locate(const mesh::Point& x) const;

 private:
  const mesh::Mesh* mesh_;
  mesh::Point lower_, upper_;
  int n_x_ = 1, n_y_ = 1;
  std::vector<std::vector<int>> buckets_;
  int bucket_of(double x, double y) const;
};

}  // namespace hpcontact::postprocess
