// Hexahedral and tetrahedral meshes of Gmsh files: corners in SolidMesh's order, physical surfaces
// as face labels.
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
using Quad = std::array<int, 4>;  ///< a face's vertices: four, or a triangle's three and −1

/// The face's vertices ascending (the −1 of a triangle last), the key of labels.
Quad face_key(Quad face) {
  std::sort(face.begin(), face[3] < 0 ? face.begin() + 3 : face.end());
  return face;
}

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
  const int corners = quad[3] < 0 ? 3 : 4;
  for (int k = 0; k < corners; ++k) centre += vertex_at(quad[k]) / corners;
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

/// The cells read from Gmsh's model: hexahedra or tetrahedra.
struct SolidCells {
  std::vector<SolidPoint> vertices;
  std::vector<std::array<int, 8>> hexahedra;
  std::vector<std::array<int, 4>> tetrahedra;
  std::unordered_map<Tag, int> index_of;  ///< node tag → vertex
  bool tetrahedral() const { return !tetrahedra.empty(); }
};

// The cells of the model: their corners (in Gmsh's node order) as vertices, hexahedra in tensor
// order and positively oriented, tetrahedra as Gmsh lists them (SolidMesh orders them).
SolidCells model_cells(const gmsh_api::Session& gmsh, const std::string& path) {
  std::vector<Tag> tags;
  std::vector<double> coordinates;
  gmsh.nodes(tags, coordinates);
  std::unordered_map<Tag, std::size_t> position;  // node tag → index into tags
  for (std::size_t k = 0; k < tags.size(); ++k) position[tags[k]] = k;
  // Only the cells' corners become vertices.
  SolidCells out;
  std::unordered_map<Tag, int>& index_of = out.index_of;
  std::vector<SolidPoint>& vertices = out.vertices;
  const auto vertex = [&](Tag tag) {
    const auto [it, added] = index_of.try_emplace(tag, static_cast<int>(vertices.size()));
    if (added) {
      const auto found = position.find(tag);
      if (found == position.end())
        throw InputError(fmt::format("{}: a cell names node {}, which has no coordinates", path, tag));
      const std::size_t k = found->second;
      vertices.emplace_back(coordinates[3 * k], coordinates[3 * k + 1], coordinates[3 * k + 2]);
    }
    return it->second;
  };

  const auto blocks = gmsh.elements(3);
  for (std::size_t t = 0; t < blocks.types.size(); ++t) {
    const auto [name, order] = gmsh.element_type(blocks.types[t]);
    const bool hexahedron = name.starts_with("Hexahedron"), tetrahedron = name.starts_with("Tetrahedron");
    if (!hexahedron && !tetrahedron)
      throw InputError(
          fmt::format("{}: 3-D meshes take hexahedra or tetrahedra; found type {} ({}): in the .geo, no Recombine for "
                      "tetrahedra; Transfinite Volume with Recombine Surface and Recombine Volume, or "
                      "Mesh.SubdivisionAlgorithm = 2 (every tetrahedron split into four hexahedra), for hexahedra",
                      path, blocks.types[t], name));
    if (order > 1)
      throw InputError(
          fmt::format("{}: the cells are of order {} ({}); 3-D cells are trilinear or affine maps of "
                      "their corners, which would flatten curved faces: mesh with Mesh.ElementOrder = 1",
                      path, order, name));
    const auto& nodes = blocks.nodes[t];
    const std::size_t per_element = nodes.size() / blocks.tags[t].size();
    for (std::size_t e = 0; e < blocks.tags[t].size(); ++e) {
      if (tetrahedron) {
        std::array<int, 4> cell{};
        for (int v = 0; v < 4; ++v) cell[v] = vertex(nodes[per_element * e + v]);
        out.tetrahedra.push_back(cell);
        continue;
      }
      std::array<int, 8> cell{};
      for (int v = 0; v < 8; ++v) cell[v] = vertex(nodes[per_element * e + kTensorFromGmsh[v]]);
      // (mirrored along the first axis: a + 2b + 4c ↔ (1 − a) + 2b + 4c)
      if (centre_orientation(vertices, cell) < 0.0)
        for (int v = 0; v < 8; v += 2) std::swap(cell[v], cell[v + 1]);
      out.hexahedra.push_back(cell);
    }
  }
  if (out.hexahedra.empty() && out.tetrahedra.empty())
    throw InputError(path +
                     ": holds no hexahedra or tetrahedra (a mesh file saved with physical groups holds only "
                     "their elements: add a Physical Volume, or save with Mesh.SaveAll = 1)");
  if (!out.hexahedra.empty() && !out.tetrahedra.empty())
    throw InputError(
        fmt::format("{}: mixes {} hexahedra and {} tetrahedra; a conforming mesh of both needs "
                    "pyramids between them, which are not built: mesh with one kind",
                    path, out.hexahedra.size(), out.tetrahedra.size()));
  return out;
}

// The labels of the physical surfaces' quadrilaterals or triangles, by their sorted corners.
std::map<Quad, std::string> physical_surface_labels(const gmsh_api::Session& gmsh, const std::string& path,
                                                    const SolidCells& cells) {
  const auto& index_of = cells.index_of;
  const auto& vertices = cells.vertices;
  const char* face_name = cells.tetrahedral() ? "Triangle" : "Quadrilateral";
  const int corners = cells.tetrahedral() ? 3 : 4;
  std::map<Quad, std::string> labels;
  for (const auto& [dim, group] : gmsh.physical_groups(2)) {
    std::string label = gmsh.physical_name(dim, group);
    if (label.empty()) label = std::to_string(group);
    for (int entity : gmsh.entities_of_physical_group(dim, group)) {
      const auto faces = gmsh.elements(2, entity);
      for (std::size_t t = 0; t < faces.types.size(); ++t) {
        const auto [name, order] = gmsh.element_type(faces.types[t]);
        if (!name.starts_with(face_name))
          throw InputError(fmt::format("{}: physical surface '{}' holds type {} ({}); the boundary faces of {} are {}",
                                       path, label, faces.types[t], name,
                                       cells.tetrahedral() ? "tetrahedra" : "hexahedra",
                                       cells.tetrahedral() ? "triangles" : "quadrilaterals"));
        const auto& nodes = faces.nodes[t];
        const std::size_t per_element = nodes.size() / faces.tags[t].size();
        for (std::size_t e = 0; e < faces.tags[t].size(); ++e) {
          Quad quad{-1, -1, -1, -1};
          for (int v = 0; v < corners; ++v) {
            const auto found = index_of.find(nodes[per_element * e + v]);
            if (found == index_of.end())
              throw InputError(
                  fmt::format("{}: physical surface '{}' holds a face whose corner (node {}) is no "
                              "corner of a cell",
                              path, label, nodes[per_element * e + v]));
            quad[v] = found->second;
          }
          quad = face_key(quad);
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
    boundary.insert(face_key(mesh.face(mesh.cell_face(face.cell, face.local_face))));
  }
  for (const auto& [quad, label] : labels)
    if (!boundary.contains(quad))
      throw InputError(
          fmt::format("{}: physical surface '{}' holds the face centred at {}, which is no boundary "
                      "face of the cells",
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
    throw InputError(path + ": holds no 3-D mesh (no cells; a .geo needs a Volume, a mesh file 3-D elements)");

  SolidCells cells = model_cells(gmsh, path);
  const std::map<Quad, std::string> labels = physical_surface_labels(gmsh, path, cells);
  std::vector<std::pair<Quad, std::string>> label_list(labels.begin(), labels.end());
  SolidMesh mesh = cells.tetrahedral()
                       ? SolidMesh::tetrahedra(std::move(cells.vertices), std::move(cells.tetrahedra), path, label_list)
                       : SolidMesh(std::move(cells.vertices), std::move(cells.hexahedra), path, label_list);
  check_no_coincident_boundary_faces(mesh, path);
  check_labels_on_boundary(mesh, labels, path);
  return mesh;
}

}  // namespace hpcontact::mesh
