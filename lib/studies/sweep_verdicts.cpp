// Verdicts of a stability sweep: α ≈ C h_min^r fitted per configuration over the finest levels
// of alpha.csv.
#include "studies/sweep_verdicts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

#include "core/error.hpp"
#include "studies/stability_sweep.hpp"

namespace hpcontact::studies {
namespace {

std::vector<std::map<std::string, std::string>> read_csv(const std::filesystem::path& path) {
  std::vector<std::map<std::string, std::string>> rows;
  std::ifstream in(path);
  if (!in) return rows;
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  std::stringstream header_stream(line);
  for (std::string cell; std::getline(header_stream, cell, ',');) header.push_back(cell);
  if (header != alpha_columns())
    throw InputError("'" + path.string() + "' is not an alpha.csv written by hpcontact sweep " +
                     "(other columns, e.g. from an older version): choose another --out folder, or --restart");
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::map<std::string, std::string> row;
    std::stringstream cells(line);
    std::size_t k = 0;
    for (std::string cell; std::getline(cells, cell, ',') && k < header.size(); ++k) row[header[k]] = cell;
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace

io::CsvTable fit_verdicts(const std::filesystem::path& alpha_csv, int fit_levels) {
  using Key = std::tuple<std::string, std::string, int, int, std::string>;
  std::map<Key, std::vector<std::pair<double, double>>> series;  // (h_min, α)
  std::map<Key, double> ratio_value;
  for (const auto& row : read_csv(alpha_csv)) {
    const double ratio = std::stod(row.at("ratio"));
    const Key key{row.at("problem"), row.at("norm"), std::stoi(row.at("p")), std::stoi(row.at("pC")),
                  fmt::format("{:.6g}", ratio)};
    series[key].emplace_back(std::stod(row.at("h_min")), std::stod(row.at("alpha")));
    ratio_value[key] = ratio;
  }
  io::CsvTable verdicts({"problem", "norm", "p", "pC", "ratio", "rate", "C", "alpha_finest", "verdict"});
  for (auto& [key, points] : series) {
    std::sort(points.begin(), points.end(), [](auto& a, auto& b) { return a.first > b.first; });
    const int count = std::min<int>(fit_levels, static_cast<int>(points.size()));
    const double alpha_finest = points.back().second;
    double rate = NAN, constant = NAN;
    std::string verdict;
    if (alpha_finest <= 1e-6) {
      verdict = "singular";
    } else if (count < 2) {
      verdict = "too_few_levels";
    } else {
      // Least squares for log α = log C + r log h over the finest levels.
      double mean_x = 0, mean_y = 0, sxx = 0, sxy = 0;
      const auto first = points.end() - count;
      for (auto it = first; it != points.end(); ++it) {
        mean_x += std::log(it->first) / count;
        mean_y += std::log(std::max(it->second, 1e-300)) / count;
      }
      for (auto it = first; it != points.end(); ++it) {
        const double dx = std::log(it->first) - mean_x;
        sxx += dx * dx;
        sxy += dx * (std::log(std::max(it->second, 1e-300)) - mean_y);
      }
      if (sxx < 1e-6 * count) {  // log h_min varies by less than 0.1 %: the levels do not refine Γ_C
        verdict = "h_unchanged";
      } else {
        rate = sxy / sxx;
        constant = std::exp(mean_y - rate * mean_x);
        verdict = rate >= 0.3 ? "decaying" : "stable";
      }
    }
    const auto& [problem, norm, p, pc, ratio_text] = key;
    verdicts.add_row({problem, norm, static_cast<long long>(p), static_cast<long long>(pc), ratio_value[key], rate,
                      constant, alpha_finest, verdict});
  }
  return verdicts;
}

}  // namespace hpcontact::studies
