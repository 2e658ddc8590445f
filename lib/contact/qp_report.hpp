// What a contact QP solve reports, whichever method ran: the iteration log (iteration, active-set
// changes, KKT residual) that goes into summary.json.
#pragma once

#include <string>
#include <vector>

namespace hpcontact::contact {

struct QpIteration {
  int iteration;
  /// Active-set method: constraints switched between active and inactive after this step.
  /// Interior point: constraints whose predicted state (slack below multiplier, both scaled)
  /// changed in this step.
  int active_set_changes;
  double kkt_residual;  ///< relative, as defined by the method's KKT function
};

struct QpReport {
  std::string method;  ///< "active-set", "active-set+proximal", "interior-point", "projected-gradient", "mprgp"
                       ///< or "primal-dual-active-set"
  bool converged = false;
  double kkt_residual = 0.0;
  int iterations = 0;      ///< active-set steps or interior-point iterations
  int proximal_steps = 0;  ///< outer proximal steps (active-set method only)
  std::vector<QpIteration> log;
  /// Why the active-set method gave way to the interior-point method on a bound-constrained
  /// problem (its error message); empty when the first method succeeded.
  std::string fallback_reason;
  /// How S was applied: "dense" (formed from the factor's trailing block), "products" (one
  /// solve with K's factor per product, S never formed; 3-D scenes, contact/trace_operator.hpp) or
  /// "saddle_point" (not at all: the active-set steps are projected CG on K).
  std::string trace_operator = "dense";
  long products = 0;  ///< products by S on the products path; CG iterations on the saddle point
  /// saddle_point: K's preconditioner applications (one per CG iteration, a few for the tolerance)
  long preconditioner_applications = 0;
};

}  // namespace hpcontact::contact
