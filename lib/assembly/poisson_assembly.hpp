// Global sparse stiffness K, mass M, volume load F and boundary (Neumann) load on S^p(T_h).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <set>

#include "mesh/mesh.hpp"
#include "space/h1_space.hpp"

namespace hpcontact::assembly {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// Which volume matrices to build in one pass over the cells.
struct VolumeMatrixRequest {
  bool stiffness = true;  ///< K_jk = (∇φ_j, ∇φ_k)
  bool mass = false;      ///< M_jk = (φ_j, φ_k)
  /// Parallelogram cells by Kronecker products of 1D matrices (exact, O(p⁴) per cell); false:
  /// every cell by quadrature (O(p⁶)), the independent path the tests compare against.
  bool kronecker_parallelograms = true;
};

struct VolumeMatrices {
  SparseMatrix stiffness;  ///< empty (0×0) unless requested; shape (n_dofs, n_dofs)
  SparseMatrix mass;
};

VolumeMatrices assemble_volume_matrices(const space::H1Space& space, const VolumeMatrixRequest& request);

/// F_k = (f, φ_k), shape (n_dofs).
Eigen::VectorXd assemble_volume_load(const space::H1Space& space, const std::function<double(const mesh::Point&)>& f);

/// G_k = ∫_{edges in `parts`} g(x, n) φ_k ds with n the outward unit normal, shape (n_dofs).
/// Used for Neumann data ∂_n u = g on Γ_N.
Eigen::VectorXd assemble_boundary_load(const space::H1Space& space, const std::set<mesh::BoundaryPart>& parts,
                                       const std::function<double(const mesh::Point& x, const mesh::Point& normal)>& g);

}  // namespace hpcontact::assembly
