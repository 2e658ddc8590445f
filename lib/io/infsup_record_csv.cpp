// alpha_columns, add_alpha_row and read_alpha_row: the α record's CSV row both ways.
#include "io/infsup_record_csv.hpp"

#include <charconv>
#include <limits>
#include <sstream>

#include "core/error.hpp"

namespace hpcontact::io {
namespace {

// The cells of a line split at commas: the row's labels hold no comma, so none is quoted.
std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream stream(line);
  for (std::string cell; std::getline(stream, cell, ',');) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

// A number that is the whole cell, or nothing.
template <class Number>
std::optional<Number> number_of(const std::string& text) {
  Number value{};
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end) return std::nullopt;
  return value;
}

std::optional<int> int_of(const std::string& text) {
  const auto value = number_of<long long>(text);
  if (!value || *value < std::numeric_limits<int>::min() || *value > std::numeric_limits<int>::max())
    return std::nullopt;
  return static_cast<int>(*value);
}

// The enumerator whose label (infsup::to_string) is `text`, or nothing.
template <class Choice>
std::optional<Choice> choice_of(const std::string& text, std::initializer_list<Choice> choices) {
  for (const Choice choice : choices)
    if (infsup::to_string(choice) == text) return choice;
  return std::nullopt;
}

// The multiplier family labelled `text` (space::to_string), or nothing.
std::optional<space::MultiplierFamily> family_of(const std::string& text) {
  try {
    return space::parse_multiplier_family(text, "alpha.csv");
  } catch (const InputError&) {
    return std::nullopt;
  }
}

}  // namespace

std::vector<std::string> alpha_columns() {
  return {"problem", "norm",  "p",  "pC",    "family",          "level",       "n",     "m",     "h",      "h_min",
          "H",       "ratio", "Pi", "alpha", "alpha_predicted", "alpha_error", "ndofs", "nmult", "seconds"};
}

void add_alpha_row(CsvTable& table, const infsup::InfSupRecord& r) {
  table.add_row({infsup::to_string(r.problem), infsup::to_string(r.norm), static_cast<long long>(r.p),
                 static_cast<long long>(r.pc), space::to_string(r.family), static_cast<long long>(r.level),
                 static_cast<long long>(r.n), static_cast<long long>(r.m), r.h, r.h_min, r.H, r.ratio, r.pi, r.alpha,
                 r.alpha_predicted, r.alpha_error, r.ndofs, r.nmult, r.seconds});
}

std::optional<infsup::InfSupRecord> read_alpha_row(const std::string& line) {
  using infsup::GramNorm, infsup::PairingProblem;
  const auto c = cells_of(line);
  if (c.size() != alpha_columns().size()) return std::nullopt;
  // The cells in the order of alpha_columns().
  const auto problem = choice_of(c[0], {PairingProblem::signorini, PairingProblem::friction});
  const auto norm = choice_of(c[1], {GramNorm::interpolation, GramNorm::extension});
  const auto p = int_of(c[2]), pc = int_of(c[3]);
  const auto family = family_of(c[4]);
  const auto level = int_of(c[5]), n = int_of(c[6]), m = int_of(c[7]);
  const auto h = number_of<double>(c[8]), h_min = number_of<double>(c[9]), H = number_of<double>(c[10]);
  const auto ratio = number_of<double>(c[11]), pi = number_of<double>(c[12]);
  const auto alpha = number_of<double>(c[13]), alpha_predicted = number_of<double>(c[14]);
  const auto alpha_error = number_of<double>(c[15]);
  const auto ndofs = number_of<long long>(c[16]), nmult = number_of<long long>(c[17]);
  const auto seconds = number_of<double>(c[18]);
  if (!problem || !norm || !p || !pc || !family || !level || !n || !m || !h || !h_min || !H || !ratio || !pi ||
      !alpha || !alpha_predicted || !alpha_error || !ndofs || !nmult || !seconds)
    return std::nullopt;
  return infsup::InfSupRecord{.problem = *problem,
                              .norm = *norm,
                              .p = *p,
                              .pc = *pc,
                              .family = *family,
                              .level = *level,
                              .n = *n,
                              .m = *m,
                              .h = *h,
                              .h_min = *h_min,
                              .H = *H,
                              .ratio = *ratio,
                              .pi = *pi,
                              .alpha = *alpha,
                              .alpha_predicted = *alpha_predicted,
                              .alpha_error = *alpha_error,
                              .alpha_converged = std::nullopt,  // not a column
                              .ndofs = *ndofs,
                              .nmult = *nmult,
                              .seconds = *seconds};
}

}  // namespace hpcontact::io
