// QuadMesh: topology construction (edges, adjacency, orientation) and validity checks.
#include "mesh/quad_mesh.hpp"

#include <algorithm>
#include <map>

#include "core/error.hpp"

namespace hpcontact::mesh {

std::string to_string(BoundaryPart part) {
  switch (part) {
    case BoundaryPart::interior:
      return "interior";
    case BoundaryPart::neumann:
      return "neumann";
    case BoundaryPart::dirichlet:
      return "dirichlet";
    case BoundaryPart::contact:
      return "contact";
  }
  return "unknown";
}

QuadMesh::QuadMesh(std::vector<Point> vertices, std::vector<std::array<int, 4>> cells, const std::string& origin)
    : vertices_(std::move(vertices)), cells_(std::move(cells)) {
  if (cells_.empty()) throw InputError(origin + ": the mesh has no cells");
  for (std::size_t c = 0; c < cells_.size(); ++c)
    for (int v : cells_[c])
      if (v < 0 || v >= n_vertices())
        throw InputError(origin + ": cell " + std::to_string(c) + " refers to vertex " + std::to_string(v) +
                         ", but the mesh has " + std::to_string(n_vertices()) + " vertices");
  check_cells(origin);
  build_topology(origin);
}

void QuadMesh::check_cells(const std::string& origin) const {
  for (int c = 0; c < n_cells(); ++c) {
    // Strict convexity and counterclockwise order: every corner turns left, which makes
    // the bilinear map's Jacobian determinant positive on the whole reference square.
    for (int k = 0; k < 4; ++k) {
      const Point& a = vertices_[cells_[c][k]];
      const Point& b = vertices_[cells_[c][(k + 1) % 4]];
      const Point& d = vertices_[cells_[c][(k + 3) % 4]];
      const Point u = b - a, w = d - a;
      const double cross = u.x() * w.y() - u.y() * w.x();
      const double scale = u.norm() * w.norm();
      if (!(cross > 1e-12 * scale))
        throw InputError(origin + ": cell " + std::to_string(c) +
                         " is not a strictly convex counterclockwise quadrilateral (corner " + std::to_string(k) + ")");
    }
  }
}

void QuadMesh::build_topology(const std::string& origin) {
  std::map<std::pair<int, int>, int> edge_index;
  cell_edges_.assign(cells_.size(), {});
  cell_edge_signs_.assign(cells_.size(), {});
  for (int c = 0; c < n_cells(); ++c) {
    for (int k = 0; k < 4; ++k) {
      const int a = cells_[c][kLocalEdgeVertices[k][0]];
      const int b = cells_[c][kLocalEdgeVertices[k][1]];
      const auto key = std::minmax(a, b);
      auto [it, inserted] = edge_index.try_emplace({key.first, key.second}, n_edges());
      if (inserted) {
        edges_.push_back({key.first, key.second});
        edge_cells_.push_back({c, -1});
      } else {
        auto& adjacent = edge_cells_[it->second];
        if (adjacent[1] >= 0)
          throw InputError(origin + ": edge (" + std::to_string(key.first) + ", " + std::to_string(key.second) +
                           ") is shared by more than two cells");
        adjacent[1] = c;
      }
      cell_edges_[c][k] = it->second;
      cell_edge_signs_[c][k] = a < b ? 1 : -1;
    }
  }
  edge_labels_.assign(edges_.size(), "");
  edge_parts_.assign(edges_.size(), BoundaryPart::interior);
  for (int e = 0; e < n_edges(); ++e)
    if (is_boundary_edge(e)) {
      boundary_edges_.push_back(e);
      edge_parts_[e] = BoundaryPart::neumann;
    }
}

int QuadMesh::local_edge_of(int e, int k) const {
  const int c = edge_cells_[e][k];
  for (int local = 0; local < 4; ++local)
    if (cell_edges_[c][local] == e) return local;
  HPC_VERIFY(false, "edge not found in its adjacent cell");
}

Point QuadMesh::edge_midpoint(int e) const { return 0.5 * (vertices_[edges_[e][0]] + vertices_[edges_[e][1]]); }

double QuadMesh::edge_length(int e) const { return (vertices_[edges_[e][1]] - vertices_[edges_[e][0]]).norm(); }

Point QuadMesh::boundary_normal(int e) const {
  HPC_VERIFY(is_boundary_edge(e), "normal requested for an interior edge");
  const int c = edge_cells_[e][0];
  const int local = local_edge_of(e, 0);
  // Local edges 0 and 1 run counterclockwise around the cell, 2 and 3 clockwise.
  const Point t =
      vertices_[cells_[c][kLocalEdgeVertices[local][1]]] - vertices_[cells_[c][kLocalEdgeVertices[local][0]]];
  const double ccw = (local <= 1) ? 1.0 : -1.0;
  return ccw * Point(t.y(), -t.x()).normalized();
}

bool QuadMesh::has_part(BoundaryPart part) const {
  return std::find(edge_parts_.begin(), edge_parts_.end(), part) != edge_parts_.end();
}

void QuadMesh::set_edge_part(int e, BoundaryPart part) {
  HPC_VERIFY(is_boundary_edge(e) || part == BoundaryPart::interior, "boundary part assigned to an interior edge");
  edge_parts_[e] = part;
}

double QuadMesh::longest_edge() const {
  double h = 0.0;
  for (int e = 0; e < n_edges(); ++e) h = std::max(h, edge_length(e));
  return h;
}

void QuadMesh::move_vertices(std::vector<Point> new_positions, const std::string& origin) {
  HPC_VERIFY(new_positions.size() == vertices_.size(), "vertex count changed");
  vertices_ = std::move(new_positions);
  check_cells(origin);
}

}  // namespace hpcontact::mesh
