// Conforming mesh of a 3-D domain of hexahedra (trilinear cell maps) or of tetrahedra (affine
// maps): vertices, cells, the edges and faces they share (numbered once, oriented by global vertex
// numbers) and labelled boundary faces; structured meshes of boxes.
#pragma once

#include <Eigen/Core>
#include <array>
#include <functional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "basis/solid_cell_topology.hpp"

namespace hpcontact::mesh {

using SolidPoint = Eigen::Vector3d;

// The reference cells' local numbering (basis/solid_cell_topology.hpp).
using basis::kHexEdgeVertices;
using basis::kHexFaceAxes;
using basis::kHexFaceVertices;
using basis::kTetEdgeVertices;
using basis::kTetFaceVertices;
using basis::SolidCellKind;

/// One boundary face of a solid mesh: its cell, local face and label ("x_min", …, or a Gmsh
/// physical surface's name; empty if it has none).
struct BoundaryFace {
  int cell = -1;
  int local_face = -1;
  std::string label;
};

class SolidMesh {
 public:
  /// Cells list their eight vertices in the tensor order above. `boundary_labels`: per boundary
  /// face (found from the cells), its label by its sorted vertex quadruple (faces not listed are
  /// unlabelled).
  /// @throws InputError naming `origin` if a cell is inverted or degenerate (its Jacobian
  /// determinant is not positive at every vertex) or a face is shared by more than two cells.
  SolidMesh(std::vector<SolidPoint> vertices, std::vector<std::array<int, 8>> cells, const std::string& origin,
            const std::vector<std::pair<std::array<int, 4>, std::string>>& boundary_labels = {});
  /// A mesh of tetrahedra, each given by its four vertices in any order; the mesh lists them in
  /// ascending order (basis/solid_cell_topology.hpp), whatever the sign of the volume that gives.
  /// `boundary_labels`: per boundary triangle its label by its vertex triple (any order), the
  /// fourth entry −1. @throws InputError naming `origin` if a tetrahedron is degenerate (volume
  /// below 1e-12 of the product of its edge lengths from its first vertex), names a vertex twice or
  /// a face is shared by more than two cells.
  static SolidMesh tetrahedra(std::vector<SolidPoint> vertices, std::vector<std::array<int, 4>> cells,
                              const std::string& origin,
                              const std::vector<std::pair<std::array<int, 4>, std::string>>& boundary_labels = {});

  SolidCellKind kind() const { return kind_; }
  bool is_tetrahedral() const { return kind_ == SolidCellKind::tetrahedron; }
  /// 8 and 4; 12 and 6 edges; 6 and 4 faces of 4 and 3 vertices.
  int n_cell_vertices() const { return is_tetrahedral() ? 4 : 8; }
  int n_cell_edges() const { return is_tetrahedral() ? 6 : 12; }
  int n_cell_faces() const { return is_tetrahedral() ? 4 : 6; }
  int n_face_vertices() const { return is_tetrahedral() ? 3 : 4; }
  /// Local vertices of a cell's local edge and face (kHex… or kTet… tables).
  std::array<int, 2> local_edge_vertices(int local_edge) const {
    return is_tetrahedral() ? kTetEdgeVertices[local_edge] : kHexEdgeVertices[local_edge];
  }
  std::span<const int> local_face_vertices(int local_face) const {
    if (is_tetrahedral()) return kTetFaceVertices[local_face];
    return kHexFaceVertices[local_face];
  }

  int n_vertices() const { return static_cast<int>(vertices_.size()); }
  int n_cells() const { return static_cast<int>(cells_.size()); }
  int n_edges() const { return static_cast<int>(edges_.size()); }
  int n_faces() const { return static_cast<int>(faces_.size()); }
  const SolidPoint& vertex(int v) const { return vertices_[v]; }
  /// The cell's vertices: 8 in tensor order, or 4 in ascending order followed by four −1.
  const std::array<int, 8>& cell(int c) const { return cells_[c]; }
  std::span<const int> cell_vertices(int c) const {
    return {cells_[c].data(), static_cast<std::size_t>(n_cell_vertices())};
  }
  /// Global vertices of edge e, lower first (the edge's direction).
  const std::array<int, 2>& edge(int e) const { return edges_[e]; }
  int cell_edge(int c, int local_edge) const { return cell_edges_[c][local_edge]; }
  /// Global vertices of face f in the face's own order. A square: its lowest global vertex first,
  /// its first axis towards the lower of that vertex's two neighbours on the face. A triangle: its
  /// vertices ascending, the fourth entry −1.
  const std::array<int, 4>& face(int f) const { return faces_[f]; }
  int cell_face(int c, int local_face) const { return cell_faces_[c][local_face]; }
  /// +1 if local edge `local_edge` of cell c (lower to upper local vertex) runs as its global edge.
  int edge_sign(int c, int local_edge) const;
  /// How the face's own axes (S, T) (see face) lie in the cell's local face coordinates (u, v)
  /// (the face's free axes in kHexFaceAxes order): S = sign_s · (swapped ? v : u),
  /// T = sign_t · (swapped ? u : v).
  struct FaceOrientation {
    bool swapped = false;
    int sign_s = 1, sign_t = 1;
  };
  /// Hexahedra only (a tetrahedron's faces run as their global ones).
  FaceOrientation face_orientation(int c, int local_face) const;
  /// The one or two cells of face f (second −1 on the boundary).
  const std::array<int, 2>& face_cells(int f) const { return face_cells_[f]; }
  bool is_boundary_face(int f) const { return face_cells_[f][1] < 0; }
  const std::vector<BoundaryFace>& boundary_faces() const { return boundary_faces_; }
  /// Gives `label` to the boundary faces whose centre satisfies `where` (the others keep theirs).
  void label_boundary_faces(const std::function<bool(const SolidPoint& centre)>& where, const std::string& label);
  /// Gives `label` to boundary face k (an entry of boundary_faces()).
  void set_boundary_face_label(std::size_t k, std::string label) { boundary_faces_.at(k).label = std::move(label); }
  /// Whether the cell map is affine (a tetrahedron or a parallelepiped), so that its Jacobian is constant.
  bool is_affine(int c) const;
  /// x(ξ) = Σ_v x_v φ_v(ξ) with the trilinear vertex functions φ_v, or the barycentric ones of the
  /// reference tetrahedron.
  SolidPoint map(int c, const Eigen::Vector3d& xi) const;
  /// The image of the reference cell's centroid (ξ = 0 on hexahedra, (−1/2, −1/2, −1/2) on tetrahedra).
  SolidPoint cell_centre(int c) const {
    return map(c, is_tetrahedral() ? Eigen::Vector3d::Constant(-0.5) : Eigen::Vector3d::Zero());
  }
  /// ∂x/∂ξ at ξ: column k is ∂x/∂ξ_k.
  Eigen::Matrix3d jacobian(int c, const Eigen::Vector3d& xi) const;
  /// The centroid of the face's vertices.
  SolidPoint face_centre(int f) const;

 private:
  SolidMesh() = default;
  void build(const std::string& origin, const std::vector<std::pair<std::array<int, 4>, std::string>>& boundary_labels);
  void build_edges();
  void build_faces(const std::string& origin);
  void check_cells(const std::string& origin) const;

  SolidCellKind kind_ = SolidCellKind::hexahedron;
  std::vector<SolidPoint> vertices_;
  std::vector<std::array<int, 8>> cells_;
  std::vector<std::array<int, 2>> edges_;
  std::vector<std::array<int, 12>> cell_edges_;
  std::vector<std::array<int, 4>> faces_;
  std::vector<std::array<int, 6>> cell_faces_;
  std::vector<std::array<int, 2>> face_cells_;
  std::vector<BoundaryFace> boundary_faces_;
};

/// The tensor mesh of the node coordinates along x, y and z (each strictly increasing, at least two),
/// vertices numbered x fastest; boundary faces labelled by side as make_box_mesh's.
/// @throws InputError naming `origin` otherwise.
SolidMesh make_tensor_box_mesh(const std::array<std::vector<double>, 3>& nodes, const std::string& origin);

/// The tensor box mesh of `nodes` with each hexahedron cut into six tetrahedra around its diagonal
/// from corner 0 to corner 7 (Kuhn's subdivision, conforming across hexahedra); boundary triangles
/// labelled by side as make_box_mesh's. @throws InputError as make_tensor_box_mesh.
SolidMesh make_tetrahedral_box_mesh(const std::array<std::vector<double>, 3>& nodes, const std::string& origin);

/// The box [lo, hi] (componentwise) cut into n[0] × n[1] × n[2] equal hexahedra, vertices
/// numbered x fastest. Boundary faces are labelled "x_min", "x_max", "y_min", "y_max", "z_min",
/// "z_max". @throws InputError if a count is < 1 or the box is empty.
SolidMesh make_box_mesh(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, const std::array<int, 3>& n);

}  // namespace hpcontact::mesh
