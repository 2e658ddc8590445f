// A named array of a VTU file written by io::vtu_text (raw appended binary block), read back as
// doubles, for tests that check what a VTU holds.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <regex>
#include <string>
#include <vector>

namespace hpcontact::testing {

// A named array of the appended block as doubles (from Float64, Int64, Int32, UInt8).
inline std::vector<double> appended_array(const std::string& file, const std::string& name) {
  const std::smatch m = [&] {
    std::smatch found;
    const std::regex element("<DataArray type=\"(\\w+)\" Name=\"" + name + "\"[^>]*offset=\"(\\d+)\"");
    if (!std::regex_search(file, found, element)) ADD_FAILURE() << "no array " << name;
    return found;
  }();
  const std::size_t start = file.find("<AppendedData encoding=\"raw\">\n_") + 31 + std::stoull(m[2]);
  std::uint64_t bytes;
  std::memcpy(&bytes, file.data() + start, 8);
  const char* data = file.data() + start + 8;
  std::vector<double> out;
  const std::string type = m[1];
  const std::size_t size = type == "Int32" ? 4 : type == "UInt8" ? 1 : 8;
  for (std::size_t i = 0; i < bytes / size; ++i) {
    if (type == "Float64") {
      double v;
      std::memcpy(&v, data + 8 * i, 8);
      out.push_back(v);
    } else if (type == "Int64") {
      std::int64_t v;
      std::memcpy(&v, data + 8 * i, 8);
      out.push_back(static_cast<double>(v));
    } else if (type == "UInt8") {
      out.push_back(static_cast<unsigned char>(data[i]));
    } else {
      std::int32_t v;
      std::memcpy(&v, data + 4 * i, 4);
      out.push_back(v);
    }
  }
  return out;
}

}  // namespace hpcontact::testing
