// The two reference cells of a mesh, the square [-1,1]² and the triangle with vertices (-1,-1),
// (1,-1), (-1,1): their local vertex and edge numbering, edge parametrizations and point tests,
// so that every cell-type-dependent fact lives in one place.
#pragma once

#include <Eigen/Core>
#include <array>

namespace hpcontact::mesh {

enum class CellType : unsigned char { quadrilateral, triangle };

/// The cells a mesh generator makes (the built-in rectangle, Gmsh from a .geo): quadrilaterals,
/// or triangles (the rectangle's cells cut along their diagonal); the built-in box's hexahedra
/// (`quadrilaterals`, the default) or tetrahedra (each hexahedron cut into six).
enum class GeneratedCells : unsigned char { quadrilaterals, triangles, tetrahedra };

/// Local numbering, both counterclockwise:
///   square    vertices 0:(-1,-1) 1:(1,-1) 2:(1,1) 3:(-1,1)
///             edges    0: v0→v1 (η=-1)  1: v1→v2 (ξ=1)  2: v3→v2 (η=1)  3: v0→v3 (ξ=-1)
///   triangle  vertices 0:(-1,-1) 1:(1,-1) 2:(-1,1)
///             edges    0: v0→v1 (η=-1)  1: v1→v2 (ξ+η=0)  2: v0→v2 (ξ=-1)
/// Each local edge is parametrized by t ∈ [-1,1], affinely, in the direction given.
int cell_vertex_count(CellType type);

/// Local (start, end) vertices of a local edge, in its direction.
std::array<int, 2> local_edge_vertices(CellType type, int local_edge);

/// The reference point of a local edge at its parameter t.
Eigen::Vector2d local_edge_point(CellType type, int local_edge, double t);

/// d(reference point)/dt along a local edge (constant).
Eigen::Vector2d local_edge_direction(CellType type, int local_edge);

/// Whether a local edge's direction runs counterclockwise around the cell (then the outward
/// normal is the tangent turned clockwise).
bool local_edge_counterclockwise(CellType type, int local_edge);

/// The reference cell's vertex v.
Eigen::Vector2d reference_vertex(CellType type, int v);

/// The centroid of the reference cell.
Eigen::Vector2d reference_centre(CellType type);

/// Whether a reference point lies in the reference cell, within `tolerance`.
bool reference_contains(CellType type, const Eigen::Vector2d& point, double tolerance);

/// The nearest point of the reference cell (for points within round-off of it).
Eigen::Vector2d clamp_to_reference(CellType type, const Eigen::Vector2d& point);

}  // namespace hpcontact::mesh
