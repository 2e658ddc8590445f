// CellField: a discrete field as the outputs read it, cell by cell — each held cell's
// coefficients at its local shapes. A distributed run's solution lives at each rank's own cells'
// dofs (LocalRows); the outputs (boundary samples, ParaView pieces) evaluate it on those
// cells only, so that no rank gathers the whole vector.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <memory>

#include "assembly/dirichlet_lift.hpp"
#include "assembly/local_rows.hpp"
#include "space/h1_space.hpp"
#include "space/vector_space.hpp"

namespace hpcontact::assembly {

struct CellField {
  const space::H1Space* space = nullptr;  ///< the cells' shapes and degrees (the problem's space)
  int components = 1;
  LocalRows rows;  ///< the cells it is known on: rows.holds(cell)
  /// A held cell's coefficients, shape (n_shapes, components) in the order of space->cell_shapes.
  std::function<Eigen::MatrixXd(int cell)> coefficients;
};

/// u = u_0 + w of a scalar problem: u_0 given at `rows` on `space` (the unknowns with Dirichlet
/// dofs eliminated), w the lift (null without Dirichlet data).
CellField scalar_field(const space::H1Space& space, Eigen::VectorXd u0, const LocalRows& rows,
                       std::shared_ptr<const DirichletLift> lift);
/// The same for a displacement of [S^p(T_h)]² (two components).
CellField vector_field(const space::VectorSpace& space, Eigen::VectorXd u0, const LocalRows& rows,
                       std::shared_ptr<const DirichletLift> lift);

}  // namespace hpcontact::assembly
