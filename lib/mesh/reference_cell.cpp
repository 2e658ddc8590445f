// The reference square and triangle: numbering tables and point tests.
#include "mesh/reference_cell.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace hpcontact::mesh {
namespace {

constexpr std::array<std::array<int, 2>, 4> kSquareEdges{{{0, 1}, {1, 2}, {3, 2}, {0, 3}}};
constexpr std::array<std::array<int, 2>, 3> kTriangleEdges{{{0, 1}, {1, 2}, {0, 2}}};
constexpr std::array<std::array<double, 2>, 4> kSquareVertices{{{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}};
constexpr std::array<std::array<double, 2>, 3> kTriangleVertices{{{-1.0, -1.0}, {1.0, -1.0}, {-1.0, 1.0}}};

}  // namespace

int cell_vertex_count(CellType type) { return type == CellType::triangle ? 3 : 4; }

std::array<int, 2> local_edge_vertices(CellType type, int local_edge) {
  HPC_VERIFY(local_edge >= 0 && local_edge < cell_vertex_count(type), "local edge out of range");
  return type == CellType::triangle ? kTriangleEdges[local_edge] : kSquareEdges[local_edge];
}

Eigen::Vector2d reference_vertex(CellType type, int v) {
  HPC_VERIFY(v >= 0 && v < cell_vertex_count(type), "local vertex out of range");
  const auto& xy = type == CellType::triangle ? kTriangleVertices[v] : kSquareVertices[v];
  return {xy[0], xy[1]};
}

Eigen::Vector2d local_edge_point(CellType type, int local_edge, double t) {
  const auto [start, end] = local_edge_vertices(type, local_edge);
  return 0.5 * (1.0 - t) * reference_vertex(type, start) + 0.5 * (1.0 + t) * reference_vertex(type, end);
}

Eigen::Vector2d local_edge_direction(CellType type, int local_edge) {
  const auto [start, end] = local_edge_vertices(type, local_edge);
  return 0.5 * (reference_vertex(type, end) - reference_vertex(type, start));
}

bool local_edge_counterclockwise(CellType type, int local_edge) {
  // Counterclockwise edges run from local vertex k to k + 1; the others (the square's 2 and 3,
  // the triangle's 2) close the cycle the other way round.
  const auto [start, end] = local_edge_vertices(type, local_edge);
  return end == start + 1;
}

Eigen::Vector2d reference_centre(CellType type) {
  return type == CellType::triangle ? Eigen::Vector2d(-1.0 / 3.0, -1.0 / 3.0) : Eigen::Vector2d(0.0, 0.0);
}

bool reference_contains(CellType type, const Eigen::Vector2d& point, double tolerance) {
  if (type == CellType::quadrilateral) return point.cwiseAbs().maxCoeff() <= 1.0 + tolerance;
  return point.x() >= -1.0 - tolerance && point.y() >= -1.0 - tolerance && point.x() + point.y() <= tolerance;
}

Eigen::Vector2d clamp_to_reference(CellType type, const Eigen::Vector2d& point) {
  Eigen::Vector2d out = point.cwiseMax(-1.0).cwiseMin(1.0);
  if (type == CellType::triangle && out.x() + out.y() > 0.0) {
    // Project onto the hypotenuse ξ + η = 0 along its normal, then back into its extent.
    const double shift = 0.5 * (out.x() + out.y());
    out = Eigen::Vector2d(std::clamp(out.x() - shift, -1.0, 1.0), std::clamp(out.y() - shift, -1.0, 1.0));
  }
  return out;
}

}  // namespace hpcontact::mesh
