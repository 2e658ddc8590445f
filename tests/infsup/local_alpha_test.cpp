// The local α predictor (infsup/local_alpha.hpp) against the global α of the paper's §7 square,
// and the properties it rests on: no dependence on the patch's scale, the checkerboard and
// balanced counts flagged, a vanishing friction weight seen, tall cells penalized, a contact
// pair's master traces counted.
#include "infsup/local_alpha.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "mesh/rectangle_mesh.hpp"
#include "support/paper_alpha.hpp"
#include "support/slepc_test_environment.hpp"

using namespace hpcontact;

namespace {

// Γ_C of the n × n §7 square seen by the predictor: n edges of degree p on [0, 2] (scaled by
// `scale`) and m segments of degree p_C.
struct UniformTrace {
  mesh::BoundaryMesh boundary;
  infsup::TracePairing pairing;
  UniformTrace(int n, int m, int p, int pc, double scale = 1.0)
      : boundary(mesh::BoundaryMesh::uniform(2.0 * scale, m)) {
    for (int i = 0; i < n; ++i) pairing.edges.push_back({2.0 * scale * i / n, 2.0 * scale * (i + 1) / n});
    pairing.edge_degrees.assign(n, p);
    pairing.boundary_mesh = &boundary;
    pairing.segment_degrees.assign(m, pc);
  }
};

}  // namespace

// Every p ≤ 4, p_C ≤ p, h/H ∈ {1, 1/2, 2/3} on 12 × 12 cells: a pairing predicted stable has a
// global α ≥ 0.1 and the prediction is within 0.2 of it; pairings with as many multipliers as
// traces (p_C = p − 1 on T_h's edges, the paper's checkerboard; p_C = p ≤ 2 at h/H = 2/3) are
// predicted unstable; h/H = 1/2 with p_C < p is predicted stable.
TEST(LocalAlpha, AgreesWithTheGlobalAlphaOnThePaperSquare) {
  const int n = 12;
  for (int p = 1; p <= 4; ++p)
    for (int pc = 0; pc <= p; ++pc)
      for (const int m : {12, 6, 8}) {
        const std::string label = "p " + std::to_string(p) + " pC " + std::to_string(pc) + " m " + std::to_string(m);
        const UniformTrace trace(n, m, p, pc);
        const auto predicted = infsup::predict_alpha(trace.pairing);
        const double alpha = hpcontact::testing::paper_alpha(n, p, pc, m).alpha;
        if (predicted.stable()) {
          EXPECT_GE(alpha, 0.1) << label;
          EXPECT_NEAR(predicted.alpha, alpha, 0.2) << label;
        }
        if ((pc + 1) * m >= p * n) EXPECT_FALSE(predicted.stable()) << label;  // as many multipliers as traces
        if (m == 6 && pc < p) EXPECT_TRUE(predicted.stable()) << label;
        EXPECT_EQ(predicted.patches, m) << label;
      }
}

// α_J is a ratio of norms that scale alike: the same patches ten times longer give the same α;
// on a uniform mesh the interior patches are one eigenproblem.
TEST(LocalAlpha, DoesNotDependOnTheScale) {
  const auto small = infsup::predict_alpha(UniformTrace(24, 12, 3, 2).pairing);
  const auto large = infsup::predict_alpha(UniformTrace(24, 12, 3, 2, 10.0).pairing);
  EXPECT_GT(small.alpha, 0.5);
  EXPECT_NEAR(large.alpha, small.alpha, 1e-9 * small.alpha);
  EXPECT_LE(small.distinct_patches, 5);  // the two patches at each end and one interior patch
  EXPECT_NEAR(small.pi, 0.5 * 4 / 3, 1e-12);
}

// s = (2 − s)² vanishes at the end of Γ_C: the multipliers of the last segment hardly pair, as in
// the global α of (22), which decays like h² there.
TEST(LocalAlpha, SeesAVanishingFrictionWeight) {
  UniformTrace coarse(12, 6, 2, 0), fine(24, 12, 2, 0);
  for (auto* trace : {&coarse, &fine}) trace->pairing.weight = [](double s) { return (2 - s) * (2 - s); };
  const auto a = infsup::predict_alpha(coarse.pairing), b = infsup::predict_alpha(fine.pairing);
  EXPECT_FALSE(a.stable());
  EXPECT_GE(a.weakest_segment, 4);  // at the end where s vanishes
  EXPECT_NEAR(b.alpha / a.alpha, 0.25, 0.1);
}

// p_C = p at h/H = 2/3: three edges and two segments hold as many multipliers as traces, and α
// decays like h although every patch has α_J > 0.
TEST(LocalAlpha, FlagsBalancedCounts) {
  EXPECT_EQ(infsup::predict_alpha(UniformTrace(24, 16, 2, 2).pairing).alpha, 0.0);
  EXPECT_GT(infsup::predict_alpha(UniformTrace(24, 16, 3, 2).pairing).alpha, 0.5);
}

// Cells 100 times taller than their edge: α_J times 2 √(1/100).
TEST(LocalAlpha, PenalizesCellsTallerThanTheirEdge) {
  UniformTrace trace(12, 6, 3, 2);
  const double plain = infsup::predict_alpha(trace.pairing).alpha;
  trace.pairing.edge_depths.assign(12, 100 * 2.0 / 12);
  EXPECT_NEAR(infsup::predict_alpha(trace.pairing).alpha, 0.2 * plain, 1e-12);
  trace.pairing.edge_depths.assign(12, 0.5 * 2.0 / 12);  // flat cells: no factor
  EXPECT_NEAR(infsup::predict_alpha(trace.pairing).alpha, plain, 1e-12);
}

// p_C = p − 1 on the slave's edges is the checkerboard for one body; a master with 14 edges over
// the same 12 adds the traces that control it (the mortar pairing of two blocks).
TEST(LocalAlpha, CountsAContactPairsMasterTraces) {
  UniformTrace trace(12, 12, 2, 1);
  EXPECT_FALSE(infsup::predict_alpha(trace.pairing).stable());
  for (int i = 0; i < 14; ++i) trace.pairing.master_edges.push_back({2.0 * i / 14, 2.0 * (i + 1) / 14});
  trace.pairing.master_degrees.assign(14, 2);
  EXPECT_TRUE(infsup::predict_alpha(trace.pairing).stable());
}
