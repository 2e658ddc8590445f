// Verdicts of a stability sweep: α ≈ C h_min^r fitted per configuration over the finest levels
// of its rows.
#include "studies/sweep_verdicts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>

namespace hpcontact::studies {
namespace {

// The rate of α ≈ C h_min^r by least squares of log α against log h_min over (h_min, α) points,
// or none when h_min hardly varies.
struct RateFit {
  double rate = NAN, constant = NAN;
  std::string verdict;
};

RateFit fit_rate(std::vector<std::pair<double, double>>::const_iterator first,
                 std::vector<std::pair<double, double>>::const_iterator last) {
  const double count = static_cast<double>(last - first);
  double mean_x = 0, mean_y = 0, sxx = 0, sxy = 0;
  for (auto it = first; it != last; ++it) {
    mean_x += std::log(it->first) / count;
    mean_y += std::log(std::max(it->second, 1e-300)) / count;
  }
  for (auto it = first; it != last; ++it) {
    const double dx = std::log(it->first) - mean_x;
    sxx += dx * dx;
    sxy += dx * (std::log(std::max(it->second, 1e-300)) - mean_y);
  }
  if (sxx < 1e-6 * count) return {NAN, NAN, "h_unchanged"};  // log h_min varies by less than 0.1 %
  const double rate = sxy / sxx;
  return {rate, std::exp(mean_y - rate * mean_x), rate >= 0.3 ? "decaying" : "stable"};
}

}  // namespace

io::CsvTable fit_verdicts(const std::vector<infsup::InfSupRecord>& rows, int fit_levels) {
  // Keyed by the labels as written, so that configurations come in the same order however they are read.
  using Key = std::tuple<std::string, std::string, int, int, std::string, std::string>;
  std::map<Key, std::vector<std::pair<double, double>>> series;  // (h_min, α)
  std::map<Key, double> ratio_value;
  for (const auto& row : rows) {
    const Key key{infsup::to_string(row.problem), infsup::to_string(row.norm),     row.p, row.pc,
                  space::to_string(row.family),   fmt::format("{:.6g}", row.ratio)};
    series[key].emplace_back(row.h_min, row.alpha);
    ratio_value[key] = row.ratio;
  }
  io::CsvTable verdicts({"problem", "norm", "p", "pC", "family", "ratio", "rate", "C", "alpha_finest", "verdict"});
  for (auto& [key, points] : series) {
    std::sort(points.begin(), points.end(), [](auto& a, auto& b) { return a.first > b.first; });
    const int count = std::min<int>(fit_levels, static_cast<int>(points.size()));
    const double alpha_finest = points.back().second;
    RateFit fit;
    if (alpha_finest <= 1e-6)
      fit.verdict = "singular";
    else if (count < 2)
      fit.verdict = "too_few_levels";
    else
      fit = fit_rate(points.end() - count, points.end());
    const auto& [problem, norm, p, pc, family, ratio_text] = key;
    verdicts.add_row({problem, norm, static_cast<long long>(p), static_cast<long long>(pc), family, ratio_value[key],
                      fit.rate, fit.constant, alpha_finest, fit.verdict});
  }
  return verdicts;
}

}  // namespace hpcontact::studies
