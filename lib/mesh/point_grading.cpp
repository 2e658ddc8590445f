// Local geometric refinement towards vertices: star replacement by trapezoid layers.
#include "mesh/point_grading.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>

#include "core/error.hpp"

namespace hpcontact::mesh {

int vertex_at(const Mesh& mesh, const Point& point, const std::string& origin) {
  const double tolerance = 1e-9 * mesh.longest_edge();
  for (int v = 0; v < mesh.n_vertices(); ++v)
    if ((mesh.vertex(v) - point).norm() < tolerance) return v;
  throw_bad_input(origin, "grading point", fmt::format("({}, {})", point.x(), point.y()),
                  "must be a vertex of the mesh");
}

namespace {

// The index of the centre whose star (the cells sharing it) holds each cell, or -1.
std::vector<int> stars_of_cells(const Mesh& mesh, const std::vector<int>& centres, const std::string& origin) {
  std::vector<int> star_of(mesh.n_cells(), -1);
  for (std::size_t s = 0; s < centres.size(); ++s) {
    if (centres[s] < 0 || centres[s] >= mesh.n_vertices())
      throw_bad_input(origin, "grading point", std::to_string(centres[s]), "must be a vertex of the mesh");
    for (int c = 0; c < mesh.n_cells(); ++c) {
      const auto& cell = mesh.cell(c);
      if (std::find(cell.begin(), cell.end(), centres[s]) == cell.end()) continue;
      if (star_of[c] >= 0) {
        const auto &a = mesh.vertex(centres[star_of[c]]), &b = mesh.vertex(centres[s]);
        throw_bad_input(origin, "grading points", fmt::format("({}, {}) and ({}, {})", a.x(), a.y(), b.x(), b.y()),
                        "share a cell of the mesh before grading: use more cells");
      }
      star_of[c] = static_cast<int>(s);
    }
  }
  return star_of;
}

// The innermost cells have the star's shortest edge times ratio^layers; below kFinestRelativeCell
// of the domain's extent round-off in the vertex coordinates distorts them.
void check_layer_depth(const Mesh& mesh, const std::vector<int>& star_of, double ratio, int layers,
                       const std::string& origin) {
  const auto& all = mesh.vertices();
  double extent = 0.0, shortest = INFINITY;
  for (const auto& v : all) extent = std::max(extent, (v - all.front()).norm());
  for (int e = 0; e < mesh.n_edges(); ++e)
    for (int c : mesh.edge_cells(e))
      if (c >= 0 && star_of[c] >= 0) shortest = std::min(shortest, mesh.edge_length(e));
  if (std::isfinite(shortest) && shortest * std::pow(ratio, layers) < kFinestRelativeCell * extent)
    throw_bad_input(
        origin, "grading_layers", std::to_string(layers),
        fmt::format("at most {} with grading {}: deeper, the innermost cells ({:.2g} of the domain's extent) would be "
                    "below {:.0e} of it, where round-off in the vertex coordinates distorts them",
                    static_cast<int>(std::floor(std::log(kFinestRelativeCell * extent / shortest) / std::log(ratio))),
                    ratio, shortest * std::pow(ratio, layers) / extent, kFinestRelativeCell));
}

}  // namespace

Mesh grade_towards_vertices(const Mesh& mesh, const std::vector<int>& centres, double ratio, int layers,
                            const std::string& origin, std::vector<int>* parents) {
  HPC_VERIFY(!mesh.is_part(), "a part of a mesh is not refined: its cut edges would become boundary");
  if (!(ratio > 0.0 && ratio < 1.0)) throw_bad_input(origin, "grading", fmt::format("{}", ratio), "must be in (0, 1)");
  if (layers < 0) throw_bad_input(origin, "grading_layers", std::to_string(layers), "must be >= 0");
  if (mesh.has_curved_cells())
    throw InputError(origin + ": grading towards vertices is not available on a mesh with curved cells");
  // 1. Which star each cell belongs to, and whether the layers stay resolvable.
  const std::vector<int> star_of = stars_of_cells(mesh, centres, origin);
  check_layer_depth(mesh, star_of, ratio, layers, origin);
  // 2. Vertices: the input's, then S_k(V) for every (centre, outer vertex V, level k ≥ 1).
  std::vector<Point> vertices = mesh.vertices();
  std::map<std::tuple<int, int, int>, int> scaled;                     // (star, V, k) -> vertex
  std::vector<std::pair<int, int>> ray_of(vertices.size(), {-1, -1});  // new vertex -> (P, V) it lies between
  auto at_level = [&](int star, int v, int k) {
    if (k == 0) return v;
    const auto key = std::make_tuple(star, v, k);
    if (auto found = scaled.find(key); found != scaled.end()) return found->second;
    const Point& centre = mesh.vertex(centres[star]);
    vertices.push_back(centre + std::pow(ratio, k) * (mesh.vertex(v) - centre));
    ray_of.emplace_back(centres[star], v);
    return scaled[key] = static_cast<int>(vertices.size()) - 1;
  };
  // 3. Cells: those outside the stars, then each star cell's layers and centre cell.
  std::vector<std::array<int, 4>> cells;
  std::vector<int> parent;
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (star_of[c] < 0) {
      cells.push_back(mesh.cells()[c]);
      parent.push_back(c);
    }
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const int star = star_of[c];
    if (star < 0) continue;
    const auto cell = mesh.cell(c);
    const int n = mesh.cell_size(c);
    const int i = static_cast<int>(std::find(cell.begin(), cell.end(), centres[star]) - cell.begin());
    // The sides facing the centre are scaled towards it layer by layer; the trapezoids between
    // two levels are quadrilaterals, and the innermost copy of the cell keeps its type.
    std::vector<int> outer;
    for (int k = 1; k < n; ++k) outer.push_back(cell[(i + k) % n]);
    for (std::size_t side = 0; side + 1 < outer.size(); ++side)
      for (int k = 0; k < layers; ++k) {
        const int q = outer[side], r = outer[side + 1];
        cells.push_back(
            {at_level(star, q, k + 1), at_level(star, q, k), at_level(star, r, k), at_level(star, r, k + 1)});
      }
    if (n == 4)
      cells.push_back({centres[star], at_level(star, outer[0], layers), at_level(star, outer[1], layers),
                       at_level(star, outer[2], layers)});
    else
      cells.push_back({centres[star], at_level(star, outer[0], layers), at_level(star, outer[1], layers), -1});
    parent.resize(cells.size(), c);
  }
  if (parents) *parents = std::move(parent);
  Mesh graded(std::move(vertices), std::move(cells), origin);
  // 4. Boundary edges lie on a boundary edge of the input: the same vertices, or on the ray P–V.
  std::map<std::pair<int, int>, int> edge_of;
  for (int e = 0; e < mesh.n_edges(); ++e) edge_of[{mesh.edge(e)[0], mesh.edge(e)[1]}] = e;
  for (int e : graded.boundary_edges()) {
    auto [a, b] = graded.edge(e);
    std::pair<int, int> original{a, b};
    for (int v : {a, b})
      if (v < static_cast<int>(ray_of.size()) && ray_of[v].first >= 0) original = ray_of[v];
    if (original.first > original.second) std::swap(original.first, original.second);
    const int source = edge_of.at(original);
    graded.set_edge_label(e, mesh.edge_label(source));
    graded.set_edge_part(e, mesh.edge_part(source));
  }
  return graded;
}

}  // namespace hpcontact::mesh
