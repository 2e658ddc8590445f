// The H¹-conforming space S^p(T_h) (the paper's §5) of tensor-product polynomials of degree p_T
// per cell, hierarchical Lobatto basis, Dirichlet dofs on Γ_D eliminated.
#pragma once

#include <vector>

#include "mesh/quad_mesh.hpp"

namespace hpcontact::space {

/// One local shape function of a cell: sign · N_i(ξ) N_j(η), with N_k the Lobatto functions.
/// `dof` is the global free dof, or -1 if the function is eliminated by the Dirichlet condition.
struct LocalShape {
  int i = 0;
  int j = 0;
  int dof = -1;
  double sign = 1.0;
};

/// Whether the dofs of Γ_D are dropped (the space of the problems, functions vanishing on Γ_D) or
/// kept (the same space without the condition: where a lifting of non-zero Dirichlet data lives).
enum class DirichletDofs { eliminated, kept };

/// Degree distribution and conformity rule ("minimum rule"): cell T carries the full
/// interior tensor space of degree p_T; an edge carries the modes of degree
/// p_e = min(p_T over the cells sharing it). So neighbouring cells of different degree share
/// exactly the traces of degree p_e on their common edge, and the space stays conforming; every
/// cell space lies between Q_{min p} and Q_{p_T}.
///
/// Global dof order: vertex dofs, then edge modes (edge by edge, degree 2..p_e), then interior
/// modes; Dirichlet dofs (vertices on closed Γ_D edges, modes of Γ_D edges) are dropped, so the
/// discrete functions vanish on Γ_D (the paper's H¹(Ω, Γ_D)).
/// The local edge (0: η = −1, 1: ξ = 1, 2: η = 1, 3: ξ = −1) whose mode a shape is, with the
/// shape's restriction to it being sign · N_k(t) (t = ξ on edges 0, 2, η on 1, 3; k its index
/// along the edge); -1 for vertex and interior shapes.
int local_edge_of(const LocalShape& shape);

class H1Space {
 public:
  /// @throws InputError if the distribution has the wrong size or a degree < 1.
  H1Space(const mesh::QuadMesh& mesh, std::vector<int> cell_degrees,
          DirichletDofs dirichlet = DirichletDofs::eliminated);
  /// Uniform degree p.
  H1Space(const mesh::QuadMesh& mesh, int degree);

  const mesh::QuadMesh& mesh() const { return *mesh_; }
  int n_dofs() const { return n_dofs_; }
  /// Vertex and edge dofs, numbered 0 … n_skeleton_dofs() − 1 before every interior mode: the
  /// unknowns left when each cell's interior modes (its own, coupled to no other cell) are
  /// condensed out.
  int n_skeleton_dofs() const { return n_skeleton_dofs_; }
  int cell_degree(int cell) const { return cell_degrees_[cell]; }
  const std::vector<int>& cell_degrees() const { return cell_degrees_; }
  int edge_degree(int edge) const { return edge_degrees_[edge]; }
  int max_degree() const { return max_degree_; }
  /// Local shape functions of a cell, with their global dofs: the 4 vertices, then the modes of
  /// local edges 0 … 3 (see local_edge_of), then the interior modes.
  const std::vector<LocalShape>& cell_shapes(int cell) const { return cell_shapes_[cell]; }

 private:
  void build(DirichletDofs dirichlet);

  const mesh::QuadMesh* mesh_;
  std::vector<int> cell_degrees_;
  std::vector<int> edge_degrees_;
  std::vector<std::vector<LocalShape>> cell_shapes_;
  int n_dofs_ = 0;
  int n_skeleton_dofs_ = 0;
  int max_degree_ = 1;
};

}  // namespace hpcontact::space
