// ParaView output of fields on S^p(T_h): VTK XML UnstructuredGrid of VTK Lagrange cells of one
// order k (quadrilaterals and triangles), points shared between cells, arrays appended as raw
// binary. Every field of degree ≤ k per cell is represented exactly, so ParaView draws u_h with
// its own nonlinear subdivision; fields with jumps between cells (∇u) are averaged at shared points.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "assembly/cell_field.hpp"
#include "assembly/cell_values.hpp"
#include "assembly/elastic_system.hpp"
#include "assembly/local_rows.hpp"
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

/// What a VTU file holds, as arrays (the Python module hands them over as numpy arrays): points,
/// VTK Lagrange cells, the cell degrees, the point fields, and the cells cut into linear
/// triangles through their nodes (for plotting without VTK).
struct VtuGrid {
  struct PointArray {
    std::string name;
    int components = 1;
    std::vector<double> values;  ///< point after point, `components` each
  };
  std::vector<double> xyz;  ///< 3 per point
  std::vector<std::int64_t> connectivity, offsets;
  std::vector<std::uint8_t> types;    ///< VTK cell types (69 triangle, 70 quadrilateral)
  std::vector<std::int32_t> degrees;  ///< p_T per cell
  std::vector<PointArray> point_data;
  std::vector<std::array<std::int64_t, 3>> triangles;  ///< the lattice of each cell, triangulated
  std::size_t n_points() const { return xyz.size() / 3; }
};

/// `fields` as point data and the cell degree p_T, on the cells `cells` holds (a distributed run's
/// piece: the rank's own cells; fields with jumps are then averaged over the piece's cells at a
/// point). @param order k of the Lagrange cells; 0 means the largest p_T of the mesh (the same in
/// every piece).
VtuGrid vtu_grid(const space::H1Space& space, const std::vector<VtuField>& fields, int order = 0,
                 const assembly::LocalRows& cells = {});
/// The VTU file's text: the point data, the degrees as cell data "p".
std::string vtu_text(const VtuGrid& grid);

/// u_h ∈ S^p(T_h) as the point fields "u" and "grad_u", on the cells u is known on.
VtuGrid solution_vtu_grid(const assembly::CellField& u);
/// A displacement of [S^p(T_h)]² as the vector field "displacement", the stress tensor "stress"
/// (xx, yy, zz, xy, yz, xz, ParaView's symmetric tensor; σ_zz of the plane model) and the von
/// Mises stress "von_mises" (both averaged over the cells meeting at a point), on the cells u is
/// known on.
VtuGrid elastic_vtu_grid(const assembly::CellField& u, const std::vector<assembly::Material>& materials);

/// The point fields of the two texts above, as (name, components).
std::vector<std::pair<std::string, int>> solution_vtu_fields();
std::vector<std::pair<std::string, int>> elastic_vtu_fields();
/// A parallel VTU (PUnstructuredGrid) naming the pieces (paths relative to it) with these point
/// fields and the cell data "p".
std::string pvtu_text(const std::vector<std::string>& pieces, const std::vector<std::pair<std::string, int>>& fields);

}  // namespace hpcontact::io
