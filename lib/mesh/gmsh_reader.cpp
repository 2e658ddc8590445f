// read_gmsh_mesh through the Gmsh API (mesh/gmsh_api.hpp): Gmsh parses the file (MSH 2 and 4, ASCII and
// binary); this file turns its quadrilaterals and triangles into a Mesh, its physical curves into boundary
// edge labels and its curved geometry into curved edges (mesh/gmsh_curves.hpp), with errors that
// say what to change.
#include "mesh/gmsh_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <unordered_map>

#include "core/error.hpp"
#include "mesh/gmsh_api.hpp"
#include "mesh/gmsh_curves.hpp"

namespace hpcontact::mesh {
namespace {

using Tag = std::size_t;

/// Twice the signed area of the polygon cell (positive if counterclockwise).
double twice_signed_area(const std::vector<Point>& vertices, const std::array<int, 4>& cell, int n) {
  double sum = 0.0;
  for (int k = 0; k < n; ++k) {
    const Point& a = vertices[cell[k]];
    const Point& b = vertices[cell[(k + 1) % n]];
    sum += a.x() * b.y() - b.x() * a.y();
  }
  return sum;
}

// What to change in Gmsh when the file holds a 2-D element type other than a quadrilateral or a
// triangle (polygons, serendipity-free types are all one of the two in 2-D Gmsh files).
std::string unsupported_cell(const gmsh_api::Session& gmsh, const std::string& path, int type) {
  const auto [name, order] = gmsh.element_type(type);
  return fmt::format(
      "{}: only triangles and quadrilaterals (of any order) are supported; found type {} ({}): mesh the "
      "surface with Gmsh's default 2-D algorithms (Mesh.Algorithm = 6), optionally recombined",
      path, type, name);
}

// A mesh size that would fill the memory is refused before Gmsh meshes (which it would do for
// minutes, then fail without a way back). The cells are estimated from the bounding box's area
// (at least the domain's): about 2.3 triangles per size², or 4.7 quadrilaterals (each triangle of
// a twice coarser mesh split in three), as measured with Gmsh 4.8 on the tutorial's block.
void check_geo_size(const gmsh_api::Session& gmsh, const GeoMeshing& geo) {
  const auto [x0, y0, z0, x1, y1, z1] = gmsh.bounding_box();
  const double per_size_squared = geo.cells == GeneratedCells::quadrilaterals ? 4.7 : 2.3;
  const double size = *geo.mesh_size, cells = per_size_squared * (x1 - x0) * (y1 - y0) / (size * size);
  if (cells > geo.max_cells)
    throw_bad_input(geo.size_where, geo.size_key, fmt::format("{:g}", size),
                    fmt::format("about {:.3g} cells on the geometry's {:g} x {:g} bounding box, more than the {:.3g} "
                                "that fit ({}): a size of at least {:.3g}",
                                cells, x1 - x0, y1 - y0, geo.max_cells, geo.max_cells_reason,
                                size * std::sqrt(cells / geo.max_cells)));
}

// Reads `path` into Gmsh's model; a .geo geometry is meshed there (returns whether it was one).
bool open_in_gmsh(gmsh_api::Session& gmsh, const std::string& path, const GeoMeshing& geo) {
  errno = 0;
  if (!std::ifstream(path)) throw InputError(describe_io_failure("cannot open the Gmsh mesh file", path));
  const bool geometry = std::filesystem::path(path).extension() == ".geo";
  if (geo.mesh_size && !geometry)
    throw InputError(path + ": a mesh size applies to Gmsh geometry files (.geo) only, not to a mesh file");
  gmsh.open(path);
  if (geometry && geo.mesh_size) check_geo_size(gmsh, geo);
  if (geometry) gmsh.generate(path, geo.mesh_size, geo.cells == GeneratedCells::quadrilaterals);
  if (gmsh.dimension() < 2)
    throw InputError(path + ": holds no 2-D mesh (no $Nodes or $Elements of 2-D cells; is it a mesh file?)");
  return geometry;
}

// The nodes of the model: tag → position (z ignored), and the tags in Gmsh's order.
std::pair<std::vector<Tag>, std::unordered_map<Tag, Point>> model_nodes(const gmsh_api::Session& gmsh) {
  std::vector<Tag> tags;
  std::vector<double> coordinates;
  gmsh.nodes(tags, coordinates);
  std::unordered_map<Tag, Point> position;
  for (std::size_t k = 0; k < tags.size(); ++k) position[tags[k]] = Point(coordinates[3 * k], coordinates[3 * k + 1]);
  return {std::move(tags), std::move(position)};
}

struct ModelCells {
  std::vector<std::array<Tag, 4>> corners;  ///< a triangle's fourth entry is 0 (Gmsh tags start at 1)
  std::vector<int> sizes;                   ///< 3 or 4 corners
  std::vector<GmshEdgeNodes> edges;         ///< of high-order cells: end, edge nodes, end
};

// The quadrilaterals and triangles of the model: corner node tags, and the nodes along each edge
// of high-order ones (Gmsh numbers the corners first, then edge k's nodes from corner k to corner
// k + 1). @throws InputError for any other 2-D element.
ModelCells model_cells(const gmsh_api::Session& gmsh, const std::string& path) {
  const auto blocks = gmsh.elements(2);
  ModelCells out;
  for (std::size_t t = 0; t < blocks.types.size(); ++t) {
    const auto [name, order] = gmsh.element_type(blocks.types[t]);
    int n = 0;
    if (name.starts_with("Quadrilateral")) n = 4;
    if (name.starts_with("Triangle")) n = 3;
    if (n == 0) throw InputError(unsupported_cell(gmsh, path, blocks.types[t]));
    const auto& nodes = blocks.nodes[t];
    const std::size_t per_element = nodes.size() / blocks.tags[t].size();
    for (std::size_t k = 0; k < blocks.tags[t].size(); ++k) {
      const Tag* element = nodes.data() + per_element * k;
      out.corners.push_back({element[0], element[1], element[2], n == 4 ? element[3] : Tag{0}});
      out.sizes.push_back(n);
      for (int side = 0; order > 1 && side < n; ++side) {
        GmshEdgeNodes along{element[side]};
        for (int j = 0; j < order - 1; ++j) along.push_back(element[n + side * (order - 1) + j]);
        along.push_back(element[(side + 1) % n]);
        out.edges.push_back(std::move(along));
      }
    }
  }
  if (out.corners.empty()) throw InputError(path + ": holds no triangles or quadrilaterals");
  return out;
}

// Labels the boundary edges on the model's physical curves with the group's name (its tag as text
// if unnamed).
void label_physical_curves(const gmsh_api::Session& gmsh, const std::string& path,
                           const std::unordered_map<Tag, int>& vertex_of, Mesh& mesh) {
  std::map<std::pair<int, int>, int> boundary_edge;  // (lower, higher vertex) -> edge
  for (int e : mesh.boundary_edges()) boundary_edge[{mesh.edge(e)[0], mesh.edge(e)[1]}] = e;
  std::map<int, std::string> label_of_curve;
  for (const auto& [dim, group] : gmsh.physical_groups(1)) {
    std::string label = gmsh.physical_name(dim, group);
    if (label.empty()) label = std::to_string(group);
    for (int curve : gmsh.entities_of_physical_group(dim, group)) {
      // A label decides the boundary condition, so an edge in two groups would be ambiguous.
      if (const auto other = label_of_curve.find(curve); other != label_of_curve.end())
        throw InputError(
            fmt::format("{}: curve {} belongs to the physical groups '{}' and '{}'; a boundary edge "
                        "can carry only one label",
                        path, curve, other->second, label));
      label_of_curve[curve] = label;
      const auto blocks = gmsh.elements(1, curve);
      const auto& types = blocks.types;
      const auto &element_tags = blocks.tags, &node_tags = blocks.nodes;
      for (std::size_t t = 0; t < types.size(); ++t) {
        // A line of order q lists its two ends first, then its q - 1 inner nodes.
        const std::size_t per_element = node_tags[t].size() / element_tags[t].size();
        for (std::size_t k = 0; k < element_tags[t].size(); ++k) {
          const Tag n0 = node_tags[t][per_element * k], n1 = node_tags[t][per_element * k + 1];
          const auto a = vertex_of.find(n0), b = vertex_of.find(n1);
          auto edge = boundary_edge.end();
          if (a != vertex_of.end() && b != vertex_of.end())
            edge = boundary_edge.find(std::minmax(a->second, b->second));
          if (edge == boundary_edge.end())
            throw InputError(
                fmt::format("{}: line element {} (nodes {}, {}) of physical group '{}' is not a boundary "
                            "edge of the 2-D mesh",
                            path, element_tags[t][k], n0, n1, label));
          mesh.set_edge_label(edge->second, label);
        }
      }
    }
  }
}

}  // namespace

Mesh read_gmsh_mesh(const std::string& path, const GeoMeshing& geo) {
  gmsh_api::Session gmsh;
  const bool geometry = open_in_gmsh(gmsh, path, geo);
  const ModelCells model = model_cells(gmsh, path);
  const auto [node_order, position] = model_nodes(gmsh);
  // Only corner nodes of cells become vertices (in Gmsh's node order): geometry points that no
  // cell uses would be isolated vertices without any basis function support.
  std::unordered_map<Tag, bool> used;
  for (std::size_t c = 0; c < model.corners.size(); ++c)
    for (int k = 0; k < model.sizes[c]; ++k) used[model.corners[c][k]] = true;
  std::vector<Point> vertices;
  std::unordered_map<Tag, int> vertex_of;
  for (Tag tag : node_order)
    if (used.contains(tag) && !vertex_of.contains(tag)) {
      vertex_of[tag] = static_cast<int>(vertices.size());
      vertices.push_back(position.at(tag));
    }
  std::vector<std::array<int, 4>> cells;
  for (std::size_t c = 0; c < model.corners.size(); ++c) {
    const int n = model.sizes[c];
    std::array<int, 4> cell{-1, -1, -1, -1};
    for (int k = 0; k < n; ++k) cell[k] = vertex_of.at(model.corners[c][k]);
    // Gmsh orders nodes along the surface orientation, which may be clockwise in the plane.
    if (twice_signed_area(vertices, cell, n) < 0.0) std::swap(cell[1], cell[n - 1]);
    cells.push_back(cell);
  }
  Mesh mesh(std::move(vertices), std::move(cells), path);
  label_physical_curves(gmsh, path, vertex_of, mesh);
  if (geometry)
    curve_edges_from_geometry(gmsh, path, vertex_of, position, mesh);
  else
    curve_edges_from_nodes(model.edges, path, vertex_of, position, mesh);
  return mesh;
}

}  // namespace hpcontact::mesh
