// Global sparse stiffness K, mass M, volume load F and boundary (Neumann) load on S^p(T_h).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <set>

#include "assembly/local_rows.hpp"
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

using DofContribution = std::function<void(int dof, double value)>;

/// add(k, (f, φ_k)_T) for every shape of every cell T that `target` assembles (Dirichlet shapes
/// excluded): the volume load cell by cell, for any layout of the result.
void visit_volume_load(const space::H1Space& space, const std::function<double(const mesh::Point&)>& f,
                       const LocalRows& target, const DofContribution& add);

/// add(k, ∫_e g(x, n) φ_k ds) for every boundary edge e in `parts` whose cell `target` assembles,
/// n the outward unit normal.
void visit_boundary_load(const space::H1Space& space, const std::set<mesh::BoundaryPart>& parts,
                         const std::function<double(const mesh::Point& x, const mesh::Point& normal)>& g,
                         const LocalRows& target, const DofContribution& add);

/// F_k = (f, φ_k), shape (target.size(n_dofs)): the whole load or a rank's share.
Eigen::VectorXd assemble_volume_load(const space::H1Space& space, const std::function<double(const mesh::Point&)>& f,
                                     const LocalRows& target = {});

/// G_k = ∫_{edges in `parts`} g(x, n) φ_k ds with n the outward unit normal, shape
/// (target.size(n_dofs)). Used for Neumann data ∂_n u = g on Γ_N.
Eigen::VectorXd assemble_boundary_load(const space::H1Space& space, const std::set<mesh::BoundaryPart>& parts,
                                       const std::function<double(const mesh::Point& x, const mesh::Point& normal)>& g,
                                       const LocalRows& target = {});

}  // namespace hpcontact::assembly
