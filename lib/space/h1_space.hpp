// The H¹-conforming space S^p(T_h) (the paper's §5): per cell the tensor-product polynomials Q_{p_T}
// on quadrilaterals and the polynomials P_{p_T} on triangles, hierarchical bases (Lobatto on the
// square, basis/triangle_basis.hpp on the triangle) that share their edge traces; Dirichlet dofs
// on Γ_D eliminated. A rank of a distributed run keeps the shapes of the cells it needs only.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "mesh/mesh.hpp"

namespace hpcontact::space {

/// What a local shape is attached to.
enum class ShapeRole : unsigned char { vertex, edge, interior };

/// One local shape function of a cell, times `sign` (edge orientation).
/// Quadrilateral: N_i(ξ) N_j(η), with N_k the Lobatto functions.
/// Triangle (basis/triangle_basis.hpp): vertex `entity`; mode k = i of edge `entity` (j = 0);
/// bubble (n1, n2) = (i, j).
/// `dof` is the global free dof, or -1 if the function is eliminated by the Dirichlet condition.
/// 16 bytes: a space holds one per shape of every cell it holds (a rank of a distributed run: its
/// own cells and Γ_C's), the largest table of a run after the factorizations (25 per cell at p = 4).
struct LocalShape {
  std::int16_t i = 0;
  std::int16_t j = 0;
  int dof = -1;
  float sign = 1.0F;  ///< ±1, exact in float
  ShapeRole role = ShapeRole::vertex;
  std::int8_t entity = -1;  ///< local vertex (vertex shapes) or local edge (edge modes); -1 for interior
};

static_assert(sizeof(LocalShape) == 16, "LocalShape is stored once per shape of every held cell");

/// Whether the dofs of Γ_D are dropped (the space of the problems, functions vanishing on Γ_D) or
/// kept (the same space without the condition: where a lifting of non-zero Dirichlet data lives).
enum class DirichletDofs { eliminated, kept };

/// Degree distribution and conformity rule ("minimum rule"): cell T carries the full
/// interior space of degree p_T; an edge carries the modes of degree
/// p_e = min(p_T over the cells sharing it). So neighbouring cells of different degree or type
/// share exactly the traces of degree p_e on their common edge, and the space stays conforming;
/// every quadrilateral's space lies between Q_{min p} and Q_{p_T}, every triangle's between
/// P_{min p} and P_{p_T}.
///
/// Global dof order: vertex dofs, then edge modes (edge by edge, degree 2..p_e), then interior
/// modes; Dirichlet dofs (vertices on closed Γ_D edges, modes of Γ_D edges) are dropped, so the
/// discrete functions vanish on Γ_D (the paper's H¹(Ω, Γ_D)).
/// The local edge (mesh/reference_cell.hpp) whose mode a shape is, with the shape's restriction to
/// it being sign · N_k(t), k = edge_mode_degree(shape), t the edge parameter; -1 for vertex and
/// interior shapes.
int local_edge_of(const LocalShape& shape);
/// The degree k of an edge mode along its edge.
int edge_mode_degree(const LocalShape& shape);

class H1Space {
 public:
  /// `held` (empty: every cell; else one flag per cell): only the flagged cells keep their local
  /// shapes, so that a rank of a distributed run stores the table for its own cells (and those its
  /// trace operators need), not for the whole mesh. The numbering is the whole space's either way.
  /// @throws InputError if the distribution has the wrong size or a degree < 1.
  H1Space(const mesh::Mesh& mesh, std::vector<int> cell_degrees, DirichletDofs dirichlet = DirichletDofs::eliminated,
          const std::vector<char>& held = {});
  /// Uniform degree p.
  H1Space(const mesh::Mesh& mesh, int degree);

  /// This space on `part`, a mesh extracted from mesh() (mesh::Mesh::extract): on each of the
  /// part's cells the same degree and local shapes, with the same global dofs, as on its cell of
  /// mesh(), and every table of the part's length; n_dofs(), n_skeleton_dofs() and max_degree() stay
  /// this space's. So a rank can keep the space of its own cells only. Without `with_shapes`, the
  /// numbering alone (no cell held) until with_shapes().
  H1Space restricted_to(const mesh::Mesh& part, bool with_shapes = true) const;
  /// This space with every cell's shapes: a part's numbering (restricted_to without them, or
  /// unpack) once it has reached its rank, or a numbering-only whole space.
  H1Space with_shapes() const;
  /// The numbering of a space restricted to a part (restricted_to without shapes) as bytes, and
  /// back on that part (sent beside it: mesh::Mesh::pack), so that one rank can number the whole
  /// space and send each rank its part's share (space/space_bytes.cpp).
  void pack(ByteWriter& out) const;
  static H1Space unpack(ByteReader& in, const mesh::Mesh& part);

  const mesh::Mesh& mesh() const { return *mesh_; }
  int n_dofs() const { return n_dofs_; }
  /// Vertex and edge dofs, numbered 0 … n_skeleton_dofs() − 1 before every interior mode: the
  /// unknowns left when each cell's interior modes (its own, coupled to no other cell) are
  /// condensed out.
  int n_skeleton_dofs() const { return n_skeleton_dofs_; }
  int cell_degree(int cell) const { return cell_degrees_[cell]; }
  const std::vector<int>& cell_degrees() const { return cell_degrees_; }
  int edge_degree(int edge) const { return edge_degrees_[edge]; }
  int max_degree() const { return max_degree_; }
  /// Local shape functions of a cell, with their global dofs: the vertices, then the modes of
  /// the local edges in order (see local_edge_of), then the interior modes. Only for a held cell.
  std::span<const LocalShape> cell_shapes(int cell) const {
    const std::int64_t first = first_shape_[cell], end = first_shape_[cell + 1];
    if (first == end) not_held(cell);  // every cell has at least three shapes
    return {shapes_.data() + first, shapes_.data() + end};
  }
  /// Whether the cell's shapes are kept (every cell unless the space was built with `held`).
  bool holds(int cell) const { return first_shape_[cell + 1] > first_shape_[cell]; }
  /// The `held` flags this space was built with: empty where it holds every cell.
  std::vector<char> held_cells() const;
  /// Whether some cell's shapes are kept (not a numbering-only space).
  bool holds_shapes() const { return first_shape_.back() > 0; }
  /// Whether the space holds every cell of the whole mesh (not some cells, not a part).
  bool whole() const { return !mesh_->is_part() && held_cells().empty(); }
  /// The number of local shapes of any cell (held or not): its unknowns, Dirichlet ones included.
  int shape_count(int cell) const;
  /// The dof of vertex v, or -1 where Γ_D eliminates it.
  int vertex_dof(int v) const { return vertex_dofs_[v]; }
  /// The dof of mode k (2 ≤ k ≤ edge_degree(e)) of edge e, or -1 where Γ_D eliminates it.
  int edge_mode_dof(int e, int k) const { return edge_first_dofs_[e] < 0 ? -1 : edge_first_dofs_[e] + k - 2; }

 private:
  H1Space() = default;  // for restricted_to
  void build(DirichletDofs dirichlet, const std::vector<char>& held);
  /// The interior modes of a cell of degree p: (p − 1)² on a quadrilateral, (p − 1)(p − 2)/2 on a triangle.
  int interior_count(int cell) const;
  /// Appends cell c's local shapes to shapes_, its interior modes numbered from first_interior.
  void append_shapes(int cell, int first_interior);
  [[noreturn]] static void not_held(int cell);

  const mesh::Mesh* mesh_ = nullptr;
  std::vector<int> cell_degrees_;
  std::vector<int> edge_degrees_;
  std::vector<int> vertex_dofs_, edge_first_dofs_;  ///< see vertex_dof, edge_mode_dof
  /// Each cell's first interior dof, kept so that restricted_to costs the part, not the mesh.
  std::vector<int> first_interior_;
  std::vector<LocalShape> shapes_;         ///< every held cell's shapes, cell after cell
  std::vector<std::int64_t> first_shape_;  ///< cell c's shapes: [first_shape_[c], first_shape_[c + 1])
  int n_dofs_ = 0;
  int n_skeleton_dofs_ = 0;
  int max_degree_ = 1;
};

}  // namespace hpcontact::space
