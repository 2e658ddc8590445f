// Coupling between S^p(T_h) and M^{p_C}(T_{C,H}) on Γ_C, integrated exactly on the common
// refinement of T_h|Γ_C and T_{C,H} (H need not be a multiple of h):
//   B_ij   = ∫_{Γ_C} μ_i φ_j ds,        B^s_ij = ∫_{Γ_C} s μ_i φ_j ds,      g_i = ∫_{Γ_C} g μ_i ds.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>

#include "linalg/coupling_matrix.hpp"
#include "mesh/contact_boundary.hpp"
#include "space/h1_space.hpp"
#include "space/multiplier_space.hpp"
#include "space/vector_space.hpp"

namespace hpcontact::assembly {

using BoundaryFunction = std::function<double(const mesh::Point&)>;

/// B (no weight) or B^s (weight s): shape (n_multiplier_dofs, n_primal_dofs). With a weight the
/// rule gets 4 extra Gauss points (s is data, not a polynomial).
/// @throws InputError if the boundary mesh does not span Γ_C.
linalg::Coupling assemble_coupling(const space::H1Space& space, const mesh::ContactBoundary& contact,
                                   const space::MultiplierSpace& multipliers, const BoundaryFunction& weight = {});

/// The normal of Γ_C (outward from Ω) or its unit tangent (along increasing arc length s).
enum class TraceDirection { normal, tangent };
/// That direction at arc length s (constant along a straight trace edge).
mesh::Point trace_direction(const mesh::ContactBoundary& contact, double s, TraceDirection direction);

/// B^d_{i,(j,c)} = ∫_{Γ_C} μ_i φ_j d_c ds with d the normal or the tangent: the pairing of a
/// multiplier with the normal (tangential) component of a field of [S^p(T_h)]², shape
/// (n_multiplier_dofs, space.n_dofs()), columns numbered by space::VectorSpace::dof.
linalg::Coupling assemble_directional_coupling(const space::VectorSpace& space, const mesh::ContactBoundary& contact,
                                               const space::MultiplierSpace& multipliers, TraceDirection direction);

/// g_i = ∫ g μ_i ds, shape (n_multiplier_dofs).
Eigen::VectorXd assemble_multiplier_load(const mesh::ContactBoundary& contact,
                                         const space::MultiplierSpace& multipliers, const BoundaryFunction& g);

/// The sub-intervals of the common refinement of T_h|Γ_C and T_{C,H}, each inside one trace
/// edge and one segment.
struct CommonInterval {
  double s_begin, s_end;
  int trace_edge;  ///< index into contact.edges()
  int segment;
};
std::vector<CommonInterval> common_intervals(const mesh::ContactBoundary& contact,
                                             const mesh::BoundaryMesh& boundary_mesh);

}  // namespace hpcontact::assembly
