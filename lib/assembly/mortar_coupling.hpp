// The master side of a mortar coupling between two bodies: with the multiplier μ on the slave's
// Γ_C and Φ the closest point on the master's (mesh::MasterProjection),
//   B^m_ij = ∫_{Γ_C^s} μ_i φ^m_j∘Φ ds,
// so that b(μ, v) = ∫ μ (v_s − v_m∘Φ) is B^s v_s − B^m v_m with B^s today's assemble_coupling of
// the slave. Integrated exactly for polynomial data on straight edges: over the mortar segments
// cut at the breakpoints of T_{C,H}, Φ is affine and φ^m_j∘Φ a polynomial of the master's degree.
#pragma once

#include "assembly/coupling.hpp"
#include "linalg/coupling_matrix.hpp"
#include "mesh/contact_pair_geometry.hpp"
#include "space/h1_space.hpp"
#include "space/multiplier_space.hpp"
#include "space/vector_space.hpp"

namespace hpcontact::assembly {

/// B^m, shape (multipliers.n_dofs(), master_space.n_dofs()); `master_space` lives on the mesh of
/// projection.master(). Parts of Γ_C^s that the master does not cover (MortarSegment::covered)
/// add nothing: there the slave meets no master.
/// @throws InputError as assemble_coupling if T_{C,H} does not span the slave's Γ_C, and as
/// MasterProjection::mortar_segments where Φ jumps.
linalg::Coupling assemble_mortar_coupling(const space::H1Space& master_space, const mesh::MasterProjection& projection,
                                          const mesh::ContactBoundary& slave,
                                          const space::MultiplierSpace& multipliers);

/// The elastic master side: B^{m,d}_{i,(j,c)} = ∫_{Γ_C^s} μ_i (φ^m_j∘Φ) d_c ds with d the slave's
/// outward normal n_s or its tangent t_s (trace_direction of the slave), so that
/// ∫ μ (v_s − v_m∘Φ)·d is B^{s,d} v_s − B^{m,d} v_m (B^{s,d} the slave's
/// assemble_directional_coupling). Columns numbered by space::VectorSpace::dof of `master_space`.
/// @throws InputError as assemble_mortar_coupling.
linalg::Coupling assemble_directional_mortar_coupling(const space::VectorSpace& master_space,
                                                      const mesh::MasterProjection& projection,
                                                      const mesh::ContactBoundary& slave,
                                                      const space::MultiplierSpace& multipliers,
                                                      TraceDirection direction);

}  // namespace hpcontact::assembly
