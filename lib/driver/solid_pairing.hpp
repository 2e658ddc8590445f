// α of a 3-D scene's pairing, for `hpcontact infsup` and the stability sweeps: T_h and p of a
// discretized scene, T_{C,H} and p_C of the scene at hand (a sweep's point varies them on one T_h),
// the [infsup] problem and tolerance, the interpolation norm of the flat Γ_C.
#pragma once

#include <optional>

#include "assembly/condensed_factor.hpp"
#include "driver/run_result.hpp"
#include "driver/solid_scene.hpp"
#include "infsup/infsup_analysis.hpp"

namespace hpcontact::driver {

/// @throws InputError naming the key for what α of a 3-D scene does not take: infsup.norm =
/// extension, the scalar friction pairing without data.s. (infsup.primal_norm is refused with
/// the keys of planar scenes: an elastic scene's α is in the vector H¹ norm.)
void check_solid_pairing(const scene::Scene& scene);

/// α of `scene`'s pairing on `d` (the scene's own, or one with the same T_h and p; its T_{C,H} is
/// not used: the scene's own is built) and the record `hpcontact infsup` prints and a sweep stores
/// (`level`: the sweep's, from 1). An elastic scene pairs the normal (signorini) or the normal and
/// tangential (friction) multipliers with [Q_p]³. The record's n is the number of trace faces on
/// Γ_C, m the number of cells of T_{C,H}, h_min the shortest edge of a trace face, ratio the
/// scene's h/H or else √(m / n); alpha_predicted is NaN (the local predictor is planar).
/// `gram_factor`: A_G of (d.space or d.vector_space, Γ_C) when shared (infsup::solid_gram_factor),
/// built otherwise, over the ranks of `distribution` (collective; every rank gets the same α).
struct SolidAlpha {
  infsup::InfSupResult result;
  InfSupSummary summary;
};
SolidAlpha solid_scene_alpha(const scene::Scene& scene, const SolidDiscretization& d, infsup::EigenBackend backend,
                             const assembly::CondensedFactor* gram_factor = nullptr, int level = 1,
                             const linalg::Distribution& distribution = {});

/// The facts of a 3-D scene's pairing a sweep needs before anything is solved: trace faces on
/// Γ_C, the shortest edge of one, cells of T_{C,H}.
struct SolidPairingFacts {
  int faces = 0;
  double h_min = 0.0;
  int multiplier_cells = 0;
};
SolidPairingFacts solid_pairing_facts(const scene::Scene& scene, const SolidDiscretization& d);

}  // namespace hpcontact::driver
