// CsvTable.
#include "io/csv_writer.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace hpcontact::io {

std::string format_full_precision(double value) { return fmt::format("{:.17g}", value); }

namespace {

/// RFC 4180: a field with a comma, quote or line break is quoted, its quotes doubled.
std::string quoted_if_needed(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

CsvTable::CsvTable(std::vector<std::string> columns) : columns_(std::move(columns)) {}

void CsvTable::add_row(std::vector<CsvCell> row) {
  HPC_VERIFY(row.size() == columns_.size(), "CSV row with the wrong number of cells");
  rows_.push_back(std::move(row));
}

std::string CsvTable::to_string() const {
  std::string out;
  for (std::size_t k = 0; k < columns_.size(); ++k) out += (k ? "," : "") + columns_[k];
  return out + '\n' + rows_to_string();
}

std::string CsvTable::rows_to_string() const {
  std::string out;
  for (const auto& row : rows_) {
    for (std::size_t k = 0; k < row.size(); ++k) {
      if (k) out += ',';
      if (const auto* text = std::get_if<std::string>(&row[k]))
        out += quoted_if_needed(*text);
      else if (const auto* number = std::get_if<double>(&row[k]))
        out += format_full_precision(*number);
      else
        out += std::to_string(std::get<long long>(row[k]));
    }
    out += '\n';
  }
  return out;
}

void append_csv_rows(const std::filesystem::path& path, const CsvTable& table) {
  std::string content = table.to_string();
  if (std::filesystem::exists(path)) {
    std::ifstream in(path);
    std::stringstream existing;
    existing << in.rdbuf();
    std::string old = existing.str();
    const std::string header = content.substr(0, content.find('\n') + 1);
    if (old.compare(0, header.size(), header) != 0)
      throw InputError("CSV file '" + path.string() + "' has other columns than " +
                       header.substr(0, header.size() - 1) + ": choose another file");
    if (!old.empty() && old.back() != '\n') old += '\n';
    content = old + content.substr(header.size());
  }
  write_file_atomically(path, content);
}

void CsvTable::write(const std::filesystem::path& path) const { write_file_atomically(path, to_string()); }

}  // namespace hpcontact::io
