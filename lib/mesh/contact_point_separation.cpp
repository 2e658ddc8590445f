// separate_contact_points.
#include "mesh/contact_point_separation.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "mesh/blended_geometry.hpp"
#include "mesh/contact_boundary.hpp"

namespace hpcontact::mesh {

namespace {

// The arc lengths to make vertices inside the trace edge [begin, end]: the points inside it and a
// midpoint between any two consecutive points of the edge, its ends included. Empty where the edge
// needs no cut (no point inside, and not both ends points).
std::vector<double> cuts_of_edge(double begin, double end, const std::vector<double>& points, double tolerance) {
  std::vector<double> on_edge;  // the points of the closed edge, in order
  for (double s : points)
    if (s > begin - tolerance && s < end + tolerance) on_edge.push_back(std::clamp(s, begin, end));
  const bool at_begin = !on_edge.empty() && on_edge.front() - begin <= tolerance;
  const bool at_end = !on_edge.empty() && end - on_edge.back() <= tolerance;
  const std::size_t inside = on_edge.size() - (at_begin ? 1 : 0) - (at_end ? 1 : 0);
  if (inside == 0 && !(at_begin && at_end)) return {};
  std::vector<double> cuts;
  for (std::size_t k = 0; k < on_edge.size(); ++k) {
    if (k > 0) cuts.push_back(0.5 * (on_edge[k - 1] + on_edge[k]));  // a separator
    if (on_edge[k] - begin > tolerance && end - on_edge[k] > tolerance) cuts.push_back(on_edge[k]);
  }
  return cuts;
}

using EdgeKey = std::pair<int, int>;
EdgeKey key_of(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

}  // namespace

std::optional<SeparatedMesh> separate_contact_points(const Mesh& mesh, const std::vector<double>& points) {
  const ContactBoundary contact(mesh);
  const double tolerance = 1e-9 * contact.length();
  std::vector<double> sorted = points;
  std::sort(sorted.begin(), sorted.end());

  std::vector<Point> vertices = mesh.vertices();
  // Per cell to cut: the ring of its vertices a, w_1 … w_k, b (a b its edge on Γ_C, counterclockwise).
  std::map<int, std::vector<int>> ring_of_cell;
  std::map<EdgeKey, int> parent_edge;  // boundary sub-edge -> the edge of the input it lies on
  for (const auto& trace : contact.edges()) {
    const auto cuts = cuts_of_edge(trace.s_begin, trace.s_end, sorted, tolerance);
    if (cuts.empty()) continue;
    if (mesh.cell_geometry(trace.cell) || ring_of_cell.contains(trace.cell)) return std::nullopt;
    const auto cell = mesh.cell(trace.cell);
    const int size = static_cast<int>(cell.size());
    const auto [u, v] = mesh.edge(trace.edge);
    int i = 0;
    while (key_of(cell[i], cell[(i + 1) % size]) != key_of(u, v)) ++i;
    const int a = cell[i], b = cell[(i + 1) % size];
    // s grows from a to b unless a is the end at s_end.
    const bool forward = (mesh.vertex(a) - contact.point_at(trace.s_begin)).norm() <
                         (mesh.vertex(b) - contact.point_at(trace.s_begin)).norm();
    std::vector<int> ring{a};
    for (std::size_t k = 0; k < cuts.size(); ++k) {
      const double s = forward ? cuts[k] : cuts[cuts.size() - 1 - k];
      ring.push_back(static_cast<int>(vertices.size()));
      vertices.push_back(contact.point_at(s));
    }
    ring.push_back(b);
    for (std::size_t k = 0; k + 1 < ring.size(); ++k) parent_edge[key_of(ring[k], ring[k + 1])] = trace.edge;
    // The vertices off the edge follow b counterclockwise.
    for (int k = 2; k < size; ++k) ring.push_back(cell[(i + k) % size]);
    ring_of_cell[trace.cell] = std::move(ring);
  }

  std::vector<std::array<int, 4>> cells;
  std::vector<int> parents;
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (!ring_of_cell.contains(c)) {
      cells.push_back(mesh.cells()[c]);
      parents.push_back(c);
    }
  const int kept = static_cast<int>(cells.size());
  for (const auto& [c, ring] : ring_of_cell) {
    // ring = a, w_1 … w_k, b, then y (and x for a quadrilateral): on-edge points are ring[0 … k + 1].
    const bool triangle = mesh.cell_type(c) == CellType::triangle;
    const int on_edge = static_cast<int>(ring.size()) - (triangle ? 1 : 2);
    const int y = ring[on_edge], x = triangle ? y : ring[on_edge + 1];
    // Triangles a … w_j fan from x, the rest from y; halfway keeps both fans' triangles alike.
    const int j = triangle ? on_edge - 1 : (on_edge - 1) / 2;
    for (int t = 0; t < on_edge - 1; ++t) {
      cells.push_back({ring[t], ring[t + 1], t < j ? x : y, -1});
      parents.push_back(c);
    }
    if (!triangle) {
      cells.push_back({ring[j], y, x, -1});
      parents.push_back(c);
    }
  }
  Mesh out(std::move(vertices), std::move(cells), "extension reference (cells cut at Γ_C's points)");
  for (int c = 0; c < kept; ++c)
    if (const BlendedGeometry* geometry = mesh.cell_geometry(parents[c]))
      out.set_cell_geometry(c, std::make_shared<BlendedGeometry>(*geometry));
  for (const int e : mesh.boundary_edges()) parent_edge.emplace(key_of(mesh.edge(e)[0], mesh.edge(e)[1]), e);
  for (const int e : out.boundary_edges()) {
    const int parent = parent_edge.at(key_of(out.edge(e)[0], out.edge(e)[1]));
    out.set_edge_label(e, mesh.edge_label(parent));
    out.set_edge_part(e, mesh.edge_part(parent));
  }
  return SeparatedMesh{std::move(out), std::move(parents)};
}

}  // namespace hpcontact::mesh
