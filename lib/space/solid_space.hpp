// The H¹-conforming space S^p(T_h) on solid meshes: per hexahedron the tensor polynomials Q_{p_T}
// in the hierarchical Lobatto basis, per tetrahedron P_{p_T} in the hierarchical basis of
// basis/tetrahedron_basis.hpp (vertex, edge, face and interior modes), edge and face modes
// oriented by global vertex numbers so that neighbouring cells share their traces; degrees per
// cell with the minimum rule on edges and faces; Dirichlet dofs on Γ_D eliminated.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "mesh/solid_mesh.hpp"

namespace hpcontact::space {

/// What a local shape of a cell is attached to.
enum class SolidShapeRole : unsigned char { vertex, edge, face, interior };

/// One local shape function of a cell, times `sign`. On a hexahedron N_i(ξ) N_j(η) N_k(ζ) with N
/// the Lobatto functions (basis/lobatto.hpp), index = (i, j, k): indices 0 and 1 are the linear
/// functions (1 ∓ t)/2, ≥ 2 the bubbles, so the number of indices ≥ 2 is the role: 0 vertex, 1
/// edge, 2 face, 3 interior. On a tetrahedron the mode of basis::TetrahedronShapes given by the
/// role, `entity` and index: (k, 0, 0) on an edge, (n1, n2, 0) on a face, (n1, n2, n3) inside;
/// sign +1. `dof` is the global free dof, or −1 where Γ_D eliminates it.
struct SolidShape {
  std::array<std::int16_t, 3> index{};
  int dof = -1;
  float sign = 1.0F;  ///< ±1, exact in float
  SolidShapeRole role = SolidShapeRole::vertex;
  std::int8_t entity = -1;  ///< local vertex, edge or face (mesh/solid_mesh.hpp); −1 for interior modes
};

/// Degrees: cell T carries Q_{p_T} on its interior; an edge or face carries the modes up to the
/// smallest degree of the cells sharing it (the minimum rule), so the space is conforming.
/// Orientation: mode k of an edge is N_k along the edge from its lower global vertex; mode (a, b)
/// of a face is N_a(S) N_b(T) in the face's own axes (mesh::SolidMesh::face). A cell's local shape
/// restricted to the edge or face is sign · that mode.
///
/// Global dof order: vertices, edge modes (edge by edge, k = 2 … p_e), face modes (face by face;
/// squares (a, b) ∈ [2, p_f]², a slowest; triangles (n1, n2), n1 + n2 ≤ p_f − 3, n1 slowest),
/// interior modes (cell by cell); the skeleton (vertices, edges,
/// faces) first, so static condensation removes the interiors (assembly/condensed_factor.hpp).
/// Dirichlet: the vertices, edges and faces of the boundary faces flagged in `dirichlet_faces`
/// carry no dof.
class SolidH1Space {
 public:
  /// `cell_degrees`: one per cell, each ≥ 1. `dirichlet_faces`: one flag per face of the mesh
  /// (empty: no Γ_D); only boundary faces may be flagged.
  /// @throws InputError on a size mismatch, a degree < 1 or a flagged interior face.
  SolidH1Space(const mesh::SolidMesh& mesh, std::vector<int> cell_degrees, const std::vector<char>& dirichlet_faces);

  const mesh::SolidMesh& mesh() const { return *mesh_; }
  int n_dofs() const { return n_dofs_; }
  int n_skeleton_dofs() const { return n_skeleton_dofs_; }
  int cell_degree(int cell) const { return cell_degrees_[cell]; }
  int edge_degree(int edge) const { return edge_degrees_[edge]; }
  int face_degree(int face) const { return face_degrees_[face]; }
  int max_degree() const { return max_degree_; }
  /// The local shapes of a cell: its vertices, the modes of its edges, of its faces, then its
  /// interior modes, each group in local order; the same list for cells of equal degrees.
  std::span<const SolidShape> cell_shapes(int cell) const {
    return {shapes_.data() + first_shape_[cell], shapes_.data() + first_shape_[cell + 1]};
  }
  int shape_count(int cell) const { return static_cast<int>(first_shape_[cell + 1] - first_shape_[cell]); }
  /// The dof of vertex v (−1 on Γ_D).
  int vertex_dof(int v) const { return vertex_dofs_[v]; }

 private:
  void number_dofs(const std::vector<char>& dirichlet_faces);
  void append_shapes(int cell, int first_interior);
  void append_tetrahedron_shapes(int cell, int first_interior);

  const mesh::SolidMesh* mesh_;
  std::vector<int> cell_degrees_, edge_degrees_, face_degrees_;
  std::vector<int> vertex_dofs_, edge_first_dofs_, face_first_dofs_;
  std::vector<SolidShape> shapes_;
  std::vector<std::int64_t> first_shape_;
  int n_dofs_ = 0;
  int n_skeleton_dofs_ = 0;
  int max_degree_ = 1;
};

/// A function's coefficients on `cell`'s local shapes: sign · coefficients(dof), 0 where the dof is
/// held (Γ_D), shape (space.shape_count(cell)).
Eigen::VectorXd local_coefficients(const SolidH1Space& space, int cell, const Eigen::VectorXd& coefficients);

/// Whether a cell's shape can be nonzero on its local face `local_face`: the face's vertex and edge
/// modes and its own face modes (what a trace on that face holds).
bool shape_on_face(const mesh::SolidMesh& mesh, const SolidShape& shape, int local_face);

/// Flags the boundary faces whose label is one of `labels` (for SolidH1Space's Γ_D).
std::vector<char> faces_labelled(const mesh::SolidMesh& mesh, const std::vector<std::string>& labels);

}  // namespace hpcontact::space
