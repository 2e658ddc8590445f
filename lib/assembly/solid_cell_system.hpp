// a K + b M on the hexahedral space S^p(T_h) as a cell system, so that static condensation and
// the trace-last factorization (assembly/condensed_factor.hpp) serve solid meshes unchanged.
#pragma once

#include "assembly/cell_system.hpp"
#include "space/solid_space.hpp"

namespace hpcontact::assembly {

/// a K + b M (a, b ≥ 0, not both 0) on S^p(T_h) of a hexahedral mesh. Parallelepipeds of equal
/// shape and degrees share their element matrix and elimination (a box mesh eliminates once).
class SolidScalarCellSystem final : public CellSystem {
 public:
  SolidScalarCellSystem(const space::SolidH1Space& space, double stiffness_weight, double mass_weight);
  const space::SolidH1Space& space() const { return *space_; }
  int n_cells() const override { return space_->mesh().n_cells(); }
  /// Coordinate bisection of the hexahedra by work (mesh::bisect_solid_cells), the same on every rank.
  std::vector<int> split_cells_over_ranks(MPI_Comm ranks) const override;
  std::vector<char> boundary_unknowns(int cell) const override;
  int n_dofs() const override { return space_->n_dofs(); }
  int n_skeleton_dofs() const override { return space_->n_skeleton_dofs(); }
  void cell_dofs(int cell, std::vector<CellDof>& out) const override;
  int cell_size(int cell) const override { return space_->shape_count(cell); }
  Eigen::MatrixXd element_matrix(int cell) const override;
  std::optional<CongruenceKey> congruence_key(int cell) const override;
  /// Nested dissection: in 3-D it factorizes with a fraction of minimum degree's fill.
  linalg::FillOrdering fill_ordering() const override { return linalg::FillOrdering::nested_dissection; }

 private:
  const space::SolidH1Space* space_;
  double stiffness_weight_, mass_weight_;
};

}  // namespace hpcontact::assembly
