// Non-zero Dirichlet data u = u_D on Γ_D (for elasticity: u_c = u_D,c wherever component c is
// fixed, on Γ_D and on rollers) by a lifting. The problems keep their unknowns u_0 in the space
// with those dofs eliminated and solve for u = u_0 + w, where w lives in the same S^p(T_h)
// without elimination and equals on the fixed edges the projection-based interpolant of u_D:
// its values at the fixed vertices, plus on each fixed edge the H¹₀(e) projection of the rest
// onto the edge modes (exact for data of degree ≤ p_e along the edge; optimal in H^{1/2}). Only
// the fixed dofs of w are non-zero, so w touches the cells along the fixed edges alone:
//   A u_0 = F − (a(w, φ_i))_i,      constraints on B(u_0 + w) = B u_0 + B w,
// with a(w, ·) from the element matrices of those cells (no global matrix is assembled).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <functional>
#include <memory>
#include <vector>

#include "assembly/cell_system.hpp"
#include "assembly/local_rows.hpp"
#include "linalg/coupling_matrix.hpp"
#include "linalg/distribution.hpp"
#include "space/h1_space.hpp"
#include "space/vector_space.hpp"

namespace hpcontact::assembly {

using PointFunction = std::function<double(const mesh::Point&)>;

/// On a cell edge (local edge 0 … 3, parameter t as space::local_edge_of), the coefficients
/// a_2 … a_p of the H¹₀ projection of u − (its linear interpolant between the edge's ends) onto
/// the Lobatto bubbles N_2 … N_p: a_k = ∫ (u − I₁u)' N_k' dt (the N_k' are orthonormal).
Eigen::VectorXd edge_projection(const mesh::Mesh& mesh, int cell, int local_edge, int degree, const PointFunction& u);

class DirichletLift {
 public:
  /// u_D on the dofs that `space` eliminates. `extended`: the space on the same cells with nothing
  /// eliminated, needed when `space` lives on a rank's part of the mesh (which cannot number it
  /// alone: operators::PrimalOperators::lift_space); null: built here from `space`'s mesh.
  DirichletLift(const space::H1Space& space, const PointFunction& u_d, const space::H1Space* extended = nullptr);
  /// u_D,c (an empty function: 0) on the unknowns that `space` fixes for component c; `extended` as above.
  DirichletLift(const space::VectorSpace& space, const std::array<PointFunction, space::kComponents>& u_d,
                const space::H1Space* extended = nullptr);
  ~DirichletLift();
  DirichletLift(const DirichletLift&) = delete;
  DirichletLift& operator=(const DirichletLift&) = delete;

  /// S^p(T_h) on the same mesh and degrees with nothing eliminated, where w and u_0 + w live.
  const space::H1Space& extended_scalar() const { return *extended_scalar_; }
  /// [S^p(T_h)]² on extended_scalar() with nothing fixed (a vector lift's space; null for a scalar one).
  const space::VectorSpace* extended_vector() const { return extended_vector_.get(); }
  /// w, numbered on the extended space: a vector of the global length, for serial use (a rank
  /// of a distributed run reads value() and times()).
  Eigen::VectorXd values() const;
  /// w at one unknown of the extended space (0 away from the fixed edges).
  double value(int extended_unknown) const;
  /// `columns` · w for a matrix over the extended space's unknowns (B w), summed as the dense
  /// product sums, column after column.
  Eigen::VectorXd times(const linalg::Coupling& columns) const;
  /// u_0 + w on the extended space, for u_0 numbered on the space with elimination (serial: a
  /// vector of the global length).
  Eigen::VectorXd total(const Eigen::VectorXd& u0) const;
  /// The entries of a vector of the extended space at the unknowns of the space with elimination
  /// (a load assembled on the extended space, restricted to the problem's unknowns; serial).
  Eigen::VectorXd restrict(const Eigen::VectorXd& extended) const;

  struct LiftedLoad {
    Eigen::VectorXd load;        ///< F − (a(w, φ_i))_i at the problem's unknowns
    double energy_offset = 0.0;  ///< ½ a(w, w) − F(w): E(u_0 + w) = ½ a(u_0, u_0) − load · u_0 + this
  };
  /// The problem's load for u_0, from F assembled on the extended space (so that F(w) is known)
  /// and the form of `system`, which must be built on the space with elimination in the lift's
  /// layout (a scalar system for a scalar lift, an elastic or componentwise one for a vector lift).
  /// Distributed: `rows` is this rank's layout (its own cells' dofs), F its share assembled in
  /// extended_rows(rows), and the load comes back as its share at `rows`, the energy's constant
  /// summed over the distribution's ranks (collective) — no vector of the global length.
  LiftedLoad lifted_load(const CellSystem& system, const Eigen::VectorXd& extended_load, const LocalRows& rows = {},
                         const LocalRows& extended_rows = {}, linalg::Distribution distribution = {}) const;
  /// The extended space's layout matching the problem's `rows`: the same cells, their unknowns of
  /// the extended space (global when `rows` is).
  LocalRows extended_rows(const LocalRows& rows) const;

 private:
  /// One cell's non-zero lifting coefficients, in the order of its local unknowns.
  struct CellLift {
    int cell;
    Eigen::VectorXd local;
  };
  /// (cell, local shape, component) → an unknown.
  using UnknownOf = std::function<int(int, int, int)>;
  /// `unknown` gives the problem's unknown (-1 where fixed); extended_unknown the extended space's.
  void build(int components, const std::array<PointFunction, space::kComponents>& u_d, const UnknownOf& unknown,
             int n_unknowns, int n_extended);

  /// The extended space's unknown of local shape s, component comp of a held cell.
  int extended_unknown(int cell, int s, int comp) const;

  std::unique_ptr<space::H1Space> extended_scalar_;
  std::unique_ptr<space::VectorSpace> extended_vector_;
  /// Problem unknown → extended unknown; only where the spaces hold every cell (serial), since a
  /// rank of a distributed run reads the correspondence cell by cell and keeps no global-length table.
  std::vector<int> embedding_;
  /// w's non-zero unknowns of the extended space (ascending) and its values there: the fixed
  /// edges' dofs only.
  std::vector<int> fixed_unknowns_;
  std::vector<double> fixed_values_;
  int n_extended_ = 0, n_unknowns_ = 0;
  bool every_cell_ = true;  ///< whether the spaces hold every cell (serial)
  std::vector<CellLift> cells_;
};

/// A discrete function as the outputs evaluate it: coefficients on a space.
struct ScalarField {
  const space::H1Space& space;
  Eigen::VectorXd coefficients;
};
struct VectorField {
  const space::VectorSpace& space;
  Eigen::VectorXd coefficients;
};
/// u_0 + w on the extended space with a lift, else u_0 on `space`.
ScalarField total_field(const DirichletLift* lift, const space::H1Space& space, const Eigen::VectorXd& u0);
VectorField total_field(const DirichletLift* lift, const space::VectorSpace& space, const Eigen::VectorXd& u0);

}  // namespace hpcontact::assembly
