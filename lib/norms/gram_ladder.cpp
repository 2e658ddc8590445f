// GramLadder and the ladders of the two realizations.
#include "norms/gram_ladder.hpp"

#include "core/error.hpp"
#include "core/timer.hpp"
#include "norms/h_minus_half_gram.hpp"
#include "norms/interpolation_norm_kernel.hpp"

namespace hpcontact::norms {

GramLadder::GramLadder(Build build, int top_level) : build_(std::move(build)), top_level_(top_level) {}

const Eigen::MatrixXd& GramLadder::at(int level) const {
  HPC_VERIFY(level >= 0 && level <= top_level_, "GramLadder: level beyond the top of the ladder");
  auto found = levels_.find(level);
  if (found == levels_.end()) {
    Stopwatch clock;
    found = levels_.emplace(level, build_(level, &geometric_)).first;
    seconds_ += clock.seconds();
  }
  return found->second;
}

GramLadder interpolation_gram_ladder(const space::MultiplierSpace& multipliers) {
  // Level 0 is accurate to ~1e-9, level 1 to round-off: α is taken on level 1, and level 2 is
  // there for the tests that check the estimate against the next level.
  return GramLadder([&multipliers](int level, bool*) { return interpolation_norm_gram_kernel(multipliers, {level}); },
                    2);
}

GramLadder extension_gram_ladder(const mesh::Mesh* mesh, std::vector<int> cell_degrees,
                                 const space::MultiplierSpace& multipliers, linalg::Distribution distribution) {
  // A copy where the mesh is given (serial; distributed, the first rank only), for the ladder's life.
  std::shared_ptr<const mesh::Mesh> copy = mesh ? std::make_shared<const mesh::Mesh>(*mesh) : nullptr;
  return GramLadder(
      [copy, degrees = std::move(cell_degrees), &multipliers, distribution](int level, bool* geometric) {
        bool graded = false;
        Eigen::MatrixXd gram =
            extension_norm_gram(copy.get(), degrees, multipliers, extension_reference_at(level), &graded, distribution);
        if (!graded) *geometric = false;
        return gram;
      },
      4);
}

GramLadder restricted_ladder(const GramLadder& envelope, const space::MultiplierSpace& envelope_space,
                             const space::MultiplierSpace& sub) {
  return GramLadder(
      [&envelope, &envelope_space, sub](int level, bool* geometric) {
        Eigen::MatrixXd gram = restrict_gram(envelope.at(level), envelope_space, sub);
        if (!envelope.geometric()) *geometric = false;
        return gram;
      },
      envelope.top_level());
}

}  // namespace hpcontact::norms
