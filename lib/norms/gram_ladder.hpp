// The H^{-1/2}(Γ_C) Gram matrix G of one multiplier space at successive reference resolutions
// (levels 0, 1, …, each built on first use), so that α can be computed on one level and its
// error estimated from the level below (infsup/infsup_analysis.hpp).
//
// Both realizations approach their limit from below as the resolution grows: the reference-space
// norms are dual norms over nested subspaces, and the kernel quadrature is exact to round-off
// from level 1 on. So α computed with a coarser G is an upper bound of α with a finer one.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <map>
#include <memory>
#include <vector>

#include "linalg/distribution.hpp"
#include "mesh/mesh.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::norms {

class GramLadder {
 public:
  /// `build(level, geometric)` for level = 0 … top_level, shape (n_multiplier_dofs,
  /// n_multiplier_dofs); it clears *geometric if that level does not converge geometrically.
  using Build = std::function<Eigen::MatrixXd(int level, bool* geometric)>;
  GramLadder(Build build, int top_level);

  /// G at `level`, built on first use. @throws InternalError beyond top_level().
  const Eigen::MatrixXd& at(int level) const;
  int top_level() const { return top_level_; }
  /// Seconds spent building levels so far.
  double seconds() const { return seconds_; }
  /// Whether the levels built so far converge geometrically, so that the difference of two bounds
  /// the error (false: a reference that could not be graded; the estimate is then too low).
  bool geometric() const { return geometric_; }

 private:
  Build build_;
  int top_level_;
  mutable std::map<int, Eigen::MatrixXd> levels_;
  mutable double seconds_ = 0.0;
  mutable bool geometric_ = true;
};

/// The interpolation norm by its kernel (interpolation_norm_kernel.hpp), level = quadrature level.
/// `multipliers` (and its boundary mesh) must outlive the ladder.
GramLadder interpolation_gram_ladder(const space::MultiplierSpace& multipliers);

/// The extension norm on the references extension_reference_at(level), graded towards the
/// breakpoints of `multipliers` (which must outlive the ladder; the ladder keeps a copy of `mesh`),
/// each factorized by `distribution` (its ranks then build every level together, in one order;
/// `mesh` and `cell_degrees` are read on its first rank only: ExtensionReferenceFactor).
GramLadder extension_gram_ladder(const mesh::Mesh* mesh, std::vector<int> cell_degrees,
                                 const space::MultiplierSpace& multipliers, linalg::Distribution distribution = {});

/// The ladder of `sub` read off that of `envelope` (restrict_gram), which must outlive it.
GramLadder restricted_ladder(const GramLadder& envelope, const space::MultiplierSpace& envelope_space,
                             const space::MultiplierSpace& sub);

}  // namespace hpcontact::norms
