// What static condensation needs to know of a symmetric positive definite system assembled cell
// by cell: each cell's unknowns (global dof, sign, interior or skeleton), its element matrix, and
// which cells are congruent (equal element matrices up to signs). One interface for the scalar
// operators a K + b M on S^p(T_h) and the elasticity operator on [S^p(T_h)]², so that both share
// one condensation and one factorization (CondensedFactor).
#pragma once

#include <mpi.h>

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "assembly/element_matrices.hpp"
#include "linalg/sparse_cholesky.hpp"
#include "mesh/mesh.hpp"
#include "space/h1_space.hpp"

namespace hpcontact::assembly {

/// One local unknown of a cell. `dof` is -1 where a Dirichlet condition eliminates it.
struct CellDof {
  int dof = -1;
  double sign = 1.0;
  bool interior = false;  ///< coupled to no other cell (eliminated by the condensation)
};

/// Cells with equal keys have equal unsigned element matrices (see CellSystem::congruence_key).
using CongruenceKey = std::vector<long long>;

class CellSystem {
 public:
  virtual ~CellSystem() = default;
  /// The cells of the mesh (planar or solid) the system is assembled on.
  virtual int n_cells() const = 0;
  /// For a distributed factorization: the rank of `ranks` that eliminates each cell, parts of
  /// about equal work (cell_work_weights) with few shared unknowns. Collective.
  /// @throws InputError where the system cannot be split (a part's system, or a mesh kind that
  /// runs serially).
  virtual std::vector<int> split_cells_over_ranks(MPI_Comm ranks) const = 0;
  /// Which of the cell's unknowns (in the order of cell_dofs) lie on the boundary of the mesh:
  /// what a solver building coarse spaces (BDDC) learns of a subdomain beyond its matrix.
  virtual std::vector<char> boundary_unknowns(int cell) const = 0;
  virtual int n_dofs() const = 0;
  /// Skeleton dofs are numbered 0 … n_skeleton_dofs() − 1, before every interior dof.
  virtual int n_skeleton_dofs() const = 0;
  /// The cell's unknowns in the order of its element matrix.
  virtual void cell_dofs(int cell, std::vector<CellDof>& out) const = 0;
  /// The number of cell_dofs(cell), known for every cell (also one whose shapes this rank does
  /// not hold).
  virtual int cell_size(int cell) const = 0;
  /// The element matrix in the basis of the signed local shapes, shape (n, n) with n the size of
  /// cell_dofs(cell).
  virtual Eigen::MatrixXd element_matrix(int cell) const = 0;
  /// A key shared exactly by the cells whose unsigned element matrices are equal (affine cells of
  /// one type with equal Jacobian, degrees and coefficients); empty where the cell has no
  /// congruent partner to look for.
  virtual std::optional<CongruenceKey> congruence_key(int cell) const = 0;
  /// The motions without energy of the operator's continuous form (elasticity's rigid motions),
  /// interpolated on the cell: shape (n, k), rows as cell_dofs(cell), coefficients of the cell's
  /// (unsigned) local shapes. A near null space for solvers that build coarse spaces (BDDC); k = 0 (the
  /// default) where the form has none to tell.
  virtual Eigen::MatrixXd null_motions(int /*cell*/) const { return Eigen::MatrixXd(0, 0); }
  /// The number of columns of null_motions (the same for every cell).
  virtual int null_motion_count() const { return 0; }
  /// The skeleton factor's fill-reducing ordering: minimum degree for planar meshes (measured
  /// faster there), nested dissection for solid ones (far less fill in 3-D).
  virtual linalg::FillOrdering fill_ordering() const { return linalg::FillOrdering::minimum_degree; }
  /// The fields of the unknowns (elasticity: the two displacement components), which a solver
  /// that builds coarse constraints per field (BDDC's edge averages) must tell apart: the
  /// cell's unknown s (in the order of cell_dofs) is of field s % field_count().
  virtual int field_count() const { return 1; }
};

/// Each cell's unknowns (Dirichlet ones included): the weight by which the cells are split over
/// ranks, so that parts of a mesh of mixed degrees eliminate and factorize about equal work.
std::vector<int> cell_work_weights(const CellSystem& system);

/// A cell system on a planar mesh whose unknowns are carried by the shapes of one scalar space
/// S^p(T_h) (the scalar operators and elasticity in 2-D).
class PlanarCellSystem : public CellSystem {
 public:
  virtual const mesh::Mesh& mesh() const = 0;
  /// The scalar space whose shapes carry the unknowns: the cell's unknown s is of its shape
  /// s / field_count().
  virtual const space::H1Space& scalar_space() const = 0;
  int n_cells() const final { return mesh().n_cells(); }
  /// mesh::split_cells_over_ranks (coordinate bisection or PT-Scotch) weighted by cell_work_weights.
  std::vector<int> split_cells_over_ranks(MPI_Comm ranks) const final;
  /// Per unknown: its shape lies on the mesh's boundary (boundary_shapes).
  std::vector<char> boundary_unknowns(int cell) const final;
};

/// Which of the cell's shapes lie on the boundary of the space's mesh (vertex shapes of its
/// vertices and edge modes of its edges there; a part's cut edges are not its boundary).
std::vector<char> boundary_shapes(const space::H1Space& space, int cell);

/// The key of an affine cell (parallelogram or straight triangle): its degree, vertex count and
/// edge degrees and its Jacobian rounded to 1e-12 of the largest entry, with the cell's size (log
/// of the largest entry, to 1e-11) because the mass matrix scales with the area. Empty for other
/// cells (or with `enabled` false).
std::optional<CongruenceKey> affine_key(const space::H1Space& space, int cell, bool enabled);

/// A K + b M on S^p(T_h) (a, b ≥ 0, not both 0).
class ScalarCellSystem final : public PlanarCellSystem {
 public:
  ScalarCellSystem(const space::H1Space& space, double stiffness_weight, double mass_weight);
  const space::H1Space& space() const { return *space_; }
  const mesh::Mesh& mesh() const override { return space_->mesh(); }
  const space::H1Space& scalar_space() const override { return *space_; }
  int n_dofs() const override { return space_->n_dofs(); }
  int n_skeleton_dofs() const override { return space_->n_skeleton_dofs(); }
  void cell_dofs(int cell, std::vector<CellDof>& out) const override;
  int cell_size(int cell) const override { return space_->shape_count(cell); }
  Eigen::MatrixXd element_matrix(int cell) const override;
  std::optional<CongruenceKey> congruence_key(int cell) const override;

 private:
  const space::H1Space* space_;
  double stiffness_weight_, mass_weight_;
  mutable ElementMatrices element_;  ///< keeps the 1D matrices per degree
};

}  // namespace hpcontact::assembly
