// Linear elasticity on [S^p(T_h)]² (plane strain or plane stress, isotropic, Lamé parameters per
// cell): the bilinear form a(u, v) = (λ div u, div v) + (2μ ε(u), ε(v)) as a cell system, so that
// static condensation and the trace-last factorization are those of the scalar problem.
#pragma once

#include <vector>

#include "assembly/cell_system.hpp"
#include "assembly/material.hpp"
#include "space/h1_space.hpp"
#include "space/vector_space.hpp"

namespace hpcontact::assembly {

/// Local unknowns of a cell: component c of scalar shape s at position 2s + c; global dofs by
/// space::VectorSpace::dof (-1 where Γ_D or a roller fixes the component). Element matrix (signed shapes), with D_ab =
/// (∂_a φ_s, ∂_b φ_t):
///   a[(s,x),(t,x)] = (λ + 2μ) D_xx + μ D_yy      a[(s,x),(t,y)] = λ D_xy + μ D_yx
///   a[(s,y),(t,x)] = λ D_yx + μ D_xy             a[(s,y),(t,y)] = (λ + 2μ) D_yy + μ D_xx
///
/// With `mass_weight` b > 0 the system is a(u, v) + b (u, v) (the energy norm of the inf-sup
/// analysis, definite without Γ_D).
class ElasticCellSystem final : public PlanarCellSystem {
 public:
  /// `materials`: one per cell. `centre`: the rotation's centre for null_motions, which every rank
  /// sharing a problem must use alike (default: the centroid of the mesh's vertices).
  /// @throws InputError on a size mismatch.
  ElasticCellSystem(const space::VectorSpace& space, std::vector<Material> materials, double mass_weight = 0.0,
                    std::optional<mesh::Point> centre = {});
  const mesh::Mesh& mesh() const override { return space_->scalar().mesh(); }
  const space::H1Space& scalar_space() const override { return space_->scalar(); }
  int n_dofs() const override;
  int n_skeleton_dofs() const override;
  void cell_dofs(int cell, std::vector<CellDof>& out) const override;
  int cell_size(int cell) const override { return space::kComponents * space_->scalar().shape_count(cell); }
  Eigen::MatrixXd element_matrix(int cell) const override;
  std::optional<CongruenceKey> congruence_key(int cell) const override;
  /// The rigid motions (1, 0), (0, 1), (−y, x) (about the centre) at the cell's vertex
  /// shapes, zero elsewhere: exact
  /// on affine cells (the vertex shapes reproduce linear functions), near elsewhere.
  Eigen::MatrixXd null_motions(int cell) const override;
  int null_motion_count() const override { return 3; }
  /// The components x, y (cell_dofs interleaves them).
  int field_count() const override { return space::kComponents; }

 private:
  const space::VectorSpace* space_;
  std::vector<Material> materials_;
  double mass_weight_;
  mesh::Point centre_ = mesh::Point(0.0, 0.0);  ///< the rotation's centre
  mutable ElementMatrices element_;
};

/// a K + b M on each component of [S^p(T_h)]² (the vector H¹ norm for a = b = 1), numbered as
/// ElasticCellSystem.
class ComponentwiseCellSystem final : public PlanarCellSystem {
 public:
  ComponentwiseCellSystem(const space::VectorSpace& space, double stiffness_weight, double mass_weight);
  const mesh::Mesh& mesh() const override { return scalar_.mesh(); }
  const space::H1Space& scalar_space() const override { return space_->scalar(); }
  /// The components x, y (cell_dofs interleaves them).
  int field_count() const override { return space::kComponents; }
  int n_dofs() const override;
  int n_skeleton_dofs() const override;
  void cell_dofs(int cell, std::vector<CellDof>& out) const override;
  int cell_size(int cell) const override { return space::kComponents * space_->scalar().shape_count(cell); }
  Eigen::MatrixXd element_matrix(int cell) const override;
  std::optional<CongruenceKey> congruence_key(int cell) const override { return scalar_.congruence_key(cell); }

 private:
  const space::VectorSpace* space_;
  ScalarCellSystem scalar_;
};

}  // namespace hpcontact::assembly
