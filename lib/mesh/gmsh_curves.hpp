// Curved edges of a mesh read through Gmsh: from the exact geometry of a .geo file (its curves'
// parametrizations, sampled through the Gmsh API) or from the edge nodes of high-order cells.
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "mesh/gmsh_api.hpp"
#include "mesh/mesh.hpp"

namespace hpcontact::mesh {

/// The nodes along one edge of a Gmsh element, from one end to the other (both ends included):
/// 2 for a first-order element, q + 1 for order q.
using GmshEdgeNodes = std::vector<std::size_t>;

/// Every edge of T_h lying on a curve of the geometry that is not a straight line follows that
/// curve exactly (an EdgeCurve interpolating Gmsh's parametrization, degree 16 … 48 until it
/// reproduces the curve to 1e-13 of the edge's length).
/// @throws InputError naming `path` if a line element of a curve is not an edge of T_h or an edge
///         crosses the seam of a closed curve's parametrization.
void curve_edges_from_geometry(const gmsh_api::Session& gmsh, const std::string& path,
                               const std::unordered_map<std::size_t, int>& vertex_of,
                               const std::unordered_map<std::size_t, Point>& position, Mesh& mesh);

/// Every edge whose high-order nodes leave its chord (by more than 1e-12 of its length) follows
/// the polynomial through them (equally spaced in the edge's parameter, as Gmsh places them).
void curve_edges_from_nodes(const std::vector<GmshEdgeNodes>& edges, const std::string& path,
                            const std::unordered_map<std::size_t, int>& vertex_of,
                            const std::unordered_map<std::size_t, Point>& position, Mesh& mesh);

}  // namespace hpcontact::mesh
