// Conforming mesh of a 3-D domain of hexahedra with trilinear cell maps: vertices, cells, the
// edges and faces they share (numbered once, oriented by global vertex numbers) and labelled
// boundary faces; structured meshes of boxes.
#pragma once

#include <Eigen/Core>
#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace hpcontact::mesh {

using SolidPoint = Eigen::Vector3d;

/// Local numbering of the reference hexahedron [-1, 1]³, tensor ordered: vertex v = a + 2b + 4c
/// sits at (2a − 1, 2b − 1, 2c − 1). Local edge e runs along axis e / 4 from its lower to its
/// upper local vertex (kHexEdgeVertices). Local face f lies at coordinate f % 2 == 0 ? −1 : +1
/// of axis f / 2; its vertices are listed in the tensor order of its two free axes
/// (kHexFaceAxes: the lower axis first).
inline constexpr std::array<std::array<int, 2>, 12> kHexEdgeVertices{
    {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3}, {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};
inline constexpr std::array<std::array<int, 4>, 6> kHexFaceVertices{
    {{0, 2, 4, 6}, {1, 3, 5, 7}, {0, 1, 4, 5}, {2, 3, 6, 7}, {0, 1, 2, 3}, {4, 5, 6, 7}}};
inline constexpr std::array<std::array<int, 2>, 6> kHexFaceAxes{{{1, 2}, {1, 2}, {0, 2}, {0, 2}, {0, 1}, {0, 1}}};

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

  int n_vertices() const { return static_cast<int>(vertices_.size()); }
  int n_cells() const { return static_cast<int>(cells_.size()); }
  int n_edges() const { return static_cast<int>(edges_.size()); }
  int n_faces() const { return static_cast<int>(faces_.size()); }
  const SolidPoint& vertex(int v) const { return vertices_[v]; }
  const std::array<int, 8>& cell(int c) const { return cells_[c]; }
  /// Global vertices of edge e, lower first (the edge's direction).
  const std::array<int, 2>& edge(int e) const { return edges_[e]; }
  int cell_edge(int c, int local_edge) const { return cell_edges_[c][local_edge]; }
  /// Global vertices of face f in the face's own tensor order: its lowest global vertex first, its
  /// first axis towards the lower of that vertex's two neighbours on the face.
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
  FaceOrientation face_orientation(int c, int local_face) const;
  /// The one or two cells of face f (second −1 on the boundary).
  const std::array<int, 2>& face_cells(int f) const { return face_cells_[f]; }
  bool is_boundary_face(int f) const { return face_cells_[f][1] < 0; }
  const std::vector<BoundaryFace>& boundary_faces() const { return boundary_faces_; }
  /// Gives `label` to the boundary faces whose centre satisfies `where` (the others keep theirs).
  void label_boundary_faces(const std::function<bool(const SolidPoint& centre)>& where, const std::string& label);
  /// Gives `label` to boundary face k (an entry of boundary_faces()).
  void set_boundary_face_label(std::size_t k, std::string label) { boundary_faces_.at(k).label = std::move(label); }
  /// Whether the cell map is affine (a parallelepiped), so that its Jacobian is constant.
  bool is_affine(int c) const;
  /// x(ξ) = Σ_v x_v φ_v(ξ) with the trilinear vertex functions φ_v.
  SolidPoint map(int c, const Eigen::Vector3d& xi) const;
  /// ∂x/∂ξ at ξ: column k is ∂x/∂ξ_k.
  Eigen::Matrix3d jacobian(int c, const Eigen::Vector3d& xi) const;
  /// The centroid of the face's four vertices.
  SolidPoint face_centre(int f) const;

 private:
  void build_edges();
  void build_faces(const std::string& origin);
  void check_cells(const std::string& origin) const;

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

/// The box [lo, hi] (componentwise) cut into n[0] × n[1] × n[2] equal hexahedra, vertices
/// numbered x fastest. Boundary faces are labelled "x_min", "x_max", "y_min", "y_max", "z_min",
/// "z_max". @throws InputError if a count is < 1 or the box is empty.
SolidMesh make_box_mesh(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, const std::array<int, 3>& n);

}  // namespace hpcontact::mesh
