// The ratio h/H of the edges of T_h on Γ_C to the segments of T_{C,H}, as users write it: a
// number or a fraction ("1", "0.5", "2/3"), kept with its text for labels and CSV.
#pragma once

#include <string>

namespace hpcontact::scene {

struct Ratio {
  double value = 1.0;
  std::string text = "1";  ///< as written, e.g. "2/3"
};

/// The largest h/H accepted.
constexpr double kMaxRatio = 64.0;

/// @throws InputError naming `where` and `key` unless `text` is a number or a fraction of a whole
/// numerator and a number, in (0, kMaxRatio].
Ratio parse_ratio(const std::string& text, const std::string& where, const std::string& key = "ratio");

}  // namespace hpcontact::scene
