// VTK's Lagrange node order and the entity of each node on our reference cells.
#include "io/vtk_lagrange_nodes.hpp"

#include <cmath>
#include <cstdlib>

namespace hpcontact::io {
namespace {

// The order-k triangle with its right-angle vertex at (o, o), in VTK's recursive order.
void add_triangle_nodes(int k, int o, std::vector<std::array<int, 2>>& out) {
  if (k < 0) return;
  if (k == 0) {
    out.push_back({o, o});
    return;
  }
  for (const std::array<int, 2> vertex : {std::array{o, o}, std::array{o + k, o}, std::array{o, o + k}})
    out.push_back(vertex);
  for (int t = 1; t < k; ++t) out.push_back({o + t, o});
  for (int t = 1; t < k; ++t) out.push_back({o + k - t, o + t});
  for (int t = 1; t < k; ++t) out.push_back({o, o + k - t});
  add_triangle_nodes(k - 3, o + 1, out);
}

std::array<int, 2> lattice_of_vertex(mesh::CellType type, int v, int k) {
  const Eigen::Vector2d r = mesh::reference_vertex(type, v);
  return {static_cast<int>(std::lround((r.x() + 1) / 2 * k)), static_cast<int>(std::lround((r.y() + 1) / 2 * k))};
}

}  // namespace

int vtk_lagrange_cell_type(mesh::CellType type) { return type == mesh::CellType::quadrilateral ? 70 : 69; }

std::vector<std::array<int, 2>> vtk_lagrange_lattice(mesh::CellType type, int k) {
  std::vector<std::array<int, 2>> out;
  out.reserve((k + 1) * (k + 1));
  if (type == mesh::CellType::triangle) {
    add_triangle_nodes(k, 0, out);
    return out;
  }
  for (const std::array<int, 2> vertex : {std::array{0, 0}, std::array{k, 0}, std::array{k, k}, std::array{0, k}})
    out.push_back(vertex);
  for (int t = 1; t < k; ++t) out.push_back({t, 0});
  for (int t = 1; t < k; ++t) out.push_back({k, t});
  for (int t = 1; t < k; ++t) out.push_back({t, k});
  for (int t = 1; t < k; ++t) out.push_back({0, t});
  for (int j = 1; j < k; ++j)
    for (int i = 1; i < k; ++i) out.push_back({i, j});
  return out;
}

assembly::ReferencePoints lattice_reference_points(const std::vector<std::array<int, 2>>& lattice, int k) {
  assembly::ReferencePoints out;
  for (const auto& [i, j] : lattice) {
    out.xi.push_back(-1.0 + 2.0 * i / k);
    out.eta.push_back(-1.0 + 2.0 * j / k);
  }
  return out;
}

LatticeEntity lattice_entity(mesh::CellType type, std::array<int, 2> node, int k) {
  const int n_vertices = mesh::cell_vertex_count(type);
  for (int v = 0; v < n_vertices; ++v)
    if (lattice_of_vertex(type, v, k) == node) return {LatticeEntity::Kind::vertex, v};
  // Edges have as many local numbers as vertices on both reference cells.
  for (int e = 0; e < n_vertices; ++e) {
    const auto [a, b] = mesh::local_edge_vertices(type, e);
    const auto start = lattice_of_vertex(type, a, k), end = lattice_of_vertex(type, b, k);
    const int di = (end[0] - start[0]) / k, dj = (end[1] - start[1]) / k;  // unit steps along the edge
    const int ni = node[0] - start[0], nj = node[1] - start[1];
    if (ni * dj != nj * di) continue;  // not on the edge's line
    const int step = di != 0 ? ni / di : nj / dj;
    if (step > 0 && step < k && ni == step * di && nj == step * dj) return {LatticeEntity::Kind::edge, e, step};
  }
  return {LatticeEntity::Kind::interior};
}

}  // namespace hpcontact::io
