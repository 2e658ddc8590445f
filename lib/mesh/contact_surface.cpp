// Flat contact surfaces of solid meshes (square or triangle faces), their multiplier meshes (grids of rectangles or
// triangles) and the clipped overlaps of trace faces and multiplier cells.
#include "mesh/contact_surface.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "core/error.hpp"

namespace hpcontact::mesh {

namespace {

double signed_area(const std::vector<Eigen::Vector2d>& polygon) {
  double twice = 0.0;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const Eigen::Vector2d& a = polygon[k];
    const Eigen::Vector2d& b = polygon[(k + 1) % polygon.size()];
    twice += a(0) * b(1) - a(1) * b(0);
  }
  return 0.5 * twice;
}

/// The outward unit normal of a boundary face at its centre.
Eigen::Vector3d outward_normal(const SolidMesh& mesh, const BoundaryFace& face) {
  if (mesh.is_tetrahedral()) {
    // Away from the vertex opposite the face (local vertex local_face).
    const auto& cell = mesh.cell(face.cell);
    const auto& corners = kTetFaceVertices[face.local_face];
    const SolidPoint& a = mesh.vertex(cell[corners[0]]);
    const Eigen::Vector3d n = (mesh.vertex(cell[corners[1]]) - a).cross(mesh.vertex(cell[corners[2]]) - a).normalized();
    return n.dot(a - mesh.vertex(cell[face.local_face])) > 0.0 ? n : Eigen::Vector3d(-n);
  }
  Eigen::Vector3d xi = Eigen::Vector3d::Zero();
  const int axis = face.local_face / 2;
  const double side = face.local_face % 2 == 0 ? -1.0 : 1.0;
  xi(axis) = side;
  const Eigen::Matrix3d j = mesh.jacobian(face.cell, xi);
  Eigen::Vector3d n = j.col(kHexFaceAxes[face.local_face][0]).cross(j.col(kHexFaceAxes[face.local_face][1]));
  n.normalize();
  return n.dot(side * j.col(axis)) > 0.0 ? n : Eigen::Vector3d(-n);
}

/// The face's vertices in plane coordinates, counterclockwise.
std::vector<Eigen::Vector2d> face_polygon(const FlatContactSurface& surface, const BoundaryFace& face) {
  const SolidMesh& mesh = surface.mesh();
  const auto corners = mesh.local_face_vertices(face.local_face);
  std::vector<Eigen::Vector2d> polygon;
  // (a square's corners are in the tensor order of its axes: around it is 0, 1, 3, 2)
  for (int k : mesh.is_tetrahedral() ? std::vector<int>{0, 1, 2} : std::vector<int>{0, 1, 3, 2})
    polygon.push_back(surface.to_plane(mesh.vertex(mesh.cell(face.cell)[corners[k]])));
  if (signed_area(polygon) < 0.0) std::reverse(polygon.begin(), polygon.end());
  return polygon;
}

/// Items binned by their bounding boxes on a uniform grid of bins × bins over [lo, hi], so that
/// only items whose boxes share a bin are compared (about one item per bin when bins² ≈ items).
class BoxBins {
 public:
  BoxBins(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, std::size_t items)
      : lo_(lo),
        bins_(std::max(1, static_cast<int>(std::sqrt(static_cast<double>(items))))),
        step_((hi - lo) / bins_),
        contents_(static_cast<std::size_t>(bins_ * bins_)) {}
  void add(int item, const Eigen::Vector2d& low, const Eigen::Vector2d& high) {
    for (const int bin : bins_meeting(low, high)) contents_[static_cast<std::size_t>(bin)].push_back(item);
  }
  /// The items in the bins the box [low, high] meets, ascending, each once.
  std::vector<int> near(const Eigen::Vector2d& low, const Eigen::Vector2d& high) const {
    std::vector<int> out;
    for (const int bin : bins_meeting(low, high)) {
      const auto& in_bin = contents_[static_cast<std::size_t>(bin)];
      out.insert(out.end(), in_bin.begin(), in_bin.end());
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }
  const std::vector<std::vector<int>>& contents() const { return contents_; }

 private:
  int bin_along(const Eigen::Vector2d& a, int k) const {
    return std::clamp(static_cast<int>(std::floor((a(k) - lo_(k)) / step_(k))), 0, bins_ - 1);
  }
  std::vector<int> bins_meeting(const Eigen::Vector2d& low, const Eigen::Vector2d& high) const {
    std::vector<int> out;
    for (int j = bin_along(low, 1); j <= bin_along(high, 1); ++j)
      for (int i = bin_along(low, 0); i <= bin_along(high, 0); ++i) out.push_back(i + bins_ * j);
    return out;
  }
  Eigen::Vector2d lo_;
  int bins_;
  Eigen::Vector2d step_;
  std::vector<std::vector<int>> contents_;
};

}  // namespace

FlatContactSurface::FlatContactSurface(const SolidMesh& mesh, const std::vector<std::string>& labels,
                                       const std::string& origin)
    : mesh_(&mesh) {
  for (const auto& face : mesh.boundary_faces())
    if (std::find(labels.begin(), labels.end(), face.label) != labels.end()) faces_.push_back(face);
  if (faces_.empty())
    throw InputError(
        fmt::format("{}: no boundary face is labelled {}: Γ_C is empty", origin, fmt::join(labels, " or ")));
  normal_ = outward_normal(mesh, faces_[0]);
  origin_ = mesh.face_centre(mesh.cell_face(faces_[0].cell, faces_[0].local_face));
  int along = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(normal_(k)) < std::abs(normal_(along)) - 1e-12) along = k;
  e1_ = Eigen::Vector3d::Unit(along) - normal_(along) * normal_;
  e1_.normalize();
  e2_ = normal_.cross(e1_);
  double size = 0.0;
  for (const auto& face : faces_)
    for (int v : mesh.local_face_vertices(face.local_face))
      size = std::max(size, (mesh.vertex(mesh.cell(face.cell)[v]) - origin_).norm());
  bounds_ = {Eigen::Vector2d::Constant(INFINITY), Eigen::Vector2d::Constant(-INFINITY)};
  for (const auto& face : faces_) {
    if (outward_normal(mesh, face).dot(normal_) < 1.0 - 1e-10)
      throw InputError(
          fmt::format("{}: Γ_C is not flat: the normals of its faces differ (3-D contact surfaces are "
                      "planar for now)",
                      origin));
    for (int v : mesh.local_face_vertices(face.local_face)) {
      const SolidPoint& x = mesh.vertex(mesh.cell(face.cell)[v]);
      if (std::abs(normal_.dot(x - origin_)) > 1e-10 * size)
        throw InputError(
            fmt::format("{}: Γ_C is not flat: vertex ({}, {}, {}) lies {:.3g} off the plane of its "
                        "first face (3-D contact surfaces are planar for now)",
                        origin, x(0), x(1), x(2), normal_.dot(x - origin_)));
      const Eigen::Vector2d a = to_plane(x);
      bounds_[0] = bounds_[0].cwiseMin(a);
      bounds_[1] = bounds_[1].cwiseMax(a);
    }
    area_ += signed_area(face_polygon(*this, face));
  }
}

Eigen::Vector2d FlatContactSurface::to_plane(const SolidPoint& x) const {
  return {e1_.dot(x - origin_), e2_.dot(x - origin_)};
}

SolidPoint FlatContactSurface::from_plane(const Eigen::Vector2d& a) const { return origin_ + a(0) * e1_ + a(1) * e2_; }

bool FlatContactSurface::is_rectangle() const {
  const Eigen::Vector2d extent = bounds_[1] - bounds_[0];
  return std::abs(area_ - extent.prod()) <= 1e-10 * extent.prod();
}

std::vector<Eigen::Vector2d> clip_to_rectangle(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& lo,
                                               const Eigen::Vector2d& hi) {
  // Sutherland–Hodgman: clip against the four half-planes in turn.
  std::vector<Eigen::Vector2d> current = polygon;
  for (int side = 0; side < 4 && !current.empty(); ++side) {
    const int axis = side / 2;
    const double bound = side % 2 == 0 ? lo(axis) : hi(axis), direction = side % 2 == 0 ? 1.0 : -1.0;
    const auto inside = [&](const Eigen::Vector2d& x) { return direction * (x(axis) - bound) >= 0.0; };
    std::vector<Eigen::Vector2d> next;
    for (std::size_t k = 0; k < current.size(); ++k) {
      const Eigen::Vector2d& a = current[k];
      const Eigen::Vector2d& b = current[(k + 1) % current.size()];
      if (inside(a)) next.push_back(a);
      if (inside(a) != inside(b)) {
        const double t = (bound - a(axis)) / (b(axis) - a(axis));
        Eigen::Vector2d crossing = a + t * (b - a);
        crossing(axis) = bound;  // exactly on the side, so that neighbouring cells share it
        next.push_back(crossing);
      }
    }
    current = std::move(next);
  }
  return current;
}

std::vector<Eigen::Vector2d> clip_convex(const std::vector<Eigen::Vector2d>& subject,
                                         const std::vector<Eigen::Vector2d>& clip) {
  std::vector<Eigen::Vector2d> current = subject;
  for (std::size_t side = 0; side < clip.size() && !current.empty(); ++side) {
    const Eigen::Vector2d& from = clip[side];
    const Eigen::Vector2d edge = clip[(side + 1) % clip.size()] - from;
    // (left of the side, or on it: inside a counterclockwise polygon)
    const auto height = [&](const Eigen::Vector2d& x) {
      const Eigen::Vector2d d = x - from;
      return edge(0) * d(1) - edge(1) * d(0);
    };
    std::vector<Eigen::Vector2d> next;
    for (std::size_t k = 0; k < current.size(); ++k) {
      const Eigen::Vector2d& a = current[k];
      const Eigen::Vector2d& b = current[(k + 1) % current.size()];
      const double ha = height(a), hb = height(b);
      if (ha >= 0.0) next.push_back(a);
      if ((ha >= 0.0) != (hb >= 0.0)) next.push_back(a + ha / (ha - hb) * (b - a));
    }
    current = std::move(next);
  }
  return current;
}

SurfaceMultiplierMesh::SurfaceMultiplierMesh(const FlatContactSurface& surface, std::array<int, 2> cells,
                                             const std::string& origin)
    : surface_(&surface), cells_(cells) {
  for (int k = 0; k < 2; ++k)
    if (cells_[k] < 1)
      throw InputError(
          fmt::format("{}: T_{{C,H}} has {} cells along its axis {}; at least 1", origin, cells_[k], k + 1));
  if (!surface.is_rectangle())
    throw InputError(
        fmt::format("{}: Γ_C (area {:.6g}) is not the rectangle that bounds it (area {:.6g}): a "
                    "grid T_{{C,H}} needs a rectangular Γ_C: give its triangles in contact_mesh.mesh",
                    origin, surface.area(), (surface.bounds()[1] - surface.bounds()[0]).prod()));
  overlaps_ = clip_faces();
}

SurfaceMultiplierMesh::SurfaceMultiplierMesh(const FlatContactSurface& surface, const std::vector<SolidPoint>& vertices,
                                             const std::vector<std::array<int, 3>>& triangles,
                                             const std::string& origin)
    : surface_(&surface), shape_(CellShape::triangle) {
  if (triangles.empty()) throw InputError(origin + ": T_{C,H} has no triangles");
  const auto& [lo, hi] = surface.bounds();
  const double size = (hi - lo).norm(), scale = (hi - lo).prod();
  for (const SolidPoint& x : vertices) {
    const double off = surface.normal().dot(x - surface.from_plane(surface.to_plane(x)));
    if (!(std::abs(off) <= 1e-9 * size))  // (a NaN coordinate fails too)
      throw InputError(fmt::format("{}: vertex ({}, {}, {}) of T_{{C,H}} lies {:.3g} off the plane of Γ_C", origin,
                                   x(0), x(1), x(2), off));
  }
  double area = 0.0;
  for (const auto& triangle : triangles) {
    std::array<Eigen::Vector2d, 3> corners;
    for (int k = 0; k < 3; ++k) corners[k] = surface.to_plane(vertices.at(static_cast<std::size_t>(triangle[k])));
    double twice = (corners[1] - corners[0])(0) * (corners[2] - corners[0])(1) -
                   (corners[1] - corners[0])(1) * (corners[2] - corners[0])(0);
    if (!(std::abs(twice) > 1e-14 * scale))
      throw InputError(fmt::format("{}: triangle {} of T_{{C,H}} has no area", origin, triangles_.size()));
    if (twice < 0.0) std::swap(corners[1], corners[2]);
    area += 0.5 * std::abs(twice);
    triangles_.push_back(corners);
  }
  overlaps_ = clip_triangles();
  double covered = 0.0;
  for (const auto& overlap : overlaps_) covered += signed_area(overlap.polygon);
  // Inside Γ_C (covered = area) and nowhere twice (no two triangles overlap), with the area of Γ_C:
  // then they cover it once.
  if (!(std::abs(area - surface.area()) <= 1e-9 * surface.area()) ||
      !(std::abs(covered - surface.area()) <= 1e-9 * surface.area()))
    throw InputError(
        fmt::format("{}: the triangles of T_{{C,H}} do not cover Γ_C once: their area is {:.10g}, the part "
                    "of Γ_C they cover {:.10g}, Γ_C's area {:.10g}",
                    origin, area, covered, surface.area()));
  if (const auto pair = overlapping_triangles(1e-9 * surface.area()))
    throw InputError(fmt::format("{}: triangles {} and {} of T_{{C,H}} overlap: they do not cover Γ_C once", origin,
                                 pair->first, pair->second));
}

std::optional<std::pair<int, int>> SurfaceMultiplierMesh::overlapping_triangles(double tolerance) const {
  // The triangles binned by their bounding boxes, about one per bin: only neighbours are clipped.
  BoxBins bins(surface_->bounds()[0], surface_->bounds()[1], static_cast<std::size_t>(n_cells()));
  for (int c = 0; c < n_cells(); ++c) {
    const auto bounds = cell_bounds(c);
    bins.add(c, bounds[0], bounds[1]);
  }
  for (const auto& in_bin : bins.contents())
    for (std::size_t a = 0; a < in_bin.size(); ++a)
      for (std::size_t b = a + 1; b < in_bin.size(); ++b) {
        const auto piece = clip_convex(cell_polygon(in_bin[a]), cell_polygon(in_bin[b]));
        if (piece.size() >= 3 && signed_area(piece) > tolerance) return std::pair(in_bin[a], in_bin[b]);
      }
  return std::nullopt;
}

const std::array<int, 2>& SurfaceMultiplierMesh::cells_per_axis() const {
  HPC_VERIFY(is_grid(), "cells_per_axis of a grid T_{C,H}");
  return cells_;
}

std::vector<Eigen::Vector2d> SurfaceMultiplierMesh::cell_polygon(int c) const {
  if (!is_grid()) {
    const auto& t = triangles_[static_cast<std::size_t>(c)];
    return {t[0], t[1], t[2]};
  }
  const auto [lo, hi] = cell_bounds(c);
  return {lo, Eigen::Vector2d(hi(0), lo(1)), hi, Eigen::Vector2d(lo(0), hi(1))};
}

std::array<Eigen::Vector2d, 2> SurfaceMultiplierMesh::cell_bounds(int c) const {
  if (!is_grid()) {
    const auto& t = triangles_[static_cast<std::size_t>(c)];
    return {t[0].cwiseMin(t[1]).cwiseMin(t[2]), t[0].cwiseMax(t[1]).cwiseMax(t[2])};
  }
  const Eigen::Vector2d lo = surface_->bounds()[0], hi = surface_->bounds()[1];
  const int i = c % cells_[0], j = c / cells_[0];
  const Eigen::Vector2d step((hi(0) - lo(0)) / cells_[0], (hi(1) - lo(1)) / cells_[1]);
  // The last cell ends exactly at the bound (no rounding gap at the far side).
  const Eigen::Vector2d lower(lo(0) + i * step(0), lo(1) + j * step(1));
  const Eigen::Vector2d upper(i + 1 == cells_[0] ? hi(0) : lo(0) + (i + 1) * step(0),
                              j + 1 == cells_[1] ? hi(1) : lo(1) + (j + 1) * step(1));
  return {lower, upper};
}

std::vector<SurfaceMultiplierMesh::Overlap> SurfaceMultiplierMesh::clip_faces() const {
  const Eigen::Vector2d lo = surface_->bounds()[0], hi = surface_->bounds()[1];  // (lambdas capture them)
  const double scale = (hi - lo).prod();
  std::vector<Overlap> out;
  const auto& faces = surface_->faces();
  for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
    const std::vector<Eigen::Vector2d> polygon = face_polygon(*surface_, faces[f]);
    Eigen::Vector2d low = polygon[0], high = polygon[0];
    for (const auto& x : polygon) {
      low = low.cwiseMin(x);
      high = high.cwiseMax(x);
    }
    // The range of grid cells the face's bounding box meets.
    std::array<int, 2> first{}, last{};
    for (int k = 0; k < 2; ++k) {
      const double step = (hi(k) - lo(k)) / cells_[k];
      first[k] = std::clamp(static_cast<int>(std::floor((low(k) - lo(k)) / step)) - 1, 0, cells_[k] - 1);
      last[k] = std::clamp(static_cast<int>(std::floor((high(k) - lo(k)) / step)) + 1, 0, cells_[k] - 1);
    }
    for (int j = first[1]; j <= last[1]; ++j)
      for (int i = first[0]; i <= last[0]; ++i) {
        const int c = i + cells_[0] * j;
        const auto [cell_lo, cell_hi] = cell_bounds(c);
        std::vector<Eigen::Vector2d> piece = clip_to_rectangle(polygon, cell_lo, cell_hi);
        if (piece.size() < 3 || signed_area(piece) <= 1e-14 * scale) continue;
        out.push_back({f, c, std::move(piece)});
      }
  }
  return out;
}

std::vector<SurfaceMultiplierMesh::Overlap> SurfaceMultiplierMesh::clip_triangles() const {
  // The faces binned by their bounding boxes on a grid of about one face per bin, so that each
  // triangle is clipped only against the faces near it.
  const Eigen::Vector2d lo = surface_->bounds()[0], hi = surface_->bounds()[1];
  const auto& faces = surface_->faces();
  BoxBins bins(lo, hi, faces.size());
  std::vector<std::vector<Eigen::Vector2d>> polygons;
  for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
    polygons.push_back(face_polygon(*surface_, faces[f]));
    Eigen::Vector2d low = polygons.back()[0], high = low;
    for (const auto& x : polygons.back()) {
      low = low.cwiseMin(x);
      high = high.cwiseMax(x);
    }
    bins.add(f, low, high);
  }
  const double scale = (hi - lo).prod();
  std::vector<Overlap> out;
  for (int c = 0; c < n_cells(); ++c) {
    const auto bounds = cell_bounds(c);
    for (const int f : bins.near(bounds[0], bounds[1])) {
      std::vector<Eigen::Vector2d> piece = clip_convex(cell_polygon(c), polygons[static_cast<std::size_t>(f)]);
      if (piece.size() < 3 || signed_area(piece) <= 1e-14 * scale) continue;
      out.push_back({f, c, std::move(piece)});
    }
  }
  std::sort(out.begin(), out.end(),
            [](const Overlap& a, const Overlap& b) { return std::pair(a.face, a.cell) < std::pair(b.face, b.cell); });
  return out;
}

}  // namespace hpcontact::mesh
