// refine_uniformly.
#include "mesh/refine.hpp"

#include "mesh/blended_geometry.hpp"
#include "mesh/cell_map.hpp"

namespace hpcontact::mesh {

QuadMesh refine_uniformly(const QuadMesh& mesh) {
  std::vector<Point> vertices = mesh.vertices();
  const int edge_base = static_cast<int>(vertices.size());
  for (int e = 0; e < mesh.n_edges(); ++e) vertices.push_back(mesh.edge_midpoint(e));
  const int centre_base = static_cast<int>(vertices.size());
  for (int c = 0; c < mesh.n_cells(); ++c) vertices.push_back(CellMap(mesh, c).map(0.0, 0.0));

  std::vector<std::array<int, 4>> cells;
  cells.reserve(4 * static_cast<std::size_t>(mesh.n_cells()));
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const auto& v = mesh.cell(c);
    const int m0 = edge_base + mesh.cell_edge(c, 0), m1 = edge_base + mesh.cell_edge(c, 1),
              m2 = edge_base + mesh.cell_edge(c, 2), m3 = edge_base + mesh.cell_edge(c, 3);
    const int centre = centre_base + c;
    // Local edges: 0 bottom (v0 v1), 1 right (v1 v2), 2 top (v3 v2), 3 left (v0 v3).
    cells.push_back({v[0], m0, centre, m3});
    cells.push_back({m0, v[1], m1, centre});
    cells.push_back({centre, m1, v[2], m2});
    cells.push_back({m3, centre, m2, v[3]});
  }
  QuadMesh fine(std::move(vertices), std::move(cells), "refined mesh");
  // Children of a curved cell keep its map on their quarter of the reference square, in the order
  // the cells were pushed above.
  constexpr std::array<std::array<double, 4>, 4> kQuarters{
      {{-1.0, 0.0, -1.0, 0.0}, {0.0, 1.0, -1.0, 0.0}, {0.0, 1.0, 0.0, 1.0}, {-1.0, 0.0, 0.0, 1.0}}};
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (const BlendedGeometry* geometry = mesh.cell_geometry(c))
      for (int k = 0; k < 4; ++k) {
        const auto& [xi0, xi1, eta0, eta1] = kQuarters[k];
        fine.set_cell_geometry(4 * c + k,
                               std::make_shared<BlendedGeometry>(geometry->restricted(xi0, xi1, eta0, eta1)));
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

}  // namespace hpcontact::mesh
