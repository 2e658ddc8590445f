// One α as it is reported: the pairing it belongs to and what was computed, the same for
// `hpcontact infsup`, a stability sweep's points and summary.json (no format of its own here:
// io/infsup_record_csv.hpp writes it as a CSV row).
#pragma once

#include <optional>

#include "infsup/infsup_analysis.hpp"
#include "infsup/infsup_operators.hpp"
#include "mesh/contact_boundary.hpp"

namespace hpcontact::infsup {

/// α(h, H, p, p_C) of one pairing. For degree rules p is the smallest p_T and pc the largest
/// p_C: the worst case, as in Π.
struct InfSupRecord {
  // The pairing.
  PairingProblem problem = PairingProblem::signorini;
  GramNorm norm = GramNorm::interpolation;
  int p = 0, pc = 0;
  space::MultiplierFamily family;  ///< the multiplier family on T_{C,H}
  int level = 1;                   ///< the sweep's level, counted from 1 (1 for a single run)
  int n = 0;                       ///< edges of T_h on Γ_C
  int m = 0;                       ///< segments of T_{C,H}
  double h = 0.0;                  ///< longest edge of T_h
  double h_min = 0.0;              ///< shortest edge of T_h on Γ_C (a sweep's rate fits use it)
  double H = 0.0;                  ///< longest segment of T_{C,H}
  double ratio = 0.0;              ///< h/H as the scene or the sweep gives it, otherwise m / n
  double pi = 0.0;                 ///< Π(h, H, p, p_C) of (20)
  // The result.
  double alpha = 0.0;
  /// The local predictor's α (infsup/local_alpha.hpp) of the same pairing: min over the patches.
  double alpha_predicted = 0.0;
  double alpha_error = 0.0;  ///< estimate of |α − α_∞| (InfSupResult::alpha_error)
  /// InfSupResult::alpha_converged; unknown for a record read back from a CSV row, which does
  /// not hold it.
  std::optional<bool> alpha_converged;
  long long ndofs = 0;   ///< unknowns of the primal space
  long long nmult = 0;   ///< multiplier unknowns
  double seconds = 0.0;  ///< operators and eigenproblem

  bool operator==(const InfSupRecord&) const = default;
};

/// What an InfSupResult does not know of its pairing: its labels, degrees and meshes as reported.
struct PairingFacts {
  PairingProblem problem = PairingProblem::signorini;
  GramNorm norm = GramNorm::interpolation;
  space::MultiplierFamily family;
  int p = 0, pc = 0, level = 1, n = 0, m = 0;
  double h_min = 0.0;
  std::optional<double> ratio;  ///< h/H as given; absent: m / n
};

InfSupRecord make_infsup_record(const PairingFacts& pairing, const InfSupResult& result);

/// The shortest edge of T_h on Γ_C in arc length (InfSupRecord::h_min): the size of the finest
/// layer on graded meshes, where checkerboard modes live.
double shortest_contact_edge(const mesh::ContactBoundary& contact);

}  // namespace hpcontact::infsup
