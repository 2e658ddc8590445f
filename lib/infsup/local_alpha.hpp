// A cheap predictor of α from small eigenproblems on patches of Γ_C, in the spirit of Stenberg's
// macro-element technique: for each segment K of T_{C,H}, the patch J made of the edges of T_h
// under K and its two neighbours, and
//   α_J = min_{μ ∈ M(J)} sup_{v ∈ V_0(J)} (μ, v)_{0,J} / (‖μ‖_{-1/2,J} ‖v‖_{1/2,J}),
// with V_0(J) the traces on J that vanish at its ends (not at a free end of an open zone of Γ_C),
// M(J) the multipliers of the segments inside J, ‖·‖_{1/2,J} the discrete interpolation norm of
// the trace space and ‖·‖_{-1/2,J} its dual over a richer reference space on J. α_J does not
// change with the patch's size, and a multiplier that no trace of its patch sees (the
// one-dimensional checkerboard) makes α_J vanish; so does a patch with as many multiplier
// functions per length as trace unknowns (the balance behind α decaying like h). The predicted α
// is min_J α_J.
// Everything is one-dimensional in the arc length: curved edges count as straight ones of the
// same length, an elastic trace as one scalar component; a contact pair adds the master's traces
// mapped onto the slave's arc length (b(μ, v) = (μ, v_s − v_m∘Φ): S = S_s + S_m).
// The body enters through one number per edge, its cell's depth d normal to Γ_C: a cell much
// taller than its edge h cannot let a trace decay as fast as H^{1/2} asks, which inflates the
// trace's norm by about √(d/h) (the global α of studies/stability/graded_anisotropic.toml follows
// 1.8 … 8 √(h/d)); α_J is multiplied by min(1, 2 √(h/d)) over the edges of J.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "mesh/boundary_mesh.hpp"
#include "space/multiplier_family.hpp"

namespace hpcontact::infsup {

/// Γ_C as the predictor sees it: the trace of T_h and T_{C,H} in the arc length.
struct TracePairing {
  std::vector<std::array<double, 2>> edges;  ///< the edges of T_h on Γ_C: [s_begin, s_end], in order of s
  std::vector<int> edge_degrees;             ///< the trace's degree on each edge (its cell's p_T)
  std::vector<double> edge_depths;           ///< each edge's cell's extent normal to the edge; empty: no factor
  /// A contact pair: the master's trace edges as Φ maps them onto the slave's arc length, in
  /// order, with their degrees (empty for one body).
  std::vector<std::array<double, 2>> master_edges;
  std::vector<int> master_degrees;
  const mesh::BoundaryMesh* boundary_mesh = nullptr;  ///< T_{C,H} with Γ_C's zones
  /// Per zone, whether the traces vanish at its start and end (Γ_D there); empty: free ends.
  std::vector<std::array<bool, 2>> held_zone_ends;
  std::vector<int> segment_degrees;  ///< p_C per segment
  space::MultiplierFamily family;
  /// s of the friction pairing (22) as a function of the arc length; empty: (11), no weight.
  std::function<double(double)> weight;
};

/// Patches whose α_J is below this are predicted unstable. Calibrated against the global α of
/// the configurations of studies/stability/predictor (docs/stability.md): below it lie the
/// patches with a one-dimensional checkerboard, above it every pairing with a global α ≥ 0.1.
inline constexpr double kStablePatchAlpha = 0.2;

struct PredictedAlpha {
  double alpha = 0.0;        ///< min_J α_J
  int weakest_segment = -1;  ///< the segment whose patch has that α
  /// Π(h, H, p, p_C) of (20) with θ = 1, the largest over the segments: h the longest edge
  /// under the segment, p the smallest trace degree there.
  double pi = 0.0;
  int patches = 0;           ///< patches analysed (segments with a multiplier)
  int distinct_patches = 0;  ///< of them, with an eigenproblem of their own (the others repeat one)
  bool stable() const { return alpha >= kStablePatchAlpha; }
};

/// @throws NumericalError if a patch's eigenproblem fails.
PredictedAlpha predict_alpha(const TracePairing& pairing);

}  // namespace hpcontact::infsup
