// Topology (shared edges and faces, their orientation) and cell maps of hexahedral and tetrahedral
// meshes; box meshes.
#include "mesh/solid_mesh.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.hpp"

namespace hpcontact::mesh {

namespace {

/// The trilinear vertex function φ_v and its gradient at ξ.
double vertex_function(int v, const Eigen::Vector3d& xi, Eigen::Vector3d* gradient) {
  std::array<double, 3> factor{}, slope{};
  for (int k = 0; k < 3; ++k) {
    const double side = ((v >> k) & 1) != 0 ? 1.0 : -1.0;
    factor[k] = 0.5 * (1.0 + side * xi(k));
    slope[k] = 0.5 * side;
  }
  if (gradient != nullptr)
    *gradient << slope[0] * factor[1] * factor[2], factor[0] * slope[1] * factor[2], factor[0] * factor[1] * slope[2];
  return factor[0] * factor[1] * factor[2];
}

/// A face's vertices in ascending order: four, or three followed by −1.
std::array<int, 4> sorted(std::array<int, 4> face) {
  std::sort(face.begin(), face[3] < 0 ? face.begin() + 3 : face.end());
  return face;
}

const char* cell_name(SolidCellKind kind) { return kind == SolidCellKind::tetrahedron ? "tetrahedron" : "hexahedron"; }

/// The face's vertices (tensor order of the cell's face) in the face's own order: the lowest
/// first, then the lower of its two neighbours, the higher, and the opposite corner.
std::array<int, 4> canonical_face(const std::array<int, 4>& tensor) {
  const int first = static_cast<int>(std::min_element(tensor.begin(), tensor.end()) - tensor.begin());
  const int across_u = first ^ 1, across_v = first ^ 2;
  const bool u_first = tensor[across_u] < tensor[across_v];
  return {tensor[first], tensor[u_first ? across_u : across_v], tensor[u_first ? across_v : across_u],
          tensor[first ^ 3]};
}

}  // namespace

SolidMesh::SolidMesh(std::vector<SolidPoint> vertices, std::vector<std::array<int, 8>> cells, const std::string& origin,
                     const std::vector<std::pair<std::array<int, 4>, std::string>>& boundary_labels)
    : vertices_(std::move(vertices)), cells_(std::move(cells)) {
  build(origin, boundary_labels);
}

SolidMesh SolidMesh::tetrahedra(std::vector<SolidPoint> vertices, std::vector<std::array<int, 4>> cells,
                                const std::string& origin,
                                const std::vector<std::pair<std::array<int, 4>, std::string>>& boundary_labels) {
  SolidMesh mesh;
  mesh.kind_ = SolidCellKind::tetrahedron;
  mesh.vertices_ = std::move(vertices);
  mesh.cells_.reserve(cells.size());
  for (std::size_t c = 0; c < cells.size(); ++c) {
    std::array<int, 4> tet = cells[c];
    std::sort(tet.begin(), tet.end());
    if (std::adjacent_find(tet.begin(), tet.end()) != tet.end())
      throw InputError(fmt::format("{}: tetrahedron {} names vertex {} twice", origin, c,
                                   *std::adjacent_find(tet.begin(), tet.end())));
    mesh.cells_.push_back({tet[0], tet[1], tet[2], tet[3], -1, -1, -1, -1});
  }
  mesh.build(origin, boundary_labels);
  return mesh;
}

void SolidMesh::build(const std::string& origin,
                      const std::vector<std::pair<std::array<int, 4>, std::string>>& boundary_labels) {
  const char* name = cell_name(kind_);
  if (cells_.empty()) throw InputError(fmt::format("{}: the mesh has no {}", origin, name));
  for (int c = 0; c < n_cells(); ++c)
    for (int v : cell_vertices(c))
      if (v < 0 || v >= n_vertices())
        throw InputError(
            fmt::format("{}: {} {} names vertex {}, outside 0 … {}", origin, name, c, v, n_vertices() - 1));
  check_cells(origin);
  build_edges();
  build_faces(origin);
  std::map<std::array<int, 4>, std::string> labels;
  for (const auto& [face, label] : boundary_labels) labels[sorted(face)] = label;
  for (int f = 0; f < n_faces(); ++f) {
    if (!is_boundary_face(f)) continue;
    const int c = face_cells_[f][0];
    const auto faces = std::span(cell_faces_[c]).first(static_cast<std::size_t>(n_cell_faces()));
    const int local = static_cast<int>(std::find(faces.begin(), faces.end(), f) - faces.begin());
    const auto found = labels.find(sorted(faces_[f]));
    boundary_faces_.push_back({c, local, found == labels.end() ? std::string() : found->second});
  }
}

void SolidMesh::check_cells(const std::string& origin) const {
  if (is_tetrahedral()) {
    for (int c = 0; c < n_cells(); ++c) {
      const Eigen::Matrix3d j = jacobian(c, Eigen::Vector3d::Zero());
      if (!(std::abs(j.determinant()) > 1e-12 * j.colwise().norm().prod()))
        throw InputError(fmt::format("{}: the tetrahedron of vertices {}, {}, {}, {} is degenerate (volume {:.3g})",
                                     origin, cells_[c][0], cells_[c][1], cells_[c][2], cells_[c][3],
                                     4.0 / 3.0 * std::abs(j.determinant())));
    }
    return;
  }
  for (int c = 0; c < n_cells(); ++c)
    for (int v = 0; v < 8; ++v) {
      const Eigen::Vector3d corner((v & 1) ? 1.0 : -1.0, (v & 2) ? 1.0 : -1.0, (v & 4) ? 1.0 : -1.0);
      const Eigen::Matrix3d j = jacobian(c, corner);
      // Relative to the cell's size, so that a tiny but valid cell passes.
      const double scale = j.colwise().norm().prod();
      if (!(j.determinant() > 1e-12 * scale))
        throw InputError(fmt::format(
            "{}: hexahedron {} is inverted or degenerate at its vertex {} (Jacobian determinant {:.3g}); its "
            "vertices must be listed in tensor order (vertex a + 2b + 4c at corner (a, b, c)) with a positive volume",
            origin, c, cells_[c][v], j.determinant()));
    }
}

void SolidMesh::build_edges() {
  std::map<std::array<int, 2>, int> index;
  cell_edges_.resize(cells_.size());
  for (int c = 0; c < n_cells(); ++c)
    for (int e = 0; e < n_cell_edges(); ++e) {
      int a = cells_[c][local_edge_vertices(e)[0]], b = cells_[c][local_edge_vertices(e)[1]];
      if (a > b) std::swap(a, b);
      const auto [at, added] = index.try_emplace({a, b}, n_edges());
      if (added) edges_.push_back({a, b});
      cell_edges_[c][e] = at->second;
    }
}

void SolidMesh::build_faces(const std::string& origin) {
  std::map<std::array<int, 4>, int> index;
  cell_faces_.resize(cells_.size());
  for (int c = 0; c < n_cells(); ++c)
    for (int f = 0; f < n_cell_faces(); ++f) {
      std::array<int, 4> local{-1, -1, -1, -1};
      const auto corners = local_face_vertices(f);
      for (std::size_t k = 0; k < corners.size(); ++k) local[k] = cells_[c][corners[k]];
      const auto [at, added] = index.try_emplace(sorted(local), n_faces());
      if (added) {
        faces_.push_back(is_tetrahedral() ? sorted(local) : canonical_face(local));
        face_cells_.push_back({c, -1});
      } else if (face_cells_[at->second][1] >= 0) {
        throw InputError(
            fmt::format("{}: the face of vertices {} is shared by more than two cells", origin,
                        fmt::join(corners.size() == 3 ? std::span(local).first(3) : std::span(local), ", ")));
      } else {
        face_cells_[at->second][1] = c;
      }
      cell_faces_[c][f] = at->second;
    }
}

void SolidMesh::label_boundary_faces(const std::function<bool(const SolidPoint& centre)>& where,
                                     const std::string& label) {
  for (auto& face : boundary_faces_)
    if (where(face_centre(cell_faces_[face.cell][face.local_face]))) face.label = label;
}

int SolidMesh::edge_sign(int c, int local_edge) const {
  const auto ends = local_edge_vertices(local_edge);
  return cells_[c][ends[0]] < cells_[c][ends[1]] ? 1 : -1;
}

SolidMesh::FaceOrientation SolidMesh::face_orientation(int c, int local_face) const {
  HPC_VERIFY(!is_tetrahedral(), "face orientations of hexahedra");
  std::array<int, 4> tensor{};
  for (int k = 0; k < 4; ++k) tensor[k] = cells_[c][kHexFaceVertices[local_face][k]];
  const std::array<int, 4>& own = faces_[cell_faces_[c][local_face]];
  const auto local_of = [&](int vertex) {
    return static_cast<int>(std::find(tensor.begin(), tensor.end(), vertex) - tensor.begin());
  };
  const int first = local_of(own[0]), next = local_of(own[1]);
  FaceOrientation orientation;
  // S runs from the first corner to the next: along u if they differ in the u bit.
  orientation.swapped = (first ^ next) == 2;
  orientation.sign_s = (first & (orientation.swapped ? 2 : 1)) == 0 ? 1 : -1;
  orientation.sign_t = (first & (orientation.swapped ? 1 : 2)) == 0 ? 1 : -1;
  return orientation;
}

bool SolidMesh::is_affine(int c) const {
  if (is_tetrahedral()) return true;
  // Trilinear maps are affine exactly when each edge vector equals its three parallels.
  const auto& x = [&](int v) -> const SolidPoint& { return vertices_[cells_[c][v]]; };
  const double size = (x(7) - x(0)).norm();
  for (int axis = 0; axis < 3; ++axis) {
    const SolidPoint reference = x(kHexEdgeVertices[4 * axis][1]) - x(kHexEdgeVertices[4 * axis][0]);
    for (int k = 1; k < 4; ++k) {
      const auto& edge = kHexEdgeVertices[4 * axis + k];
      if ((x(edge[1]) - x(edge[0]) - reference).norm() > 1e-13 * size) return false;
    }
  }
  return true;
}

SolidPoint SolidMesh::map(int c, const Eigen::Vector3d& xi) const {
  if (is_tetrahedral()) return vertices_[cells_[c][0]] + jacobian(c, xi) * (xi + Eigen::Vector3d::Ones());
  SolidPoint x = SolidPoint::Zero();
  for (int v = 0; v < 8; ++v) x += vertex_function(v, xi, nullptr) * vertices_[cells_[c][v]];
  return x;
}

Eigen::Matrix3d SolidMesh::jacobian(int c, const Eigen::Vector3d& xi) const {
  Eigen::Matrix3d j = Eigen::Matrix3d::Zero();
  if (is_tetrahedral()) {
    // x = x0 + Σ_k (x_k − x0) (1 + ξ_k)/2
    for (int k = 0; k < 3; ++k) j.col(k) = 0.5 * (vertices_[cells_[c][k + 1]] - vertices_[cells_[c][0]]);
    return j;
  }
  Eigen::Vector3d gradient;
  for (int v = 0; v < 8; ++v) {
    vertex_function(v, xi, &gradient);
    j += vertices_[cells_[c][v]] * gradient.transpose();
  }
  return j;
}

SolidPoint SolidMesh::face_centre(int f) const {
  SolidPoint centre = SolidPoint::Zero();
  for (int k = 0; k < n_face_vertices(); ++k) centre += vertices_[faces_[f][k]] / n_face_vertices();
  return centre;
}

namespace {

/// The vertices of the tensor mesh of `nodes` (x fastest) and its hexahedra in tensor order.
struct TensorBox {
  std::vector<SolidPoint> vertices;
  std::vector<std::array<int, 8>> cells;
};

TensorBox tensor_box(const std::array<std::vector<double>, 3>& nodes, const std::string& origin) {
  for (int k = 0; k < 3; ++k) {
    if (nodes[k].size() < 2)
      throw InputError(fmt::format("{}: {} nodes along {}; at least 2", origin, nodes[k].size(), "xyz"[k]));
    for (std::size_t i = 0; i + 1 < nodes[k].size(); ++i)
      if (!(nodes[k][i + 1] > nodes[k][i]))
        throw InputError(fmt::format("{}: the nodes along {} must increase strictly ({} then {})", origin, "xyz"[k],
                                     nodes[k][i], nodes[k][i + 1]));
  }
  const std::array<int, 3> n{static_cast<int>(nodes[0].size()) - 1, static_cast<int>(nodes[1].size()) - 1,
                             static_cast<int>(nodes[2].size()) - 1};
  const auto vertex = [&](int i, int j, int k) { return i + (n[0] + 1) * (j + (n[1] + 1) * k); };
  TensorBox box;
  box.vertices.reserve(static_cast<std::size_t>(n[0] + 1) * (n[1] + 1) * (n[2] + 1));
  for (int k = 0; k <= n[2]; ++k)
    for (int j = 0; j <= n[1]; ++j)
      for (int i = 0; i <= n[0]; ++i) box.vertices.emplace_back(nodes[0][i], nodes[1][j], nodes[2][k]);
  box.cells.reserve(static_cast<std::size_t>(n[0]) * n[1] * n[2]);
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        std::array<int, 8> cell{};
        for (int v = 0; v < 8; ++v) cell[v] = vertex(i + (v & 1), j + ((v >> 1) & 1), k + ((v >> 2) & 1));
        box.cells.push_back(cell);
      }
  return box;
}

/// Labels the faces (vertex lists, −1 padded) that lie on a side of the box by that side's name.
void label_box_sides(const std::array<std::vector<double>, 3>& nodes, const std::vector<SolidPoint>& vertices,
                     const std::array<int, 4>& face, std::vector<std::pair<std::array<int, 4>, std::string>>& labels) {
  static const std::array<const char*, 6> names{"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};
  for (int side = 0; side < 6; ++side) {
    const int axis = side / 2;
    const double at = side % 2 == 0 ? nodes[axis].front() : nodes[axis].back();
    bool on_side = true;
    for (int v : face) on_side = on_side && (v < 0 || vertices[v](axis) == at);
    if (on_side) labels.emplace_back(face, names[side]);
  }
}

}  // namespace

SolidMesh make_tensor_box_mesh(const std::array<std::vector<double>, 3>& nodes, const std::string& origin) {
  TensorBox box = tensor_box(nodes, origin);
  std::vector<std::pair<std::array<int, 4>, std::string>> labels;
  for (const auto& cell : box.cells)
    for (const auto& corners : kHexFaceVertices)
      label_box_sides(nodes, box.vertices, {cell[corners[0]], cell[corners[1]], cell[corners[2]], cell[corners[3]]},
                      labels);
  return SolidMesh(std::move(box.vertices), std::move(box.cells), origin, labels);
}

SolidMesh make_tetrahedral_box_mesh(const std::array<std::vector<double>, 3>& nodes, const std::string& origin) {
  TensorBox box = tensor_box(nodes, origin);
  std::vector<std::array<int, 4>> tetrahedra;
  tetrahedra.reserve(6 * box.cells.size());
  // Each of the six paths 0 → e_a → e_a + e_b → 7 along the edges of the cube spans one tetrahedron.
  static constexpr std::array<std::array<int, 2>, 6> kPaths{{{0, 1}, {0, 2}, {1, 0}, {1, 2}, {2, 0}, {2, 1}}};
  for (const auto& cell : box.cells)
    for (const auto& [a, b] : kPaths) tetrahedra.push_back({cell[0], cell[1 << a], cell[(1 << a) | (1 << b)], cell[7]});
  std::vector<std::pair<std::array<int, 4>, std::string>> labels;
  for (const auto& tet : tetrahedra)
    for (const auto& corners : kTetFaceVertices)
      label_box_sides(nodes, box.vertices, {tet[corners[0]], tet[corners[1]], tet[corners[2]], -1}, labels);
  return SolidMesh::tetrahedra(std::move(box.vertices), std::move(tetrahedra), origin, labels);
}

SolidMesh make_box_mesh(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, const std::array<int, 3>& n) {
  std::array<std::vector<double>, 3> nodes;
  for (int k = 0; k < 3; ++k) {
    if (n[k] < 1) throw InputError(fmt::format("box mesh: {} cells along axis {}; at least 1", n[k], "xyz"[k]));
    if (!(hi(k) > lo(k)))
      throw InputError(fmt::format("box mesh: the box is empty along {} ([{}, {}])", "xyz"[k], lo(k), hi(k)));
    for (int i = 0; i <= n[k]; ++i) nodes[k].push_back(i == n[k] ? hi(k) : lo(k) + (hi(k) - lo(k)) * i / n[k]);
  }
  return make_tensor_box_mesh(nodes, "box mesh");
}

}  // namespace hpcontact::mesh
