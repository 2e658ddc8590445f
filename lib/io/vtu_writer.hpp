// ParaView output of fields on S^p(T_h): every cell subdivided into k × k bilinear quadrilaterals
// (k = p_T by default), fields as point data, written as VTK XML UnstructuredGrid (ASCII).
#pragma once

#include <Eigen/Core>
#include <filesystem>
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

/// @param subdivisions per cell and direction; 0 means p_T (so fields are sampled at p_T + 1 points).
void write_vtu_fields(const std::filesystem::path& path, const space::H1Space& space,
                      const std::vector<VtuField>& fields, int subdivisions = 0);

/// u_h ∈ S^p(T_h) as the field "u".
void write_vtu(const std::filesystem::path& path, const space::H1Space& space, const Eigen::VectorXd& u,
               int subdivisions = 0);

/// A displacement of [S^p(T_h)]² as the vector field "displacement" and the von
/// Mises stress "von_mises" (with σ_zz of the plane model).
void write_elastic_vtu(const std::filesystem::path& path, const space::VectorSpace& space,
                       const std::vector<assembly::Material>& materials, const Eigen::VectorXd& u);

}  // namespace hpcontact::io
