// Numbering and local shapes of the Q_p (hexahedra) and P_p (tetrahedra) spaces: minimum-rule
// degrees on edges and faces, orientation of edge and face modes by global vertex numbers,
// Dirichlet elimination.
#include "space/solid_space.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <string>

#include "basis/tetrahedron_basis.hpp"
#include "core/error.hpp"

namespace hpcontact::space {

namespace {

/// (−1)^k for a sign s = ±1.
float power_sign(int sign, int k) { return sign < 0 && k % 2 != 0 ? -1.0F : 1.0F; }

/// Modes of a face and interior modes of a cell of degree p.
int face_mode_count(const mesh::SolidMesh& mesh, int p) {
  return mesh.is_tetrahedral() ? basis::triangle_face_mode_count(p) : (p - 1) * (p - 1);
}
int interior_mode_count(const mesh::SolidMesh& mesh, int p) {
  return mesh.is_tetrahedral() ? basis::tetrahedron_interior_mode_count(p) : (p - 1) * (p - 1) * (p - 1);
}

std::int16_t narrow(int i) { return static_cast<std::int16_t>(i); }

}  // namespace

SolidH1Space::SolidH1Space(const mesh::SolidMesh& mesh, std::vector<int> cell_degrees,
                           const std::vector<char>& dirichlet_faces)
    : mesh_(&mesh), cell_degrees_(std::move(cell_degrees)) {
  if (static_cast<int>(cell_degrees_.size()) != mesh.n_cells())
    throw InputError(fmt::format("{} degrees given for {} cells", cell_degrees_.size(), mesh.n_cells()));
  if (!dirichlet_faces.empty() && static_cast<int>(dirichlet_faces.size()) != mesh.n_faces())
    throw InputError(fmt::format("{} Dirichlet flags given for {} faces", dirichlet_faces.size(), mesh.n_faces()));
  for (int c = 0; c < mesh.n_cells(); ++c) {
    if (cell_degrees_[c] < 1)
      throw InputError(fmt::format("cell {} has degree {}; degrees are at least 1", c, cell_degrees_[c]));
    max_degree_ = std::max(max_degree_, cell_degrees_[c]);
  }
  // The minimum rule: each edge and face carries the smallest degree of its cells.
  edge_degrees_.assign(mesh.n_edges(), max_degree_);
  face_degrees_.assign(mesh.n_faces(), max_degree_);
  for (int c = 0; c < mesh.n_cells(); ++c) {
    for (int e = 0; e < mesh.n_cell_edges(); ++e) {
      int& degree = edge_degrees_[mesh.cell_edge(c, e)];
      degree = std::min(degree, cell_degrees_[c]);
    }
    for (int f = 0; f < mesh.n_cell_faces(); ++f) {
      int& degree = face_degrees_[mesh.cell_face(c, f)];
      degree = std::min(degree, cell_degrees_[c]);
    }
  }
  number_dofs(dirichlet_faces);
}

void SolidH1Space::number_dofs(const std::vector<char>& dirichlet_faces) {
  const mesh::SolidMesh& mesh = *mesh_;
  std::vector<char> vertex_fixed(mesh.n_vertices(), 0), edge_fixed(mesh.n_edges(), 0);
  std::vector<char> face_fixed(mesh.n_faces(), 0);
  for (int f = 0; f < static_cast<int>(dirichlet_faces.size()); ++f) {
    if (!dirichlet_faces[f]) continue;
    if (!mesh.is_boundary_face(f))
      throw InputError(fmt::format("face {} is flagged for Γ_D but lies inside the mesh", f));
    face_fixed[f] = 1;
  }
  for (const auto& boundary : mesh.boundary_faces()) {
    const int f = mesh.cell_face(boundary.cell, boundary.local_face);
    if (!face_fixed[f]) continue;
    for (int k = 0; k < mesh.n_face_vertices(); ++k) vertex_fixed[mesh.face(f)[k]] = 1;
    for (int e = 0; e < mesh.n_cell_edges(); ++e) {
      const auto ends = mesh.local_edge_vertices(e);
      const auto face = mesh.local_face_vertices(boundary.local_face);
      if (std::count(face.begin(), face.end(), ends[0]) != 0 && std::count(face.begin(), face.end(), ends[1]) != 0)
        edge_fixed[mesh.cell_edge(boundary.cell, e)] = 1;
    }
  }
  int next = 0;
  vertex_dofs_.resize(mesh.n_vertices());
  for (int v = 0; v < mesh.n_vertices(); ++v) vertex_dofs_[v] = vertex_fixed[v] ? -1 : next++;
  edge_first_dofs_.resize(mesh.n_edges());
  for (int e = 0; e < mesh.n_edges(); ++e) {
    edge_first_dofs_[e] = edge_fixed[e] ? -1 : next;
    if (!edge_fixed[e]) next += edge_degrees_[e] - 1;
  }
  face_first_dofs_.resize(mesh.n_faces());
  for (int f = 0; f < mesh.n_faces(); ++f) {
    const int modes = face_mode_count(mesh, face_degrees_[f]);
    face_first_dofs_[f] = face_fixed[f] ? -1 : next;
    if (!face_fixed[f]) next += modes;
  }
  n_skeleton_dofs_ = next;
  first_shape_.assign(1, 0);
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const int p = cell_degrees_[c];
    if (mesh.is_tetrahedral())
      append_tetrahedron_shapes(c, next);
    else
      append_shapes(c, next);
    next += interior_mode_count(mesh, p);
    first_shape_.push_back(static_cast<std::int64_t>(shapes_.size()));
  }
  n_dofs_ = next;
}

void SolidH1Space::append_shapes(int cell, int first_interior) {
  const mesh::SolidMesh& mesh = *mesh_;
  const auto bit = [](int vertex, int axis) { return static_cast<std::int16_t>((vertex >> axis) & 1); };
  for (int v = 0; v < 8; ++v) {
    SolidShape shape;
    shape.index = {bit(v, 0), bit(v, 1), bit(v, 2)};
    shape.dof = vertex_dofs_[mesh.cell(cell)[v]];
    shape.entity = static_cast<std::int8_t>(v);
    shapes_.push_back(shape);
  }
  for (int e = 0; e < 12; ++e) {
    const int edge = mesh.cell_edge(cell, e), axis = e / 4, lower = mesh::kHexEdgeVertices[e][0];
    const int sign = mesh.edge_sign(cell, e);
    for (int k = 2; k <= edge_degrees_[edge]; ++k) {
      SolidShape shape;
      shape.index = {bit(lower, 0), bit(lower, 1), bit(lower, 2)};
      shape.index[axis] = static_cast<std::int16_t>(k);
      shape.dof = edge_first_dofs_[edge] < 0 ? -1 : edge_first_dofs_[edge] + k - 2;
      shape.sign = power_sign(sign, k);
      shape.role = SolidShapeRole::edge;
      shape.entity = static_cast<std::int8_t>(e);
      shapes_.push_back(shape);
    }
  }
  for (int f = 0; f < 6; ++f) {
    const int face = mesh.cell_face(cell, f), p = face_degrees_[face];
    const auto [u_axis, v_axis] = mesh::kHexFaceAxes[f];
    const mesh::SolidMesh::FaceOrientation orientation = mesh.face_orientation(cell, f);
    for (int a = 2; a <= p; ++a)
      for (int b = 2; b <= p; ++b) {
        SolidShape shape;
        shape.index[f / 2] = static_cast<std::int16_t>(f % 2);
        shape.index[u_axis] = static_cast<std::int16_t>(a);
        shape.index[v_axis] = static_cast<std::int16_t>(b);
        // The face's mode (s, t) = N_s(S) N_t(T) is, in the cell's (u, v), ± N_a(u) N_b(v).
        const int s = orientation.swapped ? b : a, t = orientation.swapped ? a : b;
        shape.dof = face_first_dofs_[face] < 0 ? -1 : face_first_dofs_[face] + (s - 2) * (p - 1) + (t - 2);
        shape.sign = power_sign(orientation.sign_s, s) * power_sign(orientation.sign_t, t);
        shape.role = SolidShapeRole::face;
        shape.entity = static_cast<std::int8_t>(f);
        shapes_.push_back(shape);
      }
  }
  const int p = cell_degrees_[cell];
  int next = first_interior;
  for (int i = 2; i <= p; ++i)
    for (int j = 2; j <= p; ++j)
      for (int k = 2; k <= p; ++k) {
        SolidShape shape;
        shape.index = {static_cast<std::int16_t>(i), static_cast<std::int16_t>(j), static_cast<std::int16_t>(k)};
        shape.dof = next++;
        shape.role = SolidShapeRole::interior;
        shapes_.push_back(shape);
      }
}

void SolidH1Space::append_tetrahedron_shapes(int cell, int first_interior) {
  const mesh::SolidMesh& mesh = *mesh_;
  const auto add = [&](SolidShapeRole role, int entity, std::array<std::int16_t, 3> index, int dof) {
    SolidShape shape;
    shape.index = index;
    shape.dof = dof;
    shape.role = role;
    shape.entity = static_cast<std::int8_t>(entity);
    shapes_.push_back(shape);
  };
  // Local edges and faces run as their global ones (ascending vertices): no signs, no swaps.
  for (int v = 0; v < 4; ++v) add(SolidShapeRole::vertex, v, {}, vertex_dofs_[mesh.cell(cell)[v]]);
  for (int e = 0; e < 6; ++e) {
    const int edge = mesh.cell_edge(cell, e);
    for (int k = 2; k <= edge_degrees_[edge]; ++k)
      add(SolidShapeRole::edge, e, {narrow(k), 0, 0}, edge_first_dofs_[edge] < 0 ? -1 : edge_first_dofs_[edge] + k - 2);
  }
  for (int f = 0; f < 4; ++f) {
    const int face = mesh.cell_face(cell, f), n_max = face_degrees_[face] - 3;
    int next = face_first_dofs_[face];
    for (int n1 = 0; n1 <= n_max; ++n1)
      for (int n2 = 0; n1 + n2 <= n_max; ++n2) {
        add(SolidShapeRole::face, f, {narrow(n1), narrow(n2), 0}, next < 0 ? -1 : next);
        if (next >= 0) ++next;
      }
  }
  const int n_max = cell_degrees_[cell] - 4;
  int next = first_interior;
  for (int n1 = 0; n1 <= n_max; ++n1)
    for (int n2 = 0; n1 + n2 <= n_max; ++n2)
      for (int n3 = 0; n1 + n2 + n3 <= n_max; ++n3)
        add(SolidShapeRole::interior, -1, {narrow(n1), narrow(n2), narrow(n3)}, next++);
}

Eigen::VectorXd local_coefficients(const SolidH1Space& space, int cell, const Eigen::VectorXd& coefficients) {
  const auto shapes = space.cell_shapes(cell);
  Eigen::VectorXd local = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(shapes.size()));
  for (std::size_t s = 0; s < shapes.size(); ++s)
    if (shapes[s].dof >= 0) local(static_cast<Eigen::Index>(s)) = shapes[s].sign * coefficients(shapes[s].dof);
  return local;
}

bool shape_on_face(const mesh::SolidMesh& mesh, const SolidShape& shape, int local_face) {
  const auto corners = mesh.local_face_vertices(local_face);
  const auto has = [&](int v) { return std::find(corners.begin(), corners.end(), v) != corners.end(); };
  switch (shape.role) {
    case SolidShapeRole::vertex:
      return has(shape.entity);
    case SolidShapeRole::edge:
      return has(mesh.local_edge_vertices(shape.entity)[0]) && has(mesh.local_edge_vertices(shape.entity)[1]);
    case SolidShapeRole::face:
      return shape.entity == local_face;
    case SolidShapeRole::interior:
      return false;
  }
  return false;
}

std::vector<char> faces_labelled(const mesh::SolidMesh& mesh, const std::vector<std::string>& labels) {
  std::vector<char> flagged(mesh.n_faces(), 0);
  for (const auto& boundary : mesh.boundary_faces())
    if (std::find(labels.begin(), labels.end(), boundary.label) != labels.end())
      flagged[mesh.cell_face(boundary.cell, boundary.local_face)] = 1;
  return flagged;
}

}  // namespace hpcontact::space
