// Whether a run's pairing of T_h and T_{C,H} is stable, predicted before anything is solved
// (infsup/local_alpha.hpp), and the nearest stable alternative when it is not: what every solve
// reports, and what `[solve] stability` acts on.
#pragma once

#include "driver/run_result.hpp"
#include "driver/scene_discretization.hpp"
#include "infsup/local_alpha.hpp"
#include "mesh/contact_pair_geometry.hpp"

namespace hpcontact::driver {

/// Γ_C (`contact`, the slave's of a pair) as the predictor sees it, with `boundary_mesh` and
/// `segment_degrees` as T_{C,H} (the scene's own, or a candidate's) and, for the scalar friction
/// pairing ([infsup] problem = "friction"), the weight s. The trace degrees are the scene's p.
/// A two-body scene with `projection` (Φ onto the master's Γ_C) adds the master's traces.
/// `held_zone_ends` (SceneMesh::held_zone_ends) tells where Γ_D holds a zone's end.
/// `trace_degrees` (SceneDiscretization::trace_degrees), when not empty, replaces the scene's p.
infsup::TracePairing trace_pairing_of(const scene::Scene& scene, const mesh::ContactBoundary& contact,
                                      const std::vector<std::array<bool, 2>>& held_zone_ends,
                                      const mesh::BoundaryMesh& boundary_mesh, std::vector<int> segment_degrees,
                                      const mesh::MasterProjection* projection = nullptr,
                                      const std::vector<int>& trace_degrees = {});

/// The prediction for the scene's pairing on `d`; when it is not stable, the stable candidate
/// with the most multipliers among p_C lowered (a number p_C only) and T_{C,H} coarsened by 2
/// (`ratio` or `m` only), and the warning naming both.
StabilityReport predict_stability(const scene::Scene& scene, const SceneDiscretization& d,
                                  const mesh::MasterProjection* projection = nullptr);

/// Acts on `report` as `[solve] stability` says: prints the warning through `say` and marks it
/// warned (warn), or @throws InputError with it (refuse).
void act_on_stability(const scene::Scene& scene, StabilityReport& report,
                      const std::function<void(const std::string&)>& say);

/// The prediction for a candidate scene (the scene with another p_C, T_{C,H} or family) on the
/// same Γ_C: its α and its number of multiplier functions; none if the candidate does not fit the
/// mesh (a ratio without whole segments, a family that does not fit) or its prediction fails.
struct CandidatePrediction {
  double alpha = 0.0;
  long long nmult = 0;
  bool stable() const { return alpha >= infsup::kStablePatchAlpha; }
};
std::optional<CandidatePrediction> predict_candidate(const scene::Scene& candidate,
                                                     const mesh::ContactBoundary& contact,
                                                     const std::vector<std::array<bool, 2>>& held_zone_ends,
                                                     const mesh::MasterProjection* projection);

}  // namespace hpcontact::driver
