// Shared by tests that read back the CSV files a run wrote: the header and the rows as text, by
// position or by column name, the rows as numbers, and the numeric columns. The one CSV reader of
// the tests.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace hpcontact::testing {

/// Fields joined by commas, as a line of the file.
inline std::string line_of(const std::vector<std::string>& fields) {
  std::string line;
  for (std::size_t k = 0; k < fields.size(); ++k) line += (k == 0 ? "" : ",") + fields[k];
  return line;
}

struct CsvFile {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  ///< without the header

  /// The header as written ("a,b,c").
  std::string header_line() const { return line_of(header); }
  /// Every row as numbers (for files whose cells are all numbers). @throws std::invalid_argument
  /// on a cell that is not a number.
  std::vector<std::vector<double>> numbers() const {
    std::vector<std::vector<double>> out;
    for (const auto& row : rows) {
      auto& values = out.emplace_back();
      for (const auto& cell : row) values.push_back(std::stod(cell));
    }
    return out;
  }
  /// Each row as column name → text.
  std::vector<std::map<std::string, std::string>> records() const {
    std::vector<std::map<std::string, std::string>> out;
    for (const auto& row : rows) {
      auto& record = out.emplace_back();
      for (std::size_t k = 0; k < header.size() && k < row.size(); ++k) record[header[k]] = row[k];
    }
    return out;
  }
  /// Every column whose cells are numbers, by name, but those named in `skipped`.
  std::map<std::string, std::vector<double>> numeric_columns(const std::vector<std::string>& skipped = {}) const {
    std::map<std::string, std::vector<double>> values;
    for (const auto& row : rows)
      for (std::size_t k = 0; k < header.size() && k < row.size(); ++k) {
        char* end = nullptr;
        const double value = std::strtod(row[k].c_str(), &end);
        bool skip = end == row[k].c_str() || *end != '\0';
        for (const auto& name : skipped) skip = skip || header[k] == name;
        if (!skip) values[header[k]].push_back(value);
      }
    return values;
  }
};

/// The file split at commas (no quoting: the files written by hpcontact quote nothing).
inline CsvFile read_csv(const std::filesystem::path& path) {
  std::ifstream in(path);
  CsvFile file;
  bool first = true;
  for (std::string line; std::getline(in, line); first = false) {
    std::vector<std::string> fields;
    std::stringstream stream(line);
    for (std::string field; std::getline(stream, field, ',');) fields.push_back(field);
    if (first)
      file.header = std::move(fields);
    else
      file.rows.push_back(std::move(fields));
  }
  return file;
}

}  // namespace hpcontact::testing
