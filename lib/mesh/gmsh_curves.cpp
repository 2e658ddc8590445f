// Curved edges from Gmsh's geometry or from high-order nodes.
#include "mesh/gmsh_curves.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <memory>

#include "core/error.hpp"
#include "mesh/edge_curve.hpp"

namespace hpcontact::mesh {
namespace {

using Tag = std::size_t;

std::map<std::pair<int, int>, int> edges_by_vertices(const Mesh& mesh) {
  std::map<std::pair<int, int>, int> out;
  for (int e = 0; e < mesh.n_edges(); ++e) out[{mesh.edge(e)[0], mesh.edge(e)[1]}] = e;
  return out;
}

// The exact curve between parameters u_a (at t = -1) and u_b (at t = 1), interpolated at the
// lowest degree of 16, 24, ..., 48 that reproduces it to 1e-13 of the chord at points between the
// interpolation nodes.
EdgeCurve sample_curve(const gmsh_api::Session& gmsh, int curve, double u_a, double u_b) {
  const auto parameter = [&](double t) { return u_a + 0.5 * (t + 1.0) * (u_b - u_a); };
  const auto points_at = [&](const std::vector<double>& ts) {
    std::vector<double> u;
    for (double t : ts) u.push_back(parameter(t));
    const auto xyz = gmsh.curve_points(curve, u);
    std::vector<Point> out;
    for (std::size_t k = 0; k < ts.size(); ++k) out.emplace_back(xyz[3 * k], xyz[3 * k + 1]);
    return out;
  };
  const std::vector<double> probes{-0.93, -0.61, -0.27, 0.11, 0.47, 0.83};
  const auto exact = points_at(probes);
  for (int degree = 16;; degree += 8) {
    const auto values = points_at(EdgeCurve::chebyshev_lobatto(degree));
    const EdgeCurve candidate = EdgeCurve::from_values(values);
    const double chord = (values.back() - values.front()).norm();
    double error = 0.0;
    for (std::size_t k = 0; k < probes.size(); ++k)
      error = std::max(error, (candidate.point(probes[k]) - exact[k]).norm());
    if (error <= 1e-13 * chord || degree >= 48) return candidate;
  }
}

}  // namespace

void curve_edges_from_geometry(const gmsh_api::Session& gmsh, const std::string& path,
                               const std::unordered_map<Tag, int>& vertex_of,
                               const std::unordered_map<Tag, Point>& position, Mesh& mesh) {
  const auto edge_of = edges_by_vertices(mesh);
  for (int curve : gmsh.curves()) {
    if (gmsh.curve_type(curve) == "Line") continue;
    const auto blocks = gmsh.elements(1, curve);
    const auto parameter_of = gmsh.curve_node_parameters(curve);
    for (std::size_t b = 0; b < blocks.types.size(); ++b) {
      const std::size_t per_element = blocks.nodes[b].size() / blocks.tags[b].size();
      for (std::size_t k = 0; k < blocks.tags[b].size(); ++k) {
        Tag n0 = blocks.nodes[b][per_element * k], n1 = blocks.nodes[b][per_element * k + 1];
        const auto a = vertex_of.find(n0), c = vertex_of.find(n1);
        const auto edge = (a != vertex_of.end() && c != vertex_of.end())
                              ? edge_of.find(std::minmax(a->second, c->second))
                              : edge_of.end();
        if (edge == edge_of.end())
          throw InputError(fmt::format("{}: line element {} of curve {} is not an edge of the quadrilateral mesh", path,
                                       blocks.tags[b][k], curve));
        if (a->second > c->second) std::swap(n0, n1);  // t = -1 at the edge's lower vertex
        const Point &p0 = position.at(n0), &p1 = position.at(n1);
        auto shape = std::make_shared<EdgeCurve>(sample_curve(gmsh, curve, parameter_of.at(n0), parameter_of.at(n1)));
        // Across the seam of a closed curve the parameters of the two ends lie on either side of
        // the period, and the interpolant would run the long way round.
        if ((shape->point(0.0) - 0.5 * (p0 + p1)).norm() > 0.5 * (p1 - p0).norm())
          throw InputError(
              fmt::format("{}: curve {} ({}): an element crosses the seam of its parametrization; split "
                          "the closed curve into arcs",
                          path, curve, gmsh.curve_type(curve)));
        if (shape->relative_deviation_from_chord() > 1e-13) mesh.set_edge_curve(edge->second, shape, path);
      }
    }
  }
}

void curve_edges_from_nodes(const std::vector<GmshEdgeNodes>& edges, const std::string& path,
                            const std::unordered_map<Tag, int>& vertex_of,
                            const std::unordered_map<Tag, Point>& position, Mesh& mesh) {
  const auto edge_of = edges_by_vertices(mesh);
  std::vector<bool> done(mesh.n_edges(), false);
  for (const auto& nodes : edges) {
    if (nodes.size() < 3) continue;
    const int a = vertex_of.at(nodes.front()), b = vertex_of.at(nodes.back());
    const int e = edge_of.at(std::minmax(a, b));
    if (done[e]) continue;
    done[e] = true;
    std::vector<Point> points;
    for (Tag node : nodes) points.push_back(position.at(node));
    if (a > b) std::reverse(points.begin(), points.end());  // t = -1 at the edge's lower vertex
    auto shape = std::make_shared<EdgeCurve>(EdgeCurve::through_equispaced(points));
    if (shape->relative_deviation_from_chord() > 1e-12) mesh.set_edge_curve(e, shape, path);
  }
}

}  // namespace hpcontact::mesh
