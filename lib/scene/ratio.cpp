// Parsing h/H.
#include "scene/ratio.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "core/error.hpp"

namespace hpcontact::scene {

Ratio parse_ratio(const std::string& text, const std::string& where, const std::string& key) {
  double value = NAN;
  try {
    std::size_t used = 0;
    const auto slash = text.find('/');
    if (slash == std::string::npos) {
      value = std::stod(text, &used);
      if (used != text.size()) value = NAN;
    } else {
      const double numerator = std::stod(text.substr(0, slash), &used);
      const bool whole_numerator = used == slash;
      const double denominator = std::stod(text.substr(slash + 1), &used);
      value = (whole_numerator && used == text.size() - slash - 1) ? numerator / denominator : NAN;
    }
  } catch (const std::exception&) {
    value = NAN;
  }
  if (!(value > 0.0) || !std::isfinite(value))
    throw_bad_input(where, key, "\"" + text + "\"", "must be a positive number or fraction such as \"2/3\"");
  if (value > kMaxRatio)
    throw_bad_input(where, key, "\"" + text + "\"",
                    fmt::format("at most {}: segments of T_{{C,H}} that many times shorter than the edges of T_h "
                                "are far past any stable pairing (α falls like H/h) and cost memory like m = n · ratio",
                                kMaxRatio));
  return {value, text};
}

}  // namespace hpcontact::scene
