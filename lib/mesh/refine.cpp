// refine_uniformly and split_into_triangles.
#include "mesh/refine.hpp"

#include <map>

#include "core/error.hpp"
#include "mesh/blended_geometry.hpp"
#include "mesh/cell_map.hpp"

namespace hpcontact::mesh {

Mesh refine_uniformly(const Mesh& mesh) {
  HPC_VERIFY(!mesh.is_part(), "a part of a mesh is not refined: its cut edges would become boundary");
  std::vector<Point> vertices = mesh.vertices();
  const int edge_base = static_cast<int>(vertices.size());
  for (int e = 0; e < mesh.n_edges(); ++e) vertices.push_back(mesh.edge_midpoint(e));
  // Quadrilaterals get a centre vertex; triangles are cut at their edge midpoints only.
  const int centre_base = static_cast<int>(vertices.size());
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (mesh.cell_type(c) == CellType::quadrilateral) vertices.push_back(CellMap(mesh, c).map(0.0, 0.0));

  std::vector<std::array<int, 4>> cells;
  cells.reserve(4 * static_cast<std::size_t>(mesh.n_cells()));
  int centre = centre_base;
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const auto v = mesh.cell(c);
    const int m0 = edge_base + mesh.cell_edge(c, 0), m1 = edge_base + mesh.cell_edge(c, 1),
              m2 = edge_base + mesh.cell_edge(c, 2);
    if (mesh.cell_type(c) == CellType::triangle) {
      // Local edges: 0 (v0 v1), 1 (v1 v2), 2 (v0 v2); the middle child is m0 m1 m2.
      cells.push_back({v[0], m0, m2, -1});
      cells.push_back({m0, v[1], m1, -1});
      cells.push_back({m2, m1, v[2], -1});
      cells.push_back({m0, m1, m2, -1});
      continue;
    }
    const int m3 = edge_base + mesh.cell_edge(c, 3);
    // Local edges: 0 bottom (v0 v1), 1 right (v1 v2), 2 top (v3 v2), 3 left (v0 v3).
    cells.push_back({v[0], m0, centre, m3});
    cells.push_back({m0, v[1], m1, centre});
    cells.push_back({centre, m1, v[2], m2});
    cells.push_back({m3, centre, m2, v[3]});
    ++centre;
  }
  Mesh fine(std::move(vertices), std::move(cells), "refined mesh");
  // Children of a curved cell keep its map composed with the affine map of their reference cell into
  // the parent's, in the order the cells were pushed above: the child's reference vertices 0, 1
  // and the last one (3 on the square, 2 on the triangle) in the parent's reference cell.
  using Corners = std::array<Eigen::Vector2d, 3>;
  const std::array<Corners, 4> square_children{{{{{-1, -1}, {0, -1}, {-1, 0}}},
                                                {{{0, -1}, {1, -1}, {0, 0}}},
                                                {{{0, 0}, {1, 0}, {0, 1}}},
                                                {{{-1, 0}, {0, 0}, {-1, 1}}}}};
  const std::array<Corners, 4> triangle_children{{{{{-1, -1}, {0, -1}, {-1, 0}}},
                                                  {{{0, -1}, {1, -1}, {0, 0}}},
                                                  {{{-1, 0}, {0, 0}, {-1, 1}}},
                                                  {{{0, -1}, {0, 0}, {-1, 0}}}}};
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (const BlendedGeometry* geometry = mesh.cell_geometry(c)) {
      const auto& children = mesh.cell_type(c) == CellType::triangle ? triangle_children : square_children;
      for (int k = 0; k < 4; ++k) {
        // r ↦ offset + matrix r sends the reference vertices (-1,-1), (1,-1), (-1,1) to the corners.
        const auto& [v0, v1, v2] = children[k];
        Eigen::Matrix2d matrix;
        matrix << 0.5 * (v1 - v0), 0.5 * (v2 - v0);
        const Eigen::Vector2d offset = v0 + matrix * Eigen::Vector2d(1.0, 1.0);
        fine.set_cell_geometry(4 * c + k, std::make_shared<BlendedGeometry>(geometry->restricted(matrix, offset)));
      }
    }
  // A fine boundary edge has one original vertex and the midpoint of its parent edge.
  for (int e : fine.boundary_edges()) {
    const auto& ends = fine.edge(e);
    const int parent = (ends[1] >= edge_base && ends[1] < centre_base) ? ends[1] - edge_base : ends[0] - edge_base;
    fine.set_edge_label(e, mesh.edge_label(parent));
    fine.set_edge_part(e, mesh.edge_part(parent));
  }
  return fine;
}

Mesh split_into_triangles(const Mesh& mesh, const std::function<bool(int cell)>& which, const std::string& origin) {
  HPC_VERIFY(!mesh.is_part(), "a part of a mesh is not refined: its cut edges would become boundary");
  std::vector<std::array<int, 4>> cells;
  std::vector<std::pair<int, int>> kept;  // (new index, original) of cells kept whole
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const auto& cell = mesh.cells()[c];
    if (mesh.cell_type(c) == CellType::triangle || (which && !which(c))) {
      kept.emplace_back(static_cast<int>(cells.size()), c);
      cells.push_back(cell);
      continue;
    }
    if (mesh.cell_geometry(c))
      throw InputError(origin + ": cell " + std::to_string(c) +
                       " is curved and cannot be cut into triangles (curved sides need quadrilaterals)");
    cells.push_back({cell[0], cell[1], cell[2], -1});
    cells.push_back({cell[0], cell[2], cell[3], -1});
  }
  Mesh out(mesh.vertices(), std::move(cells), origin);
  for (const auto& [cell, original] : kept)
    if (const BlendedGeometry* geometry = mesh.cell_geometry(original))
      out.set_cell_geometry(cell, std::make_shared<BlendedGeometry>(*geometry));
  std::map<std::pair<int, int>, int> edge_of;
  for (int e : mesh.boundary_edges()) edge_of[{mesh.edge(e)[0], mesh.edge(e)[1]}] = e;
  for (int e : out.boundary_edges()) {
    const int original = edge_of.at({out.edge(e)[0], out.edge(e)[1]});
    out.set_edge_label(e, mesh.edge_label(original));
    out.set_edge_part(e, mesh.edge_part(original));
  }
  return out;
}

}  // namespace hpcontact::mesh
