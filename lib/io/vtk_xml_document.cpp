// VtkXmlDocument and the PVD collection.
#include "io/vtk_xml_document.hpp"

#include <fmt/format.h>

#include <bit>
#include <cstring>

#include "io/csv_writer.hpp"

namespace hpcontact::io {

static_assert(std::endian::native == std::endian::little, "the appended VTK data are written as LittleEndian");

VtkXmlDocument::VtkXmlDocument(std::string type) : type_(std::move(type)) {}

std::string VtkXmlDocument::element(const std::string& type_name, const std::string& name, int components,
                                    const void* bytes, std::size_t size) {
  const std::size_t offset = appended_.size();
  const std::uint64_t header = size;
  appended_.append(reinterpret_cast<const char*>(&header), sizeof header);
  appended_.append(static_cast<const char*>(bytes), size);
  return fmt::format(
      "<DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"appended\" offset=\"{}\"/>\n", type_name,
      name, components, offset);
}

std::string VtkXmlDocument::array(const std::string& name, std::span<const double> values, int components) {
  return element("Float64", name, components, values.data(), values.size_bytes());
}
std::string VtkXmlDocument::array(const std::string& name, std::span<const std::int64_t> values) {
  return element("Int64", name, 1, values.data(), values.size_bytes());
}
std::string VtkXmlDocument::array(const std::string& name, std::span<const std::int32_t> values) {
  return element("Int32", name, 1, values.data(), values.size_bytes());
}
std::string VtkXmlDocument::array(const std::string& name, std::span<const std::uint8_t> values) {
  return element("UInt8", name, 1, values.data(), values.size_bytes());
}

std::string VtkXmlDocument::text(const std::string& pieces) const {
  // Readers find the end of the block by the newline before </AppendedData>.
  return fmt::format(
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"{0}\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      "<{0}>\n{1}</{0}>\n<AppendedData encoding=\"raw\">\n_{2}\n</AppendedData>\n</VTKFile>\n",
      type_, pieces, appended_);
}

std::string pvd_text(const std::vector<PvdEntry>& entries) {
  std::string out =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "<Collection>\n";
  for (const auto& entry : entries)
    out += fmt::format("<DataSet timestep=\"{}\" part=\"0\" file=\"{}\"/>\n", format_full_precision(entry.time),
                       entry.file);
  return out + "</Collection>\n</VTKFile>\n";
}

}  // namespace hpcontact::io
