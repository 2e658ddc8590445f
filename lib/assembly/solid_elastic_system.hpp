// Linear elasticity on [S^p(T_h)]³ of a hexahedral mesh as a cell system: a(u, v) = (λ div u, div v)
// + (2μ ε(u), ε(v)), Lamé parameters per cell, so that static condensation and the trace-last
// factorization serve it as they serve the planar operators; or the vector H¹ inner product
// Σ_c (∇u_c, ∇v_c) + (u_c, v_c), the Gram matrix of α's primal norm on the same space.
#pragma once

#include <vector>

#include "assembly/cell_system.hpp"
#include "assembly/material.hpp"
#include "space/solid_vector_space.hpp"

namespace hpcontact::assembly {

/// Local unknowns: component c of the cell's scalar shape s at position 3s + c. Element matrix,
/// with D_ab(s, t) = (∂_a φ_s, ∂_b φ_t):
///   a[(s, i), (t, j)] = λ D_ij(s, t) + μ D_ji(s, t) + δ_ij μ Σ_k D_kk(s, t).
class SolidElasticCellSystem final : public CellSystem {
 public:
  /// `materials`: one per cell (λ, μ of 3-D elasticity: lame_parameters' plane-strain values).
  /// @throws InputError on a size mismatch.
  SolidElasticCellSystem(const space::SolidVectorSpace& space, std::vector<Material> materials);
  /// The vector H¹ inner product instead (no material).
  static SolidElasticCellSystem vector_h1(const space::SolidVectorSpace& space);
  int n_cells() const override { return space_->scalar().mesh().n_cells(); }
  /// Coordinate bisection of the hexahedra by work (mesh::bisect_solid_cells), the same on every rank.
  std::vector<int> split_cells_over_ranks(MPI_Comm ranks) const override;
  std::vector<char> boundary_unknowns(int cell) const override;
  int n_dofs() const override { return space_->n_dofs(); }
  int n_skeleton_dofs() const override { return space_->n_skeleton_dofs(); }
  void cell_dofs(int cell, std::vector<CellDof>& out) const override;
  int cell_size(int cell) const override { return 3 * space_->scalar().shape_count(cell); }
  Eigen::MatrixXd element_matrix(int cell) const override;
  std::optional<CongruenceKey> congruence_key(int cell) const override;
  /// Nested dissection: in 3-D it factorizes with a fraction of minimum degree's fill.
  linalg::FillOrdering fill_ordering() const override { return linalg::FillOrdering::nested_dissection; }
  int field_count() const override { return 3; }
  /// The six rigid motions (three translations, three rotations about the centroid of the mesh's
  /// vertices, the same on every rank) at the cell's vertex shapes, zero elsewhere: exact on cells
  /// with straight edges (the vertex shapes reproduce linear functions), near on curved ones.
  /// GAMG's and BDDC's near null space.
  Eigen::MatrixXd null_motions(int cell) const override;
  int null_motion_count() const override { return 6; }

 private:
  const space::SolidVectorSpace* space_;
  std::vector<Material> materials_;  ///< empty for the vector H¹ inner product
  mesh::SolidPoint centre_;          ///< the rotations' (about a far-away point one is nearly a translation)
};

}  // namespace hpcontact::assembly
