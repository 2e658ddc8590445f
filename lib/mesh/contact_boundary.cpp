// ContactBoundary: chain ordering of Γ_C edges, arc length along curved ones.
#include "mesh/contact_boundary.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "basis/quadrature.hpp"
#include "core/error.hpp"
#include "mesh/cell_map.hpp"

namespace hpcontact::mesh {

/// σ(t) = ∫_{-1}^{t} |dΨ/dt| along a curved local edge, and its inverse.
class EdgeArcLength {
 public:
  EdgeArcLength(const Mesh& mesh, int cell, int local_edge) : map_(mesh, cell), local_edge_(local_edge) {
    panel_start_.push_back(0.0);
    for (int k = 0; k < kPanels; ++k) panel_start_.push_back(panel_start_.back() + integral(panel(k), panel(k + 1)));
  }
  double length() const { return panel_start_.back(); }
  double speed(double t) const { return map_.edge_tangent(local_edge_, t).norm(); }
  double arc(double t) const {
    const int k = std::clamp(static_cast<int>((t + 1.0) / 2.0 * kPanels), 0, kPanels - 1);
    return panel_start_[k] + integral(panel(k), t);
  }
  /// Newton on σ(t) = σ from the affine guess; σ' = speed > 0 and σ is smooth, so it converges
  /// quadratically in a few steps.
  double parameter(double sigma) const {
    double t = 2.0 * sigma / length() - 1.0;
    for (int iteration = 0; iteration < 50; ++iteration) {
      const double step = (arc(t) - sigma) / speed(t);
      t = std::clamp(t - step, -1.0, 1.0);
      if (std::abs(step) < 1e-15) break;
    }
    return t;
  }

 private:
  static constexpr int kPanels = 8;
  static double panel(int k) { return -1.0 + 2.0 * k / kPanels; }
  // 16 Gauss points on a panel of 1/8 of a curve resolved at degree ≤ 24: round-off.
  double integral(double a, double b) const {
    const auto& rule = basis::gauss_legendre(16);
    double sum = 0.0;
    for (std::size_t q = 0; q < rule.points.size(); ++q)
      sum += rule.weights[q] * speed(a + 0.5 * (b - a) * (rule.points[q] + 1.0));
    return 0.5 * (b - a) * sum;
  }

  CellMap map_;
  int local_edge_;
  std::vector<double> panel_start_;
};

double TraceEdge::local_parameter(double s) const {
  if (arc) return arc->parameter(reversed ? s_end - s : s - s_begin);
  const double t = 2.0 * (s - s_begin) / (s_end - s_begin) - 1.0;
  return reversed ? -t : t;
}

namespace {

bool lexicographically_before(const Point& a, const Point& b) {
  return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
}

// The contact edges at each vertex of Γ_C. @throws InputError if Γ_C is empty or branches.
std::map<int, std::vector<int>> contact_edges_at_vertices(const Mesh& mesh) {
  std::map<int, std::vector<int>> at;
  for (int e : mesh.boundary_edges())
    if (mesh.edge_part(e) == BoundaryPart::contact)
      for (int v : mesh.edge(e)) at[v].push_back(e);
  if (at.empty()) throw InputError("Γ_C is empty: no boundary edge is marked as contact");
  for (const auto& [v, incident] : at)
    if (incident.size() > 2)
      throw InputError("Γ_C branches at vertex (" + std::to_string(mesh.vertex(v).x()) + ", " +
                       std::to_string(mesh.vertex(v).y()) + "): each zone must be one open or closed curve");
  return at;
}

struct Walk {
  std::vector<int> vertices, edges;  ///< vertices.size() = edges.size() + 1 (a closed walk repeats its start)
};

// Follows Γ_C from `start` along `first`, until an end of the curve or back at `start`.
Walk walk_from(const Mesh& mesh, const std::map<int, std::vector<int>>& at, int start, int first) {
  Walk walk{{start}, {}};
  int vertex = start, edge = first;
  while (edge >= 0) {
    walk.edges.push_back(edge);
    vertex = mesh.edge(edge)[0] == vertex ? mesh.edge(edge)[1] : mesh.edge(edge)[0];
    walk.vertices.push_back(vertex);
    if (vertex == start) break;
    const auto& incident = at.at(vertex);
    const int previous = edge;
    edge = -1;
    for (int e : incident)
      if (e != previous) edge = e;
  }
  return walk;
}

// The zones of Γ_C: open curves from their lexicographically first end, then closed curves from
// their lexicographically first vertex, running with Ω on their left; all ordered by start point.
std::vector<Walk> contact_zones(const Mesh& mesh) {
  const auto at = contact_edges_at_vertices(mesh);
  std::vector<Walk> zones;
  std::map<int, bool> used;
  std::vector<int> ends;
  for (const auto& [v, incident] : at)
    if (incident.size() == 1) ends.push_back(v);
  std::sort(ends.begin(), ends.end(),
            [&](int a, int b) { return lexicographically_before(mesh.vertex(a), mesh.vertex(b)); });
  for (int end : ends) {
    if (used[at.at(end)[0]]) continue;  // the far end of a zone already walked
    zones.push_back(walk_from(mesh, at, end, at.at(end)[0]));
    for (int e : zones.back().edges) used[e] = true;
  }
  while (true) {
    int start = -1;
    for (const auto& [v, incident] : at)
      if (!used[incident[0]] && (start < 0 || lexicographically_before(mesh.vertex(v), mesh.vertex(start)))) start = v;
    if (start < 0) break;
    // Ω on the left: the outward normal points to the right of the direction of travel.
    int first = at.at(start)[0];
    const Point direction =
        mesh.vertex(mesh.edge(first)[0] == start ? mesh.edge(first)[1] : mesh.edge(first)[0]) - mesh.vertex(start);
    const Point normal = mesh.boundary_normal(first, 0.0);
    if (normal.dot(Point(direction.y(), -direction.x())) < 0.0) first = at.at(start)[1];
    zones.push_back(walk_from(mesh, at, start, first));
    for (int e : zones.back().edges) used[e] = true;
  }
  std::stable_sort(zones.begin(), zones.end(), [&](const Walk& a, const Walk& b) {
    return lexicographically_before(mesh.vertex(a.vertices.front()), mesh.vertex(b.vertices.front()));
  });
  return zones;
}

}  // namespace

ContactBoundary::ContactBoundary(const Mesh& mesh) : mesh_(&mesh) {
  for (const Walk& walk : contact_zones(mesh)) {
    ContactZone zone;
    zone.s_begin = length_;
    zone.first_edge = static_cast<int>(edges_.size());
    zone.closed = walk.vertices.front() == walk.vertices.back();
    for (std::size_t k = 0; k < walk.edges.size(); ++k) {
      const int e = walk.edges[k], vertex = walk.vertices[k];
      TraceEdge trace;
      trace.edge = e;
      trace.cell = mesh.edge_cells(e)[0];
      trace.local_edge = mesh.local_edge_of(e, 0);
      trace.zone = static_cast<int>(zones_.size());
      trace.s_begin = length_;
      if (mesh.cell_geometry(trace.cell)) {
        trace.arc = std::make_shared<EdgeArcLength>(mesh, trace.cell, trace.local_edge);
        length_ += trace.arc->length();
      } else {
        length_ += mesh.edge_length(e);
      }
      trace.s_end = length_;
      // The local edge parameter runs from the local edge's start vertex to its end.
      const int local_start =
          mesh.cell(trace.cell)[local_edge_vertices(mesh.cell_type(trace.cell), trace.local_edge)[0]];
      trace.reversed = local_start != vertex;
      edges_.push_back(trace);
      edge_ends_.push_back({mesh.vertex(vertex), mesh.vertex(walk.vertices[k + 1])});
    }
    zone.s_end = length_;
    zone.end_edge = static_cast<int>(edges_.size());
    zones_.push_back(zone);
  }
}

int ContactBoundary::zone_at(double s) const { return edges_[edge_index_at(s)].zone; }

std::vector<BoundaryZone> ContactBoundary::boundary_zones() const {
  std::vector<BoundaryZone> out;
  for (const auto& zone : zones_) out.push_back({zone.s_begin, zone.s_end, zone.closed});
  return out;
}

BoundaryMesh ContactBoundary::edge_mesh() const {
  BoundaryMesh edges(breakpoints(), "trace of T_h");
  edges.set_zones(boundary_zones(), "trace of T_h");
  return edges;
}

std::vector<double> ContactBoundary::breakpoints() const {
  std::vector<double> s{0.0};
  for (const auto& e : edges_) s.push_back(e.s_end);
  return s;
}

int ContactBoundary::edge_index_at(double s) const {
  const auto it = std::lower_bound(edges_.begin(), edges_.end(), s,
                                   [](const TraceEdge& e, double value) { return e.s_end < value; });
  return it == edges_.end() ? static_cast<int>(edges_.size()) - 1 : static_cast<int>(it - edges_.begin());
}

Point ContactBoundary::point_at(double s) const { return point_on_edge(edge_index_at(s), s); }

Point ContactBoundary::point_on_edge(int k, double s) const {
  const auto& e = edges_[k];
  if (!e.arc) {
    const double fraction = (s - e.s_begin) / (e.s_end - e.s_begin);
    return (1.0 - fraction) * edge_ends_[k][0] + fraction * edge_ends_[k][1];
  }
  const Eigen::Vector2d ref = local_edge_point(mesh_->cell_type(e.cell), e.local_edge, e.local_parameter(s));
  return CellMap(*mesh_, e.cell).map(ref.x(), ref.y());
}

Point ContactBoundary::point_at_parameter(int k, double t) const {
  const auto& e = edges_[k];
  const Eigen::Vector2d ref = local_edge_point(mesh_->cell_type(e.cell), e.local_edge, t);
  return CellMap(*mesh_, e.cell).map(ref.x(), ref.y());
}

Point ContactBoundary::tangent_at_parameter(int k, double t) const {
  const auto& e = edges_[k];
  if (!e.arc) return (edge_ends_[k][1] - edge_ends_[k][0]).normalized();
  return (e.reversed ? -1.0 : 1.0) * CellMap(*mesh_, e.cell).edge_tangent(e.local_edge, t).normalized();
}

double ContactBoundary::arc_length_at_parameter(int k, double t) const {
  const auto& e = edges_[k];
  if (e.arc) return e.reversed ? e.s_end - e.arc->arc(t) : e.s_begin + e.arc->arc(t);
  const double fraction = 0.5 * ((e.reversed ? -t : t) + 1.0);
  return e.s_begin + fraction * (e.s_end - e.s_begin);
}

Point ContactBoundary::normal_at(double s) const {
  const auto& e = edges_[edge_index_at(s)];
  return mesh_->boundary_normal(e.edge, e.local_parameter(s));
}

Point ContactBoundary::tangent_at(double s) const { return tangent_on_edge(edge_index_at(s), s); }

Point ContactBoundary::tangent_on_edge(int k, double s) const {
  const auto& e = edges_[k];
  if (!e.arc) return (edge_ends_[k][1] - edge_ends_[k][0]).normalized();
  const Point along_t = CellMap(*mesh_, e.cell).edge_tangent(e.local_edge, e.local_parameter(s));
  return (e.reversed ? -1.0 : 1.0) * along_t.normalized();
}

bool ContactBoundary::is_curved() const {
  return std::any_of(edges_.begin(), edges_.end(), [](const TraceEdge& e) { return e.arc != nullptr; });
}

}  // namespace hpcontact::mesh
