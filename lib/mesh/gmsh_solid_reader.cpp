// Hexahedral meshes of Gmsh files: corners in tensor order, physical surfaces as face labels.
#include "mesh/gmsh_solid_reader.hpp"

#include <fmt/format.h>

#include <Eigen/LU>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <unordered_map>

#include "core/error.hpp"
#include "mesh/gmsh_api.hpp"

namespace hpcontact::mesh {
namespace {

using Tag = std::size_t;
using Quad = std::array<int, 4>;

// Gmsh numbers a hexahedron's corners around its bottom face, then around its top one; SolidMesh
// wants the tensor order v = a + 2b + 4c. kTensorFromGmsh[v] is the Gmsh corner at tensor vertex v.
constexpr std::array<int, 8> kTensorFromGmsh{0, 1, 3, 2, 4, 5, 7, 6};

// Hexahedra per mesh_size³ of the bounding box: Gmsh's Delaunay tetrahedra of the unit cube, each
// split into four by Mesh.SubdivisionAlgorithm = 2, measured with Gmsh 4.8: 20 at size 0.1 (19976),
// 36 at size 0.2 (4500: the boundary's share); a transfinite volume ignores the size.
constexpr double kHexahedraPerSizeCubed = 20.0;

// A mesh size that would fill the memory is refused before Gmsh meshes, which it would do for
// minutes before failing without a way back.
void check_geo_size(const gmsh_api::Session& gmsh, const GeoMeshing& geo) {
  const auto [x0, y0, z0, x1, y1, z1] = gmsh.bounding_box();
  const double size = *geo.mesh_size;
  const double cells = kHexahedraPerSizeCubed * (x1 - x0) * (y1 - y0) * (z1 - z0) / (size * size * size);
  if (cells > geo.max_cells)
    throw_bad_input(geo.size_where, geo.size_key, fmt::format("{:g}", size),
                    fmt::format("about {:.3g} hexahedra in the geometry's {:g} x {:g} x {:g} bounding box, more than "
                                "the {:.3g} that fit ({}): a size of at least {:.3g}",
                                cells, x1 - x0, y1 - y0, z1 - z0, geo.max_cells, geo.max_cells_reason,
                                size * std::cbrt(cells / geo.max_cells)));
}

// The sign of the trilinear map's Jacobian determinant at the cell centre, where ∂x/∂ξ_k is the
// mean of the four edges along axis k (halved, which does not change the sign).
double centre_orientation(const std::vector<SolidPoint>& vertices, const std::array<int, 8>& cell) {
  Eigen::Matrix3d mean_edges = Eigen::Matrix3d::Zero();
  for (int e = 0; e < 12; ++e)
    mean_edges.col(e / 4) += vertices[cell[kHexEdgeVertices[e][1]]] - vertices[cell[kHexEdgeVertices[e][0]]];
  return mean_edges.determinant();
}

// The centre of a face, for messages; `vertex_at`: a vertex's position by its index.
template <typename VertexAt>
std::string centre_text(const Quad& quad, const VertexAt& vertex_at) {
  SolidPoint centre = SolidPoint::Zero();
  for (int v : quad) centre += vertex_at(v) / 4.0;
  return fmt::format("({:.6g}, {:.6g}, {:.6g})", centre.x(), centre.y(), centre.z());
}

// Two boundary faces at one place: volumes meshed without shared nodes, whose common face would be
// two free faces, a crack that no error would show. Centres are compared on a grid of 1e-9 of the
// mesh's size.
void check_no_coincident_boundary_faces(const SolidMesh& mesh, const std::string& path) {
  SolidPoint low = SolidPoint::Constant(INFINITY), high = -low;
  for (int v = 0; v < mesh.n_vertices(); ++v) {
    low = low.cwiseMin(mesh.vertex(v));
    high = high.cwiseMax(mesh.vertex(v));
  }
  const double grid = 1e-9 * std::max((high - low).maxCoeff(), 1e-300);
  std::map<std::array<long long, 3>, int> seen;
  for (const auto& face : mesh.boundary_faces()) {
    const SolidPoint x = mesh.face_centre(mesh.cell_face(face.cell, face.local_face));
    const std::array<long long, 3> key{std::llround((x.x() - low.x()) / grid), std::llround((x.y() - low.y()) / grid),
                                       std::llround((x.z() - low.z()) / grid)};
    if (!seen.try_emplace(key, 1).second)
      throw InputError(
          fmt::format("{}: two boundary faces lie at ({:.6g}, {:.6g}, {:.6g}): volumes meshed without "
                      "shared nodes, whose common face would be a crack; join them in the .geo "
                      "(BooleanFragments, or Coherence)",
                      path, x.x(), x.y(), x.z()));
  }
}

/// The hexahedra read from Gmsh's model.
struct HexahedralCells {
  std::vector<SolidPoint> vertices;
  std::vector<std::array<int, 8>> cells;
  std::unordered_map<Tag, int> index_of;  ///< node tag → vertex
};

// The hexahedra of the model: their corners (in Gmsh's node order) as vertices, the cells in tensor
// order, positively oriented.
HexahedralCells model_hexahedra(const gmsh_api::Session& gmsh, const std::string& path) {
  std::vector<Tag> tags;
  std::vector<double> coordinates;
  gmsh.nodes(tags, coordinates);
  std::unordered_map<Tag, std::size_t> position;  // node tag → index into tags
  for (std::size_t k = 0; k < tags.size(); ++k) position[tags[k]] = k;
  // Only the hexahedra's corners become vertices.
  HexahedralCells out;
  std::unordered_map<Tag, int>& index_of = out.index_of;
  std::vector<SolidPoint>& vertices = out.vertices;
  const auto vertex = [&](Tag tag) {
    const auto [it, added] = index_of.try_emplace(tag, static_cast<int>(vertices.size()));
    if (added) {
      const auto found = position.find(tag);
      if (found == position.end())
        throw InputError(fmt::format("{}: a hexahedron names node {}, which has no coordinates", path, tag));
      const std::size_t k = found->second;
      vertices.emplace_back(coordinates[3 * k], coordinates[3 * k + 1], coordinates[3 * k + 2]);
    }
    return it->second;
  };

  std::vector<std::array<int, 8>>& cells = out.cells;
  const auto blocks = gmsh.elements(3);
  for (std::size_t t = 0; t < blocks.types.size(); ++t) {
    const auto [name, order] = gmsh.element_type(blocks.types[t]);
    if (!name.starts_with("Hexahedron"))
      throw InputError(fmt::format(
          "{}: 3-D meshes take hexahedra only; found type {} ({}): in the .geo, Transfinite Volume with Recombine "
          "Surface and Recombine Volume, or Mesh.SubdivisionAlgorithm = 2 (every tetrahedron split into four "
          "hexahedra)",
          path, blocks.types[t], name));
    if (order > 1)
      throw InputError(
          fmt::format("{}: the hexahedra are of order {} ({}); 3-D cells are trilinear maps of their "
                      "corners, which would flatten curved faces: mesh with Mesh.ElementOrder = 1",
                      path, order, name));
    const auto& nodes = blocks.nodes[t];
    const std::size_t per_element = nodes.size() / blocks.tags[t].size();
    for (std::size_t e = 0; e < blocks.tags[t].size(); ++e) {
      std::array<int, 8> cell{};
      for (int v = 0; v < 8; ++v) cell[v] = vertex(nodes[per_element * e + kTensorFromGmsh[v]]);
      // (mirrored along the first axis: a + 2b + 4c ↔ (1 − a) + 2b + 4c)
      if (centre_orientation(vertices, cell) < 0.0)
        for (int v = 0; v < 8; v += 2) std::swap(cell[v], cell[v + 1]);
      cells.push_back(cell);
    }
  }
  if (cells.empty())
    throw InputError(path +
                     ": holds no hexahedra (a mesh file saved with physical groups holds only their "
                     "elements: add a Physical Volume, or save with Mesh.SaveAll = 1)");

  return out;
}

// The labels of the physical surfaces' quadrilaterals, by their sorted corners.
std::map<Quad, std::string> physical_surface_labels(const gmsh_api::Session& gmsh, const std::string& path,
                                                    const HexahedralCells& hexahedra) {
  const auto& index_of = hexahedra.index_of;
  const auto& vertices = hexahedra.vertices;
  std::map<Quad, std::string> labels;
  for (const auto& [dim, group] : gmsh.physical_groups(2)) {
    std::string label = gmsh.physical_name(dim, group);
    if (label.empty()) label = std::to_string(group);
    for (int entity : gmsh.entities_of_physical_group(dim, group)) {
      const auto faces = gmsh.elements(2, entity);
      for (std::size_t t = 0; t < faces.types.size(); ++t) {
        const auto [name, order] = gmsh.element_type(faces.types[t]);
        if (!name.starts_with("Quadrilateral"))
          throw InputError(
              fmt::format("{}: physical surface '{}' holds type {} ({}); the boundary faces of "
                          "hexahedra are quadrilaterals",
                          path, label, faces.types[t], name));
        const auto& nodes = faces.nodes[t];
        const std::size_t per_element = nodes.size() / faces.tags[t].size();
        for (std::size_t e = 0; e < faces.tags[t].size(); ++e) {
          Quad quad{};
          for (int v = 0; v < 4; ++v) {
            const auto found = index_of.find(nodes[per_element * e + v]);
            if (found == index_of.end())
              throw InputError(
                  fmt::format("{}: physical surface '{}' holds a quadrilateral whose corner (node {}) "
                              "is no corner of a hexahedron",
                              path, label, nodes[per_element * e + v]));
            quad[v] = found->second;
          }
          std::sort(quad.begin(), quad.end());
          const auto [it, added] = labels.try_emplace(quad, label);
          if (!added && it->second != label)
            throw InputError(
                fmt::format("{}: the face centred at {} lies in physical surfaces '{}' and '{}'; a "
                            "boundary face takes one",
                            path, centre_text(quad, [&](int v) { return vertices[v]; }), it->second, label));
        }
      }
    }
  }
  return labels;
}

// Every labelled quadrilateral must be a boundary face: one inside the body would be ignored.
void check_labels_on_boundary(const SolidMesh& mesh, const std::map<Quad, std::string>& labels,
                              const std::string& path) {
  std::set<Quad> boundary;
  for (const auto& face : mesh.boundary_faces()) {
    Quad quad = mesh.face(mesh.cell_face(face.cell, face.local_face));
    std::sort(quad.begin(), quad.end());
    boundary.insert(quad);
  }
  for (const auto& [quad, label] : labels)
    if (!boundary.contains(quad))
      throw InputError(
          fmt::format("{}: physical surface '{}' holds the face centred at {}, which is no boundary "
                      "face of the hexahedra",
                      path, label, centre_text(quad, [&](int v) { return mesh.vertex(v); })));
}

}  // namespace

int gmsh_file_dimension(const std::string& path) {
  gmsh_api::Session gmsh;
  gmsh.open(path);
  return gmsh.dimension();
}

SolidMesh read_gmsh_solid_mesh(const std::string& path, const GeoMeshing& geo) {
  errno = 0;
  if (!std::ifstream(path)) throw InputError(describe_io_failure("cannot open the Gmsh mesh file", path));
  const bool geometry = std::filesystem::path(path).extension() == ".geo";
  if (geo.mesh_size && !geometry)
    throw InputError(path + ": a mesh size applies to Gmsh geometry files (.geo) only, not to a mesh file");
  gmsh_api::Session gmsh;
  gmsh.open(path);
  if (geometry && geo.mesh_size) check_geo_size(gmsh, geo);
  if (geometry) gmsh.generate_volume(path, geo.mesh_size);
  if (gmsh.dimension() < 3)
    throw InputError(path + ": holds no 3-D mesh (no hexahedra; a .geo needs a Volume, a mesh file 3-D elements)");

  HexahedralCells hexahedra = model_hexahedra(gmsh, path);
  const std::map<Quad, std::string> labels = physical_surface_labels(gmsh, path, hexahedra);
  SolidMesh mesh(std::move(hexahedra.vertices), std::move(hexahedra.cells), path,
                 std::vector<std::pair<Quad, std::string>>(labels.begin(), labels.end()));
  check_no_coincident_boundary_faces(mesh, path);
  check_labels_on_boundary(mesh, labels, path);
  return mesh;
}

}  // namespace hpcontact::mesh
