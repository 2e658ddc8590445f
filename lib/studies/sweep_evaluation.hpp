// What a stability sweep computes at each point: α of the point's pairing as an InfSupRecord, on
// the T_h and operators its group (level, p) shares, with the Gram ladders its share reuses.
// Which rank computes which point, and when, is the SweepSchedule's.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "infsup/infsup_analysis.hpp"
#include "infsup/infsup_record.hpp"
#include "linalg/distribution.hpp"
#include "scene/ratio.hpp"
#include "studies/stability_sweep.hpp"
#include "studies/sweep_plan.hpp"

namespace hpcontact::studies {

class SweepEvaluation {
 public:
  /// T_h of one group's (level, p) and its operators, shared by the group's points.
  class Group;

  /// `points`: the sweep's (list_sweep_points), which decide the multiplier spaces whose Gram
  /// matrices a share's points reuse. `distribution`: the ranks that compute a unit together
  /// (serial, or a group of ranks), over which every factorization is distributed.
  SweepEvaluation(const StabilitySweep& sweep, const std::vector<SweepPoint>& points,
                  linalg::Distribution distribution);
  ~SweepEvaluation();
  SweepEvaluation(const SweepEvaluation&) = delete;
  SweepEvaluation& operator=(const SweepEvaluation&) = delete;

  /// Builds `group`'s T_h and operators. Collective on the distribution's ranks.
  std::shared_ptr<const Group> start_group(const SweepGroup& group) const;
  /// α of `point`, one of `group`'s points, with the Gram ladders of its share built on first use.
  /// Collective on the distribution's ranks.
  infsup::InfSupRecord evaluate_point(const SweepPoint& point, const Group& group);
  /// Frees the Gram ladders kept for the points of `share` (SweepGroup::share).
  void release_share(std::size_t share);

 private:
  struct ShareGrams;
  struct EnvelopeGram;
  const EnvelopeGram& envelope_of(const SweepPoint& point, const Group& group, const mesh::BoundaryMesh& boundary);

  const StabilitySweep& sweep_;
  const std::vector<SweepPoint>& points_;
  std::vector<std::optional<scene::Ratio>> ratios_;
  /// Per (level, ratio index): the p_C as given that its points use (the envelope's degrees).
  std::map<std::pair<std::size_t, std::size_t>, std::set<std::optional<int>>> degrees_used_;
  infsup::EigenBackend backend_;
  std::optional<int> largest_p_;  ///< the sweep's largest p (the extension norm's references); none without a list
  linalg::Distribution distribution_;
  std::map<std::size_t, std::unique_ptr<ShareGrams>> grams_of_share_;
};

}  // namespace hpcontact::studies
