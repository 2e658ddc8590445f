// Structured n_x × n_y quadrilateral meshes of rectangles, optionally perturbed, and the
// assignment of boundary parts Γ_D, Γ_C, Γ_N to boundary edges.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace hpcontact::mesh {

struct Rectangle {
  double x_min = -1.0, x_max = 1.0, y_min = -1.0, y_max = 1.0;
};

/// Uniform n_x × n_y mesh of the rectangle. Boundary edges are labelled "bottom", "right",
/// "top", "left"; all boundary parts start as Neumann.
/// @throws InputError if n_x, n_y < 1 or the rectangle is empty.
Mesh make_rectangle_mesh(const Rectangle& rectangle, int n_x, int n_y);

/// Tensor-product mesh with the given x and y nodes (each strictly increasing, at least two);
/// labels as make_rectangle_mesh. @throws InputError naming `origin` otherwise.
Mesh make_tensor_mesh(const std::vector<double>& x_nodes, const std::vector<double>& y_nodes,
                      const std::string& origin = "tensor mesh");

/// n uniform cells on [a, b], geometrically refined towards each coordinate in `points`: the
/// nearest node moves onto the point, and each of its two neighbouring cells gets `layers` extra
/// nodes at distances size · ratio^k (k = 1..layers) from it, so that cell sizes shrink by `ratio`
/// towards the point (the geometric meshes of hp-FEM). n + (layers per side) cells in all.
/// Coordinates in `snapped_only` also get a node (the nearest moves onto them) but no layers:
/// the points that grade_towards_vertices refines locally; errors about them name
/// `snapped_origin` (default `origin`). Equal coordinates share their node.
/// @throws InputError if a point lies outside [a, b], two points share a node, or snapping
/// would leave a cell thinner than h/4.
std::vector<double> graded_nodes(double a, double b, int n, const std::vector<double>& points, double ratio, int layers,
                                 const std::string& origin, const std::vector<double>& snapped_only = {},
                                 const std::string& snapped_origin = "");

/// Moves every interior vertex by a uniformly random offset of at most `amplitude` times the
/// smallest adjacent edge length in each coordinate (deterministic for a given seed).
/// amplitude < 0.25 keeps every cell convex.
void perturb_interior_vertices(Mesh& mesh, double amplitude, std::uint32_t seed);

/// Sets the part of every boundary edge whose midpoint satisfies `contains`; later calls
/// override earlier ones. Returns the number of edges set.
int assign_boundary_part(Mesh& mesh, BoundaryPart part, const std::function<bool(const Point&)>& contains);

/// Sets parts by edge label (e.g. Gmsh physical group names). Labels not in the map keep
/// their part. Returns the number of edges set.
int assign_boundary_parts_by_label(Mesh& mesh, const std::map<std::string, BoundaryPart>& part_of_label);

/// The geometry of the paper's §7: Ω = (-1,1)², Γ_C the bottom edge, Γ_D the top edge and the
/// upper half {1} × [0,1] of the right edge, Γ_N the rest. n × n cells, h = 2/n.
/// @throws InputError if n is odd (then (1,0), where Γ_D ends, would not be a vertex).
Mesh make_paper_square_mesh(int n);

/// Marks Γ_C and Γ_D of the paper's §7 on a mesh of (-1,1)².
void assign_paper_boundary_parts(Mesh& mesh);

}  // namespace hpcontact::mesh
