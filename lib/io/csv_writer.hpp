// CSV tables with a header row, comma separator and full-precision numbers (%.17g).
#pragma once

#include <filesystem>
#include <string>
#include <variant>
#include <vector>

namespace hpcontact::io {

using CsvCell = std::variant<std::string, double, long long>;

class CsvTable {
 public:
  explicit CsvTable(std::vector<std::string> columns);
  /// @pre row.size() == number of columns.
  void add_row(std::vector<CsvCell> row);
  const std::vector<std::string>& columns() const { return columns_; }
  std::size_t n_rows() const { return rows_.size(); }
  const std::vector<std::vector<CsvCell>>& rows() const { return rows_; }
  /// The header line and the rows.
  std::string to_string() const;
  /// The rows alone, for appending to a file that has the header.
  std::string rows_to_string() const;
  /// Writes the table atomically.
  void write(const std::filesystem::path& path) const;

 private:
  std::vector<std::string> columns_;
  std::vector<std::vector<CsvCell>> rows_;
};

/// Appends the rows of `table` to the CSV file at `path` (created with a header if absent). The
/// file is rewritten atomically. @throws InputError if its header differs from table's columns.
void append_csv_rows(const std::filesystem::path& path, const CsvTable& table);

/// Formats a double with 17 significant digits, so that reading it back gives the same value.
std::string format_full_precision(double value);

}  // namespace hpcontact::io
