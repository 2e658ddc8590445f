// Where a discrete contact solution changes regime along Γ_C: the ends of the contact set of (9),
// of the stick zone of (13) and (15). These are the free-boundary singularities (u − g ~ d^{3/2}
// on one side, the multiplier's distance to its bound ~ d^{1/2} on the other) that a mesh must be
// graded towards for hp convergence.
#pragma once

#include <vector>

#include "contact/contact_problem.hpp"

namespace hpcontact::contact {

struct FreeBoundaryPoint {
  double s = 0.0;  ///< arc length on Γ_C: the estimate
  /// The constraint points it lies between: the last one where λ is free (strictly inside its
  /// bounds) and the first where λ is held at a bound, in either order.
  double bracket_begin = 0.0, bracket_end = 0.0;
};

/// Every change along Γ_C between a constraint point where λ(τ) is free and one where it is held
/// at a bound (within `tolerance` times the largest |bound| or |λ(τ)|). The estimate inside the
/// bracket uses the square-root onset: with m = |λ(τ) − bound| at the two nearest free points on
/// the free side, m ≈ c |s − s*|^{1/2} gives s*; the estimate is clipped to the bracket, and is the
/// bracket's shared end where both points sit at one breakpoint of T_{C,H} (the mesh is fitted).
std::vector<FreeBoundaryPoint> locate_free_boundary(const ContactSolution& solution, double tolerance = 1e-9);

}  // namespace hpcontact::contact
