// ParaView output of fields on S^p(T_h): VTK XML UnstructuredGrid of VTK Lagrange cells of one
// order k (quadrilaterals and triangles), points shared between cells, arrays appended as raw
// binary. Every field of degree ≤ k per cell is represented exactly, so ParaView draws u_h with
// its own nonlinear subdivision; fields with jumps between cells (∇u) are averaged at shared points.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "assembly/cell_values.hpp"
#include "assembly/elastic_system.hpp"
#include "space/h1_space.hpp"
#include "space/vector_space.hpp"

namespace hpcontact::io {

/// A point field: its values at the tabulated points of one cell, shape (n_points, components);
/// 3 components make a vector in ParaView.
struct VtuField {
  std::string name;
  int components = 1;
  std::function<Eigen::MatrixXd(int cell, const assembly::CellValues& values)> evaluate;
};

/// The VTU file's text: `fields` as point data, the cell degree p_T as cell data "p".
/// @param order k of the Lagrange cells; 0 means the largest p_T.
std::string vtu_text(const space::H1Space& space, const std::vector<VtuField>& fields, int order = 0);

/// u_h ∈ S^p(T_h) as the point fields "u" and "grad_u".
std::string solution_vtu_text(const space::H1Space& space, const Eigen::VectorXd& u);

/// A displacement of [S^p(T_h)]² as the vector field "displacement" and the von Mises stress
/// "von_mises" (with σ_zz of the plane model; averaged over the cells meeting at a point).
std::string elastic_vtu_text(const space::VectorSpace& space, const std::vector<assembly::Material>& materials,
                             const Eigen::VectorXd& u);

}  // namespace hpcontact::io
