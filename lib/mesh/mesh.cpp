// Mesh: topology construction (edges, adjacency, orientation) and validity checks.
#include "mesh/mesh.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <functional>
#include <map>

#include "basis/quadrature.hpp"
#include "core/error.hpp"
#include "mesh/blended_geometry.hpp"
#include "mesh/cell_map.hpp"

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

Mesh::Mesh(std::vector<Point> vertices, std::vector<std::array<int, 4>> cells, const std::string& origin)
    : vertices_(std::move(vertices)), cells_(std::move(cells)) {
  if (cells_.empty()) throw InputError(origin + ": the mesh has no cells");
  for (std::size_t c = 0; c < cells_.size(); ++c)
    for (int v : cell(static_cast<int>(c)))
      if (v < 0 || v >= n_vertices())
        throw InputError(origin + ": cell " + std::to_string(c) + " refers to vertex " + std::to_string(v) +
                         ", but the mesh has " + std::to_string(n_vertices()) + " vertices");
  check_cells(origin);
  build_topology(origin);
}

void Mesh::check_cells(const std::string& origin) const {
  for (int c = 0; c < n_cells(); ++c) {
    // Strict convexity and counterclockwise order: every corner turns left, which makes
    // the bilinear (affine) map's Jacobian determinant positive on the whole reference cell.
    const int n = cell_size(c);
    for (int k = 0; k < n; ++k) {
      const Point& a = vertices_[cells_[c][k]];
      const Point& b = vertices_[cells_[c][(k + 1) % n]];
      const Point& d = vertices_[cells_[c][(k + n - 1) % n]];
      const Point u = b - a, w = d - a;
      const double cross = u.x() * w.y() - u.y() * w.x();
      const double scale = u.norm() * w.norm();
      if (!(cross > 1e-12 * scale))
        throw InputError(
            origin + ": cell " + std::to_string(c) + " is not a " +
            (n == 3 ? "non-degenerate counterclockwise triangle" : "strictly convex counterclockwise quadrilateral") +
            " (corner " + std::to_string(k) + ")");
    }
  }
}

void Mesh::build_topology(const std::string& origin) {
  std::map<std::pair<int, int>, int> edge_index;
  cell_edges_.assign(cells_.size(), {});
  cell_edge_signs_.assign(cells_.size(), {});
  for (int c = 0; c < n_cells(); ++c) {
    cell_edges_[c].fill(-1);
    for (int k = 0; k < cell_size(c); ++k) {
      const auto [start, end] = local_edge_vertices(cell_type(c), k);
      const int a = cells_[c][start];
      const int b = cells_[c][end];
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
  edge_label_index_.assign(edges_.size(), 0);
  edge_parts_.assign(edges_.size(), BoundaryPart::interior);
  for (int e = 0; e < n_edges(); ++e)
    if (is_boundary_edge(e)) {
      boundary_edges_.push_back(e);
      edge_parts_[e] = BoundaryPart::neumann;
    }
}

Mesh Mesh::extract(const std::vector<int>& cells) const {
  HPC_VERIFY(!is_part(), "a part is extracted from a whole mesh");
  HPC_VERIFY(!cells.empty() && std::adjacent_find(cells.begin(), cells.end(), std::greater_equal<>()) == cells.end() &&
                 cells.front() >= 0 && cells.back() < n_cells(),
             "a part's cells are distinct cells of the mesh, ascending");
  Mesh part;
  part.global_cells_ = cells;
  auto& vertices = part.global_vertices_;
  auto& edges = part.global_edges_;
  for (int c : cells)
    for (int k = 0; k < cell_size(c); ++k) {
      vertices.push_back(cells_[c][k]);
      edges.push_back(cell_edges_[c][k]);
    }
  for (auto* ids : {&vertices, &edges}) {
    std::sort(ids->begin(), ids->end());
    ids->erase(std::unique(ids->begin(), ids->end()), ids->end());
    ids->shrink_to_fit();  // a part lives as long as the run: no slack from the duplicates
  }
  // The part's index of a whole mesh's cell, vertex or edge (−1: not in the part).
  const auto local = [](const std::vector<int>& ids, int id) {
    const auto found = std::lower_bound(ids.begin(), ids.end(), id);
    return found != ids.end() && *found == id ? static_cast<int>(found - ids.begin()) : -1;
  };
  part.vertices_.reserve(vertices.size());
  for (int v : vertices) part.vertices_.push_back(vertices_[v]);
  for (auto* table : {&part.cells_, &part.cell_edges_}) table->reserve(cells.size());
  part.cell_edge_signs_.reserve(cells.size());
  if (!cell_geometry_.empty()) part.cell_geometry_.reserve(cells.size());
  for (auto* table : {&part.edges_, &part.edge_cells_}) table->reserve(edges.size());
  part.edge_label_index_.reserve(edges.size());
  part.edge_parts_.reserve(edges.size());
  for (int c : cells) {
    std::array<int, 4> corners{-1, -1, -1, -1}, sides{-1, -1, -1, -1};
    for (int k = 0; k < cell_size(c); ++k) {
      corners[k] = local(vertices, cells_[c][k]);
      sides[k] = local(edges, cell_edges_[c][k]);
    }
    part.cells_.push_back(corners);
    part.cell_edges_.push_back(sides);
    part.cell_edge_signs_.push_back(cell_edge_signs_[c]);
    if (!cell_geometry_.empty()) part.cell_geometry_.push_back(cell_geometry_[c]);
  }
  part.labels_ = labels_;
  for (int e : edges) {
    part.edges_.push_back({local(vertices, edges_[e][0]), local(vertices, edges_[e][1])});
    std::array<int, 2> neighbours{};
    for (int k = 0; k < 2; ++k) {
      const int c = edge_cells_[e][k];
      neighbours[k] = c < 0 ? -1 : (local(cells, c) >= 0 ? local(cells, c) : kCellElsewhere);
    }
    if (neighbours[0] == kCellElsewhere) std::swap(neighbours[0], neighbours[1]);  // the part's cell first
    part.edge_cells_.push_back(neighbours);
    if (neighbours[1] == -1) part.boundary_edges_.push_back(part.n_edges() - 1);
    part.edge_label_index_.push_back(edge_label_index_[e]);
    part.edge_parts_.push_back(edge_parts_[e]);
  }
  return part;
}

int Mesh::local_edge_of(int e, int k) const {
  const int c = edge_cells_[e][k];
  for (int local = 0; local < cell_size(c); ++local)
    if (cell_edges_[c][local] == e) return local;
  HPC_VERIFY(false, "edge not found in its adjacent cell");
}

Point Mesh::edge_point(int e, double t) const {
  const int c = edge_cells_[e][0];
  if (!cell_geometry(c)) return 0.5 * (1.0 - t) * vertices_[edges_[e][0]] + 0.5 * (1.0 + t) * vertices_[edges_[e][1]];
  const int local = local_edge_of(e, 0);
  const Eigen::Vector2d ref = local_edge_point(cell_type(c), local, cell_edge_signs_[c][local] * t);
  return CellMap(*this, c).map(ref.x(), ref.y());
}

double Mesh::edge_length(int e) const {
  const int c = edge_cells_[e][0];
  if (!cell_geometry(c)) return (vertices_[edges_[e][1]] - vertices_[edges_[e][0]]).norm();
  // The speed |dΨ/dt| of a curve resolved to round-off at degree ≤ 24 is smooth: 32 Gauss points
  // give its integral to round-off.
  const int local = local_edge_of(e, 0);
  const CellMap map(*this, c);
  const auto& rule = basis::gauss_legendre(32);
  double length = 0.0;
  for (std::size_t q = 0; q < rule.points.size(); ++q)
    length += rule.weights[q] * map.edge_tangent(local, rule.points[q]).norm();
  return length;
}

Point Mesh::boundary_normal(int e, double t) const {
  HPC_VERIFY(is_boundary_edge(e), "normal requested for an interior edge");
  const int c = edge_cells_[e][0];
  const int local = local_edge_of(e, 0);
  const auto [start, end] = local_edge_vertices(cell_type(c), local);
  const Point tangent = cell_geometry(c) ? CellMap(*this, c).edge_tangent(local, t)
                                         : Point(vertices_[cells_[c][end]] - vertices_[cells_[c][start]]);
  const double ccw = local_edge_counterclockwise(cell_type(c), local) ? 1.0 : -1.0;
  return ccw * Point(tangent.y(), -tangent.x()).normalized();
}

void Mesh::set_edge_curve(int e, std::shared_ptr<const EdgeCurve> curve, const std::string& origin) {
  HPC_VERIFY(!is_part(), "curves are set on the whole mesh, before its parts are extracted");
  const Point &a = vertices_[edges_[e][0]], &b = vertices_[edges_[e][1]];
  const double length = (b - a).norm();
  if ((curve->point(-1.0) - a).norm() > 1e-8 * length || (curve->point(1.0) - b).norm() > 1e-8 * length)
    throw InputError(origin + ": the curve of edge (" + std::to_string(edges_[e][0]) + ", " +
                     std::to_string(edges_[e][1]) + ") does not end at its vertices");
  if (cell_geometry_.empty()) cell_geometry_.resize(cells_.size());
  for (int k = 0; k < 2; ++k) {
    const int c = edge_cells_[e][k];
    if (c < 0) continue;
    const int local = local_edge_of(e, k);
    HPC_VERIFY(!cell_geometry_[c] || cell_geometry_[c]->is_whole(), "edge curves are set before refinement");
    std::array<Point, 4> corners;
    corners.fill(Point::Zero());  // (a triangle's fourth is unused, but packed and sent)
    for (int v = 0; v < cell_size(c); ++v) corners[v] = vertices_[cells_[c][v]];
    auto geometry = cell_geometry_[c] ? std::make_shared<BlendedGeometry>(*cell_geometry_[c])
                                      : std::make_shared<BlendedGeometry>(cell_type(c), corners);
    geometry->set_side(local, curve, cell_edge_signs_[c][local] < 0);
    cell_geometry_[c] = std::move(geometry);
    // The blended map must stay invertible: a side bulging past the opposite side (a curve much
    // more curved than the cell is small) folds the cell.
    const CellMap map(*this, c);
    const Eigen::Vector2d centre = reference_centre(cell_type(c));
    const double scale = map.jacobian(centre.x(), centre.y()).determinant();
    for (int i = 0; i <= 8; ++i)
      for (int j = 0; j <= 8; ++j)
        if (const Eigen::Vector2d r(-1.0 + i / 4.0, -1.0 + j / 4.0);
            reference_contains(cell_type(c), r, 0.0) &&
            !(map.jacobian(r.x(), r.y()).determinant() > 1e-10 * std::abs(scale)))
          throw InputError(origin + ": cell " + std::to_string(c) +
                           " folds over with its curved side (Jacobian determinant ≤ 0); refine the mesh near the "
                           "curve");
  }
}

void Mesh::set_cell_geometry(int c, std::shared_ptr<const BlendedGeometry> geometry) {
  if (cell_geometry_.empty()) {
    if (!geometry) return;
    cell_geometry_.resize(cells_.size());
  }
  cell_geometry_[c] = std::move(geometry);
}

bool Mesh::has_curved_cells() const {
  return std::any_of(cell_geometry_.begin(), cell_geometry_.end(), [](const auto& g) { return g != nullptr; });
}

void Mesh::straighten() { cell_geometry_.clear(); }

bool Mesh::has_triangles() const {
  return std::any_of(cells_.begin(), cells_.end(), [](const auto& cell) { return cell[3] < 0; });
}

bool Mesh::has_part(BoundaryPart part) const {
  return std::find(edge_parts_.begin(), edge_parts_.end(), part) != edge_parts_.end();
}

void Mesh::set_edge_label(int e, const std::string& label) {
  auto found = std::find(labels_.begin(), labels_.end(), label);
  if (found == labels_.end()) {
    if (labels_.size() > UINT16_MAX)
      throw InputError("the mesh carries more than 65 535 distinct edge labels; edge " + std::to_string(e) +
                       " would get '" + label + "'");
    found = labels_.insert(labels_.end(), label);
  }
  edge_label_index_[e] = static_cast<std::uint16_t>(found - labels_.begin());
}

void Mesh::set_edge_part(int e, BoundaryPart part) {
  HPC_VERIFY(is_boundary_edge(e) || part == BoundaryPart::interior, "boundary part assigned to an interior edge");
  edge_parts_[e] = part;
}

double Mesh::longest_edge() const {
  double h = 0.0;
  for (int e = 0; e < n_edges(); ++e) h = std::max(h, edge_length(e));
  return h;
}

void Mesh::move_vertices(std::vector<Point> new_positions, const std::string& origin) {
  HPC_VERIFY(new_positions.size() == vertices_.size(), "vertex count changed");
  HPC_VERIFY(!is_part(), "vertices move on the whole mesh, before its parts are extracted");
  if (has_curved_cells())
    throw InputError(origin +
                     ": a mesh with curved cells cannot be perturbed or graded (its curves would no "
                     "longer end at the vertices)");
  vertices_ = std::move(new_positions);
  check_cells(origin);
}

}  // namespace hpcontact::mesh
