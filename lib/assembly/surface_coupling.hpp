// The couplings between a solid space (hexahedra or tetrahedra) and the multipliers on a flat Γ_C, integrated exactly
// on the overlaps of trace faces and cells of T_{C,H} (where both are polynomial):
//   B_ij = ∫_{Γ_C} w ℓ_i φ_j ds   and   G_i = ∫_{Γ_C} ℓ_i g ds.
#pragma once

#include <Eigen/Core>

#include "assembly/solid_load.hpp"
#include "linalg/coupling_matrix.hpp"
#include "space/solid_space.hpp"
#include "space/solid_vector_space.hpp"
#include "space/surface_multiplier_space.hpp"

namespace hpcontact::assembly {

/// The local coordinates ξ in its cell of the point of a trace face at plane coordinates a (the
/// inverse of a square face's bilinear map by Newton's method, one step on a parallelogram; the
/// barycentric coordinates on a triangle).
Eigen::Vector3d face_point_in_cell(const mesh::FlatContactSurface& surface, const mesh::BoundaryFace& face,
                                   const Eigen::Vector2d& a);

/// B of shape (multipliers.n_dofs(), space.n_dofs()), with the weight w (empty: w = 1; the
/// friction problem (13) pairs μ with s γ_C v). Each overlap polygon is cut into triangles from its
/// first vertex and integrated with the collapsed Gauss rule of p + p_C + 2 points per direction:
/// exact for w = 1 on parallelogram and triangle faces (the integrand is then a polynomial of degree
/// 2(p + p_C) in the plane); on other flat quadrilaterals the trace shapes are not polynomial and the rule is
/// that of a degree-two margin. The multiplier space must live on Γ_C of the space's mesh.
linalg::Coupling surface_coupling(const space::SolidH1Space& space, const space::SurfaceMultiplierSpace& multipliers,
                                  const SolidFunction& weight = {});

/// The coupling of the multipliers with v·d on the vector space from the scalar B:
/// B_d(i, dof(j, c)) = d_c B(i, j) (components along which d vanishes, or held, add nothing).
linalg::Coupling directional_coupling(const space::SolidVectorSpace& space, const linalg::Coupling& scalar,
                                      const Eigen::Vector3d& direction);

/// Whether s > 0 somewhere on cell c of T_{C,H} (sampled at 12 × 12 Gauss points, or the 144
/// collapsed points of a triangle): the friction
/// problem (13) and its pairing (22) keep only the multipliers of such cells (B^s has no entry on
/// the others, where λ would be undetermined).
bool cell_meets_support(const mesh::SurfaceMultiplierMesh& mesh, int cell, const SolidFunction& s);

/// G_i = ∫ ℓ_i g over Γ_C, shape (multipliers.n_dofs()): tensor Gauss rule of p_C + 6 points per
/// axis on each rectangle of T_{C,H}, the collapsed rule of (p_C + 6)² points on each triangle.
Eigen::VectorXd surface_multiplier_load(const space::SurfaceMultiplierSpace& multipliers, const SolidFunction& g);

}  // namespace hpcontact::assembly
