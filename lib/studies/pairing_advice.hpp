// `hpcontact advise`: for a scene's T_h and p, the multiplier discretizations (p_C, T_{C,H} by
// h/H, the multiplier family, the constraint points) ranked by the predicted α
// (infsup/local_alpha.hpp) and the multipliers they resolve, with the global α of the recommended
// candidate and its runner-up, and the scene edits that apply the recommendation.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "io/csv_writer.hpp"
#include "scene/scene.hpp"

namespace hpcontact::studies {

/// One multiplier discretization for the scene's T_h and p.
struct AdviceCandidate {
  int pc = 0;
  scene::Ratio ratio;
  space::MultiplierFamily family;
  std::optional<int> constraint_points;  ///< per segment (p_C + 1); none for the families (their nodes)
  double alpha_predicted = 0.0;
  std::optional<double> alpha;        ///< the global α (`hpcontact infsup`), for the recommended row and its runner-up
  long long nmult = 0, unknowns = 0;  ///< multiplier functions; unknowns of the primal space plus those
  bool admitted = false;              ///< alpha_predicted ≥ the advice's alpha_min
  std::vector<std::string> edits;     ///< the scene edits that make the scene this candidate
};

struct PairingAdvice {
  std::string p;  ///< the scene's p as written
  /// Admitted candidates first, by multipliers (resolution for the same primal cost), then by
  /// predicted α; then the others by predicted α.
  std::vector<AdviceCandidate> candidates;
  double alpha_min = 0.0;
  std::optional<std::size_t> recommended, runner_up;  ///< indices into candidates
  double seconds = 0.0;
};

struct AdviceOptions {
  /// Candidates need alpha_predicted ≥ this; default: 0.1 · the best candidate's, and at least
  /// the predictor's threshold (kStablePatchAlpha).
  std::optional<double> alpha_min;
  std::function<void(const std::string&)> progress;  ///< may be empty
};

/// @throws InputError as the scene's builders do, or if `options.alpha_min` is outside (0, 1].
PairingAdvice advise_pairing(const scene::Scene& scene, const AdviceOptions& options = {});

/// advice.csv: zone,p,pC,ratio,family,constraint_points,alpha_predicted,alpha,unknowns,recommended
/// (zone "all": one choice for every zone of Γ_C; recommended: yes, runner-up or no).
io::CsvTable advice_table(const PairingAdvice& advice);

}  // namespace hpcontact::studies
