// Boundary samples of a contact solution on Γ_C (boundary_<problem>.csv): u, the obstacle or
// bound, and λ.
#pragma once

#include "contact/contact_problem.hpp"
#include "io/csv_writer.hpp"

namespace hpcontact::postprocess {

struct BoundarySamples {
  /// x,u,obstacle,lambda (Signorini) or x,u,s,lambda (friction), plus y,s_arc,zone
  io::CsvTable table;
  double contact_set_length;  ///< length of Γ_C where λ ≠ 0 (|λ| > 1e-10 max|λ|), from the samples
  std::vector<double> zone_contact_set_length;  ///< the same per zone of Γ_C
};

/// Samples every interval of the common refinement of T_h|Γ_C and T_{C,H} at `per_interval`
/// equidistant points including both ends, so that at least that many fall in every boundary
/// element and jumps of λ show.
BoundarySamples sample_boundary(const contact::ContactSetup& setup, const contact::ContactSolution& solution,
                                int per_interval = 20);

}  // namespace hpcontact::postprocess
