// The inf-sup constant α(h, H, p, p_C) of a 3-D pairing: S^p(T_h) on hexahedra with M^{p_C}(T_{C,H})
// on a flat rectangular Γ_C,
//   α² = λ_min of  S_G x = λ G x,   S_G = B A_G⁻¹ Bᵀ,   A_G = K + M,
// with B the coupling (Signorini, (11)) or B^s with the multipliers of the cells of T_{C,H} that
// meet supp s (friction, (22)); or, on [Q_p]³ with the vector H¹ Gram matrix A_G, the pairing of
// the normal multiplier with v·n (signorini), or of the normal and the two tangential ones with
// (v·n, v·e_1, v·e_2) (friction; G = diag(G, G, G)); and G the interpolation norm of H^{-1/2}(Γ_C)
// (norms/surface_interpolation_gram.hpp), refined on its ladder until α's error estimate is below
// the tolerance, as in 2-D (infsup/infsup_analysis.hpp). S_G is dense, B A_G⁻¹ Bᵀ from the trailing
// block of A_G's factor with Γ_C's trace last, or applied by products with G (many multipliers).
#pragma once

#include "assembly/condensed_factor.hpp"
#include "assembly/solid_load.hpp"
#include "contact/trace_operator.hpp"
#include "infsup/infsup_analysis.hpp"
#include "mesh/contact_surface.hpp"
#include "space/solid_space.hpp"
#include "space/solid_vector_space.hpp"
#include "space/surface_multiplier_space.hpp"

namespace hpcontact::infsup {

/// A_G = K + M on `space` with every dof of Γ_C (`surface`) last (`trace_last`; the dense S_G is
/// its trailing block, the products need no such order): one factor serves every multiplier space
/// on Γ_C (a sweep's p_C and H on one T_h). `distribution`: factorized over its ranks, as K of a
/// distributed 3-D solve (every rank holds the box and makes the same calls), or serial.
assembly::CondensedFactor solid_gram_factor(const space::SolidH1Space& space, const mesh::FlatContactSurface& surface,
                                            bool trace_last = true, linalg::Distribution distribution = {});
/// The same for the vector H¹ Gram matrix on [Q_p]³ (every component of the dofs of Γ_C last).
assembly::CondensedFactor solid_gram_factor(const space::SolidVectorSpace& space,
                                            const mesh::FlatContactSurface& surface, bool trace_last = true,
                                            linalg::Distribution distribution = {});

/// Whether α takes the products path (surface_products_ladder.hpp) for `multipliers` rows of B:
/// `automatic` with the SLEPc backend from kAlphaProductsFrom multipliers on (the dense backend is
/// the LAPACK-type reference and keeps S_G and G dense). Measured on the cube of
/// studies/three_d/cube.toml (n³ hexahedra, p = 2, p_C = 1, H = 2h, one thread): 0.41 s on both
/// paths at 16 multipliers, 0.59 s against 1.09 s at 64, 1.44 s against 3.19 s at 144
/// (docs/three_d.md, "α by products"). The rule ignores the unknowns: on a thin slab of 4 356
/// unknowns the dense path was faster at 256 multipliers (0.22 s against 0.38 s), where each
/// product is a large part of a cheap solve.
inline constexpr long kAlphaProductsFrom = 64;
inline bool uses_alpha_products(contact::SchurPath path, Eigen::Index multipliers, EigenBackend backend) {
  if (path != contact::SchurPath::automatic) return path == contact::SchurPath::products;
  return backend == EigenBackend::slepc && multipliers >= kAlphaProductsFrom;
}

struct SolidInfSupSetup {
  const space::SolidH1Space* space = nullptr;
  /// The elastic pairing when given (on [space]³ with its rollers; s is then not used).
  const space::SolidVectorSpace* vector_space = nullptr;
  const space::SurfaceMultiplierSpace* multipliers = nullptr;  ///< on Γ_C of the space's mesh
  PairingProblem problem = PairingProblem::signorini;
  assembly::SolidFunction friction_bound;  ///< s, required for the friction problem
  double alpha_tolerance = 1e-4;           ///< in (0, 0.1]
  /// Optional, built when absent: solid_gram_factor of (space or vector_space, Γ_C), and the ladder of
  /// `multipliers` (surface_interpolation_gram_ladder; given, it keeps `automatic` on the dense
  /// path, and the products path refuses it).
  const assembly::CondensedFactor* gram_factor = nullptr;
  const norms::GramLadder* grams = nullptr;
  /// S_G and G formed densely, or applied by products (uses_alpha_products); the products ignore
  /// the backend, and take a factor with or without the trace last.
  contact::SchurPath path = contact::SchurPath::automatic;
  /// The ranks that factorize A_G when it is built here, or serial. Collective: on the dense path
  /// every rank forms S_G from the distributed factor and solves the same small eigenproblem; on the
  /// products path the first rank runs the eigensolver and the others serve its products
  /// (contact/led_products.hpp). Every rank gets the same α.
  linalg::Distribution distribution;
};

/// α with the fields of InfSupResult: h the longest edge of T_h, H the longest side of the cells
/// of T_{C,H}, the mode in the multipliers' nodal coefficients (0 off supp s; the elastic friction
/// pairing: normal, then e_1, then e_2 blocks), no zones.
/// @throws InputError for a bad tolerance, a friction problem without s or with s ≡ 0 on Γ_C.
InfSupResult analyse_solid_infsup(const SolidInfSupSetup& setup, EigenBackend backend);

}  // namespace hpcontact::infsup
