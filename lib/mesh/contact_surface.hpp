// A flat contact surface Γ_C of a solid mesh (the boundary faces of some labels, squares or triangles, lying in
// one plane) in in-plane coordinates, and the multiplier mesh T_{C,H} on it, independent of the
// trace faces: a structured grid of rectangles or a mesh of triangles, with each cell's overlaps
// with the trace faces found by polygon clipping (Sutherland–Hodgman), where the couplings are
// integrated.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mesh/solid_mesh.hpp"

namespace hpcontact::mesh {

/// Γ_C: the boundary faces labelled with one of `labels`, all in one plane.
class FlatContactSurface {
 public:
  /// @throws InputError naming `origin` if no boundary face has such a label, or the faces do not
  /// lie in one plane (to 1e-10 of the surface's size).
  FlatContactSurface(const SolidMesh& mesh, const std::vector<std::string>& labels, const std::string& origin);

  const SolidMesh& mesh() const { return *mesh_; }
  /// The boundary faces of Γ_C (entries of mesh().boundary_faces()).
  const std::vector<BoundaryFace>& faces() const { return faces_; }
  /// The outward unit normal n of Γ_C.
  const Eigen::Vector3d& normal() const { return normal_; }
  /// The in-plane axes e_1 (k = 0) and e_2 (k = 1) (below).
  const Eigen::Vector3d& axis(int k) const { return k == 0 ? e1_ : e2_; }
  /// In-plane coordinates: x = origin + a e_1 + b e_2 (e_1, e_2, n a right-handed orthonormal
  /// frame; e_1 along the coordinate axis most nearly in the plane, the first one on a tie).
  Eigen::Vector2d to_plane(const SolidPoint& x) const;
  SolidPoint from_plane(const Eigen::Vector2d& a) const;
  /// The bounding rectangle of Γ_C in plane coordinates: (lower corner, upper corner).
  const std::array<Eigen::Vector2d, 2>& bounds() const { return bounds_; }
  /// The area of Γ_C (sum of its faces' areas).
  double area() const { return area_; }
  /// Whether Γ_C is exactly its bounding rectangle (to 1e-10 in area).
  bool is_rectangle() const;

 private:
  const SolidMesh* mesh_;
  std::vector<BoundaryFace> faces_;
  Eigen::Vector3d normal_, origin_, e1_, e2_;
  std::array<Eigen::Vector2d, 2> bounds_;
  double area_ = 0.0;
};

/// The convex polygon (counterclockwise vertices) common to a convex counterclockwise polygon and
/// an axis-aligned rectangle [lo, hi]; empty where they do not overlap in area.
std::vector<Eigen::Vector2d> clip_to_rectangle(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& lo,
                                               const Eigen::Vector2d& hi);

/// The convex polygon common to two convex counterclockwise polygons (Sutherland–Hodgman: `subject`
/// clipped by each side of `clip` in turn); empty where they do not overlap in area.
std::vector<Eigen::Vector2d> clip_convex(const std::vector<Eigen::Vector2d>& subject,
                                         const std::vector<Eigen::Vector2d>& clip);

/// T_{C,H}: either an m_1 × m_2 grid of equal rectangles over the bounding rectangle of Γ_C, cell
/// (i, j) = i + m_1 j (Γ_C must be that rectangle), or a mesh of triangles covering Γ_C (any
/// shape of Γ_C; from a Gmsh surface mesh).
class SurfaceMultiplierMesh {
 public:
  enum class CellShape { rectangle, triangle };

  /// The grid. @throws InputError naming `origin` if m_1 or m_2 < 1 or Γ_C is not a rectangle.
  SurfaceMultiplierMesh(const FlatContactSurface& surface, std::array<int, 2> cells, const std::string& origin);
  /// Triangles (vertex indices into `vertices`, points in space on Γ_C's plane; either
  /// orientation). @throws InputError naming `origin` if a vertex lies off the plane of Γ_C (by
  /// more than 1e-9 of Γ_C's size), a triangle is degenerate, or the triangles do not cover Γ_C
  /// once (their area, and their overlaps' area with Γ_C, equal to Γ_C's to 1e-9 relative).
  SurfaceMultiplierMesh(const FlatContactSurface& surface, const std::vector<SolidPoint>& vertices,
                        const std::vector<std::array<int, 3>>& triangles, const std::string& origin);

  const FlatContactSurface& surface() const { return *surface_; }
  CellShape shape() const { return shape_; }
  bool is_grid() const { return shape_ == CellShape::rectangle; }
  int n_cells() const { return is_grid() ? cells_[0] * cells_[1] : static_cast<int>(triangles_.size()); }
  /// The grid's cells along Γ_C's two axes (a grid only).
  const std::array<int, 2>& cells_per_axis() const;
  /// Lower and upper corner of cell c's bounding rectangle in plane coordinates (on a grid: the cell).
  std::array<Eigen::Vector2d, 2> cell_bounds(int c) const;
  /// Cell c's corners in plane coordinates, counterclockwise (a rectangle from its lower left
  /// corner; a triangle from its first vertex).
  std::vector<Eigen::Vector2d> cell_polygon(int c) const;

  /// The piece of one trace face inside one cell of T_{C,H}, where trace shapes and multipliers
  /// are both polynomial: the couplings are integrated over these.
  struct Overlap {
    int face = -1;                         ///< index into surface().faces()
    int cell = -1;                         ///< cell of T_{C,H}
    std::vector<Eigen::Vector2d> polygon;  ///< convex, counterclockwise, plane coordinates
  };
  /// Every overlap of positive area (relative 1e-14), by face then cell (clipped once, when the
  /// mesh is built).
  const std::vector<Overlap>& overlaps() const { return overlaps_; }

 private:
  std::vector<Overlap> clip_faces() const;
  std::vector<Overlap> clip_triangles() const;
  /// Two triangles whose common part has an area above `tolerance`, if any.
  std::optional<std::pair<int, int>> overlapping_triangles(double tolerance) const;
  const FlatContactSurface* surface_;
  CellShape shape_ = CellShape::rectangle;
  std::array<int, 2> cells_{};
  std::vector<std::array<Eigen::Vector2d, 3>> triangles_;  ///< counterclockwise, plane coordinates
  std::vector<Overlap> overlaps_;
};

}  // namespace hpcontact::mesh
