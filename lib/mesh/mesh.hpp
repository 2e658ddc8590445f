// Conforming mesh T_h of a 2-D domain of quadrilaterals and triangles (mixed meshes too) with cell
// maps Ψ_T (bilinear / affine, or blended from curved sides) and boundary edges carrying a label
// (from the generator or a Gmsh physical group) and a BoundaryPart.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "mesh/reference_cell.hpp"

namespace hpcontact {
class ByteReader;
class ByteWriter;
}  // namespace hpcontact

namespace hpcontact::mesh {

using Point = Eigen::Vector2d;
class BlendedGeometry;
class EdgeCurve;

/// Which boundary condition an edge carries. Interior edges are `interior`.
enum class BoundaryPart : unsigned char { interior, neumann, dirichlet, contact };

std::string to_string(BoundaryPart part);

/// Local numbering of the reference cells: mesh/reference_cell.hpp.
/// A global edge runs from its lower to its higher global vertex index; edge_sign tells whether
/// the local direction agrees (+1) or not (-1).
class Mesh {
 public:
  /// Cells list their vertices counterclockwise; a triangle has -1 as its fourth entry.
  /// Builds topology and checks validity: every quadrilateral must be strictly convex and every
  /// triangle non-degenerate, both counterclockwise, and every edge shared by at most two cells.
  /// @throws InputError naming `origin` otherwise.
  Mesh(std::vector<Point> vertices, std::vector<std::array<int, 4>> cells, const std::string& origin = "mesh");

  int n_vertices() const { return static_cast<int>(vertices_.size()); }
  int n_cells() const { return static_cast<int>(cells_.size()); }
  int n_edges() const { return static_cast<int>(edges_.size()); }

  const Point& vertex(int v) const { return vertices_[v]; }
  const std::vector<Point>& vertices() const { return vertices_; }
  /// Vertex indices of cell c, counterclockwise (three or four).
  std::span<const int> cell(int c) const { return {cells_[c].data(), cells_[c][3] < 0 ? 3u : 4u}; }
  /// Every cell as given to the constructor (a triangle's fourth entry is -1).
  const std::vector<std::array<int, 4>>& cells() const { return cells_; }
  CellType cell_type(int c) const { return cells_[c][3] < 0 ? CellType::triangle : CellType::quadrilateral; }
  /// Number of vertices (= of edges) of cell c.
  int cell_size(int c) const { return cells_[c][3] < 0 ? 3 : 4; }
  bool has_triangles() const;
  /// Global vertex indices of edge e, lower index first.
  const std::array<int, 2>& edge(int e) const { return edges_[e]; }
  int cell_edge(int c, int local_edge) const { return cell_edges_[c][local_edge]; }
  /// +1 if the local direction of local_edge of cell c agrees with the global edge direction.
  int edge_sign(int c, int local_edge) const { return cell_edge_signs_[c][local_edge]; }
  /// The one or two cells adjacent to edge e (second entry -1 on the boundary; kCellElsewhere on a
  /// part's cut, the first entry being the part's cell).
  const std::array<int, 2>& edge_cells(int e) const { return edge_cells_[e]; }
  /// Local edge index of edge e within cell edge_cells(e)[k].
  int local_edge_of(int e, int k) const;
  bool is_boundary_edge(int e) const { return edge_cells_[e][1] == -1; }
  const std::vector<int>& boundary_edges() const { return boundary_edges_; }

  /// The point of edge e at parameter t ∈ [-1, 1] in the global direction (lower vertex first).
  Point edge_point(int e, double t) const;
  Point edge_midpoint(int e) const { return edge_point(e, 0.0); }
  /// Outward unit normal of boundary edge e at the local edge parameter t of its cell.
  Point boundary_normal(int e, double t) const;
  /// Arc length of edge e (the chord for a straight edge).
  double edge_length(int e) const;

  /// Edge e follows `curve` (t = -1 at edge(e)[0], t = 1 at edge(e)[1]); its cells become
  /// blended (mesh/blended_geometry.hpp). Only on an unrefined mesh.
  /// @throws InputError naming `origin` if the curve's ends miss the edge's vertices (by more than
  /// 1e-8 of its length), a cell's map is no longer invertible (Jacobian determinant ≤ 0), or the
  /// edge belongs to a triangle (curved triangles are not supported).
  void set_edge_curve(int e, std::shared_ptr<const EdgeCurve> curve, const std::string& origin);
  /// The blended map of cell c, or nullptr for a bilinear cell.
  const BlendedGeometry* cell_geometry(int c) const {
    return cell_geometry_.empty() ? nullptr : cell_geometry_[c].get();
  }
  void set_cell_geometry(int c, std::shared_ptr<const BlendedGeometry> geometry);
  bool has_curved_cells() const;
  /// Drops every curve: the polygonal mesh with the same vertices.
  void straighten();

  /// Label of a boundary edge ("bottom", a Gmsh physical name, ...); empty for interior edges.
  /// (Valid until a label new to the mesh is set: the labels live in one growing table.)
  const std::string& edge_label(int e) const { return labels_[edge_label_index_[e]]; }
  /// @throws InputError if the mesh would carry more than 65 535 distinct labels.
  void set_edge_label(int e, const std::string& label);
  BoundaryPart edge_part(int e) const { return edge_parts_[e]; }
  void set_edge_part(int e, BoundaryPart part);
  /// Whether some boundary edge belongs to `part`.
  bool has_part(BoundaryPart part) const;

  /// Mesh size h: the longest edge (2/n for the n × n paper square).
  double longest_edge() const;

  /// The neighbour across a cut edge of a part (extract): a cell of the whole mesh the part does not hold.
  static constexpr int kCellElsewhere = -2;
  /// The part of this mesh made of `cells` (ascending, distinct): what a rank of a distributed run
  /// needs of the mesh. Its cells, vertices and edges are numbered in the order of their indices in
  /// this mesh, so edge directions and signs are the same; labels, boundary parts and curved cells are
  /// carried over. An edge shared with a cell outside the part is a cut: not a boundary edge, its
  /// second neighbour kCellElsewhere. @pre this mesh is not itself a part. A part is not refined,
  /// graded, moved or given curves (the whole mesh is, before): those refuse it. On a cut edge the
  /// part's cell comes first, so a curved cut edge's points come from that cell's map (the same
  /// curve as its neighbour's, to round-off).
  Mesh extract(const std::vector<int>& cells) const;
  /// Whether this mesh is a part of another (extract).
  bool is_part() const { return !global_cells_.empty(); }
  /// A part's cell, vertex or edge as numbered in the whole mesh (the identity on a whole mesh).
  int global_cell(int c) const { return global_cells_.empty() ? c : global_cells_[c]; }
  int global_vertex(int v) const { return global_vertices_.empty() ? v : global_vertices_[v]; }
  int global_edge(int e) const { return global_edges_.empty() ? e : global_edges_[e]; }

  /// The mesh (whole or a part, with its curves and labels) as bytes, and back: the same mesh to
  /// the bit, so that one rank can build a mesh and send it to others (mesh/mesh_bytes.cpp).
  void pack(ByteWriter& out) const;
  static Mesh unpack(ByteReader& in);

  /// Vertex positions may be moved (perturbation, grading) without changing topology.
  /// @throws InputError if a cell becomes invalid, or if the mesh has curved cells.
  void move_vertices(std::vector<Point> new_positions, const std::string& origin);

 private:
  Mesh() = default;  // for extract
  void build_topology(const std::string& origin);
  void check_cells(const std::string& origin) const;

  std::vector<Point> vertices_;
  std::vector<std::array<int, 4>> cells_;
  std::vector<std::array<int, 2>> edges_;
  std::vector<std::array<int, 4>> cell_edges_;
  std::vector<std::array<std::int8_t, 4>> cell_edge_signs_;
  std::vector<std::array<int, 2>> edge_cells_;
  std::vector<int> boundary_edges_;
  // Each edge's label as an index into labels_ (labels_[0] is the empty one): an edge costs two
  // bytes, not a string's 32, and a mesh has only a few labels.
  std::vector<std::string> labels_{""};
  std::vector<std::uint16_t> edge_label_index_;
  std::vector<BoundaryPart> edge_parts_;
  std::vector<std::shared_ptr<const BlendedGeometry>> cell_geometry_;  ///< empty while all cells are bilinear
  /// A part's indices in the whole mesh, each ascending; empty on a whole mesh.
  std::vector<int> global_cells_, global_vertices_, global_edges_;
};

/// The smallest cell size, relative to the extent of the domain, that grading may create. Vertex
/// coordinates carry absolute round-off, so a cell of relative size 1e-12 has its shape only to
/// about 1e-4; measured on the §7 problems, energies on meshes graded to 1e-12 move by 1e-9 …
/// 6e-7, while down to 1e-10 they agree with shallower meshes to 1e-11.
inline constexpr double kFinestRelativeCell = 1e-10;

/// Points as bytes (by coordinates: Eigen's fixed-size types are not trivially copyable in the
/// type system's sense), and back (mesh/mesh_bytes.cpp).
void put_points(ByteWriter& out, const std::vector<Point>& points);
std::vector<Point> get_points(ByteReader& in);

}  // namespace hpcontact::mesh
