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
  EdgeArcLength(const QuadMesh& mesh, int cell, int local_edge) : map_(mesh, cell), local_edge_(local_edge) {
    panel_start_.push_back(0.0);
    for (int k = 0; k < kPanels; ++k) panel_start_.push_back(panel_start_.back() + integral(panel(k), panel(k + 1)));
  }
  double length() const { return panel_start_.back(); }
  double speed(double t) const {
    const Eigen::Vector2d ref = local_edge_point(local_edge_, t);
    return (map_.jacobian(ref.x(), ref.y()) * local_edge_direction(local_edge_)).norm();
  }
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

ContactBoundary::ContactBoundary(const QuadMesh& mesh) : mesh_(&mesh) {
  std::map<int, std::vector<int>> edges_at_vertex;
  int n_contact = 0;
  for (int e : mesh.boundary_edges())
    if (mesh.edge_part(e) == BoundaryPart::contact) {
      ++n_contact;
      for (int v : mesh.edge(e)) edges_at_vertex[v].push_back(e);
    }
  if (n_contact == 0) throw InputError("Γ_C is empty: no boundary edge is marked as contact");
  std::vector<int> ends;
  for (const auto& [v, incident] : edges_at_vertex) {
    if (incident.size() > 2)
      throw InputError("Γ_C branches at vertex (" + std::to_string(mesh.vertex(v).x()) + ", " +
                       std::to_string(mesh.vertex(v).y()) + "): it must be one open curve");
    if (incident.size() == 1) ends.push_back(v);
  }
  if (ends.size() != 2)
    throw InputError("Γ_C must be one open curve; it has " + std::to_string(ends.size() / 2) + " pieces or is closed");
  const auto lexicographic = [&](int a, int b) {
    const Point &pa = mesh.vertex(a), &pb = mesh.vertex(b);
    return pa.x() < pb.x() || (pa.x() == pb.x() && pa.y() < pb.y());
  };
  int vertex = lexicographic(ends[0], ends[1]) ? ends[0] : ends[1];
  int previous_edge = -1;
  chain_vertices_.push_back(mesh.vertex(vertex));
  while (true) {
    const auto& incident = edges_at_vertex[vertex];
    const auto next = std::find_if(incident.begin(), incident.end(), [&](int e) { return e != previous_edge; });
    if (next == incident.end()) break;
    const int e = *next;
    const int other = mesh.edge(e)[0] == vertex ? mesh.edge(e)[1] : mesh.edge(e)[0];
    TraceEdge trace;
    trace.edge = e;
    trace.cell = mesh.edge_cells(e)[0];
    trace.local_edge = mesh.local_edge_of(e, 0);
    trace.s_begin = length_;
    if (mesh.cell_geometry(trace.cell)) {
      trace.arc = std::make_shared<EdgeArcLength>(mesh, trace.cell, trace.local_edge);
      length_ += trace.arc->length();
    } else {
      length_ += mesh.edge_length(e);
    }
    trace.s_end = length_;
    // The local edge parameter runs from local vertex kLocalEdgeVertices[.][0] to [1].
    const int local_start = mesh.cell(trace.cell)[kLocalEdgeVertices[trace.local_edge][0]];
    trace.reversed = local_start != vertex;
    edges_.push_back(trace);
    chain_vertices_.push_back(mesh.vertex(other));
    previous_edge = e;
    vertex = other;
  }
  if (static_cast<int>(edges_.size()) != n_contact)
    throw InputError("Γ_C must be one connected curve; it has several pieces");
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

Point ContactBoundary::point_at(double s) const {
  const int k = edge_index_at(s);
  const auto& e = edges_[k];
  if (!e.arc) {
    const double fraction = (s - e.s_begin) / (e.s_end - e.s_begin);
    return (1.0 - fraction) * chain_vertices_[k] + fraction * chain_vertices_[k + 1];
  }
  const Eigen::Vector2d ref = local_edge_point(e.local_edge, e.local_parameter(s));
  return CellMap(*mesh_, e.cell).map(ref.x(), ref.y());
}

Point ContactBoundary::normal_at(double s) const {
  const auto& e = edges_[edge_index_at(s)];
  return mesh_->boundary_normal(e.edge, e.local_parameter(s));
}

Point ContactBoundary::tangent_at(double s) const {
  const int k = edge_index_at(s);
  const auto& e = edges_[k];
  if (!e.arc) return (chain_vertices_[k + 1] - chain_vertices_[k]).normalized();
  const Eigen::Vector2d ref = local_edge_point(e.local_edge, e.local_parameter(s));
  const Point along_t = CellMap(*mesh_, e.cell).jacobian(ref.x(), ref.y()) * local_edge_direction(e.local_edge);
  return (e.reversed ? -1.0 : 1.0) * along_t.normalized();
}

bool ContactBoundary::is_curved() const {
  return std::any_of(edges_.begin(), edges_.end(), [](const TraceEdge& e) { return e.arc != nullptr; });
}

}  // namespace hpcontact::mesh
