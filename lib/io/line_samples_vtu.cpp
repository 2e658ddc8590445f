// line_samples_vtu_text.
#include "io/line_samples_vtu.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "io/vtk_xml_document.hpp"

namespace hpcontact::io {
namespace {

double number(const CsvCell& cell) {
  if (const auto* d = std::get_if<double>(&cell)) return *d;
  if (const auto* i = std::get_if<long long>(&cell)) return static_cast<double>(*i);
  throw std::logic_error("line_samples_vtu_text: a text cell in a numeric column");
}

bool numeric_column(const CsvTable& table, std::size_t column) {
  return std::ranges::all_of(table.rows(),
                             [&](const auto& row) { return !std::holds_alternative<std::string>(row[column]); });
}

}  // namespace

std::string line_samples_vtu_text(const CsvTable& table) {
  const auto& names = table.columns();
  auto column = [&](const std::string& name) {
    const auto it = std::ranges::find(names, name);
    if (it == names.end()) throw std::logic_error("line_samples_vtu_text: no column " + name);
    return static_cast<std::size_t>(it - names.begin());
  };
  const std::size_t x = column("x"), y = column("y"), zone = column("zone");
  const auto& rows = table.rows();
  std::vector<double> xyz;
  std::vector<std::int64_t> connectivity, offsets;
  std::vector<std::uint8_t> types;
  constexpr std::uint8_t kVtkLine = 3;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    xyz.insert(xyz.end(), {number(rows[r][x]), number(rows[r][y]), 0.0});
    if (r + 1 < rows.size() && number(rows[r + 1][zone]) == number(rows[r][zone])) {
      connectivity.insert(connectivity.end(), {static_cast<std::int64_t>(r), static_cast<std::int64_t>(r + 1)});
      offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
      types.push_back(kVtkLine);
    }
  }
  VtkXmlDocument document("UnstructuredGrid");
  std::string piece =
      fmt::format("<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n<PointData>\n", rows.size(), types.size());
  for (std::size_t c = 0; c < names.size(); ++c) {
    if (c == x || c == y || !numeric_column(table, c)) continue;
    std::vector<double> values;
    for (const auto& row : rows) values.push_back(number(row[c]));
    piece += document.array(names[c], values);
  }
  piece += "</PointData>\n<Points>\n" + document.array("Points", xyz, 3) + "</Points>\n<Cells>\n" +
           document.array("connectivity", connectivity) + document.array("offsets", offsets) +
           document.array("types", types) + "</Cells>\n</Piece>\n";
  return document.text(piece);
}

}  // namespace hpcontact::io
