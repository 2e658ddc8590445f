// ContactBoundary: chain ordering of Γ_C edges.
#include "mesh/contact_boundary.hpp"

#include <algorithm>
#include <map>

#include "core/error.hpp"

namespace hpcontact::mesh {

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
    length_ += mesh.edge_length(e);
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
  const double fraction = (s - e.s_begin) / (e.s_end - e.s_begin);
  return (1.0 - fraction) * chain_vertices_[k] + fraction * chain_vertices_[k + 1];
}

}  // namespace hpcontact::mesh
