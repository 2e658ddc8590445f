// Triangles of a Gmsh surface mesh, with their nodes' three coordinates.
#include "mesh/gmsh_surface.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <unordered_map>

#include "core/error.hpp"
#include "mesh/gmsh_api.hpp"

namespace hpcontact::mesh {

SurfaceTriangles read_gmsh_surface_triangles(const std::string& path, std::optional<double> mesh_size) {
  errno = 0;
  if (!std::ifstream(path)) throw InputError(describe_io_failure("cannot open the Gmsh mesh file", path));
  const bool geometry = std::filesystem::path(path).extension() == ".geo";
  if (mesh_size && !geometry)
    throw InputError(path + ": a mesh size applies to Gmsh geometry files (.geo) only, not to a mesh file");
  gmsh_api::Session gmsh;
  gmsh.open(path);
  if (geometry) gmsh.generate(path, mesh_size, false);
  if (gmsh.dimension() < 2) throw InputError(path + ": holds no 2-D mesh (no triangles for T_{C,H})");
  std::vector<std::size_t> tags;
  std::vector<double> coordinates;
  gmsh.nodes(tags, coordinates);
  std::unordered_map<std::size_t, std::size_t> position;  // node tag → index into tags
  for (std::size_t k = 0; k < tags.size(); ++k) position[tags[k]] = k;
  // (only the triangles' corners become vertices: edge and inner nodes of high-order cells do not)
  std::unordered_map<std::size_t, int> index_of;
  SurfaceTriangles out;
  const auto vertex = [&](std::size_t tag) {
    const auto [it, added] = index_of.try_emplace(tag, static_cast<int>(out.vertices.size()));
    if (added) {
      const auto found = position.find(tag);
      if (found == position.end())
        throw InputError(fmt::format("{}: a triangle names node {}, which has no coordinates", path, tag));
      const std::size_t k = found->second;
      out.vertices.emplace_back(coordinates[3 * k], coordinates[3 * k + 1], coordinates[3 * k + 2]);
    }
    return it->second;
  };
  const auto blocks = gmsh.elements(2);
  for (std::size_t t = 0; t < blocks.types.size(); ++t) {
    const auto [name, order] = gmsh.element_type(blocks.types[t]);
    if (!name.starts_with("Triangle"))
      throw InputError(
          fmt::format("{}: T_{{C,H}} takes triangles only; found type {} ({}): mesh the surface without "
                      "recombination",
                      path, blocks.types[t], name));
    const auto& nodes = blocks.nodes[t];
    const std::size_t per_element = nodes.size() / blocks.tags[t].size();
    for (std::size_t e = 0; e < blocks.tags[t].size(); ++e)
      out.triangles.push_back(
          {vertex(nodes[per_element * e]), vertex(nodes[per_element * e + 1]), vertex(nodes[per_element * e + 2])});
  }
  if (out.triangles.empty()) throw InputError(path + ": holds no triangles for T_{C,H}");
  return out;
}

}  // namespace hpcontact::mesh
