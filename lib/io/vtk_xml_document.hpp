// VTK XML files (UnstructuredGrid, Collection) with their arrays appended as raw binary
// (header_type UInt64, little-endian): the XML stays readable, the numbers stay exact and small.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace hpcontact::io {

class VtkXmlDocument {
 public:
  /// @param type the dataset type, "UnstructuredGrid".
  explicit VtkXmlDocument(std::string type);

  /// The <DataArray> element of an array whose values go into the appended block.
  std::string array(const std::string& name, std::span<const double> values, int components = 1);
  std::string array(const std::string& name, std::span<const std::int64_t> values);
  std::string array(const std::string& name, std::span<const std::int32_t> values);
  std::string array(const std::string& name, std::span<const std::uint8_t> values);

  /// The whole file: `pieces` (the <Piece> elements, which use the arrays above) inside the
  /// dataset element, then the appended block.
  std::string text(const std::string& pieces) const;

 private:
  std::string element(const std::string& type_name, const std::string& name, int components, const void* bytes,
                      std::size_t size);
  std::string type_;
  std::string appended_;
};

/// A time series of files for ParaView: a PVD collection of (time, file relative to the PVD).
struct PvdEntry {
  double time;
  std::string file;
};
std::string pvd_text(const std::vector<PvdEntry>& entries);

}  // namespace hpcontact::io
