// Meshes of annulus sectors r_inner < r < r_outer, θ_from < θ < θ_to with n_r × n_θ quadrilaterals
// whose sides on the two arcs follow the circles exactly (degree-16 interpolants): curved
// boundaries built without Gmsh.
#pragma once

#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include "mesh/edge_curve.hpp"
#include "mesh/mesh.hpp"

namespace hpcontact::testing {

inline mesh::Point on_circle(double radius, double angle) {
  return radius * mesh::Point(std::cos(angle), std::sin(angle));
}

inline mesh::Mesh annulus_sector_mesh(double r_inner, double r_outer, double theta_from, double theta_to, int n_r,
                                      int n_theta) {
  std::vector<mesh::Point> vertices;
  const auto index = [&](int i, int j) { return i + (n_r + 1) * j; };
  for (int j = 0; j <= n_theta; ++j)
    for (int i = 0; i <= n_r; ++i)
      vertices.push_back(
          on_circle(r_inner + (r_outer - r_inner) * i / n_r, theta_from + (theta_to - theta_from) * j / n_theta));
  std::vector<std::array<int, 4>> cells;
  for (int j = 0; j < n_theta; ++j)
    for (int i = 0; i < n_r; ++i) cells.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)});
  mesh::Mesh mesh(vertices, cells, "annulus sector");
  for (int e : mesh.boundary_edges()) {
    const mesh::Point a = mesh.vertex(mesh.edge(e)[0]), b = mesh.vertex(mesh.edge(e)[1]);
    const double radius = a.norm();
    if (std::abs(b.norm() - radius) > 1e-12 * radius) continue;  // a straight side
    const double from = std::atan2(a.y(), a.x()), to = std::atan2(b.y(), b.x());
    mesh.set_edge_curve(e,
                        std::make_shared<mesh::EdgeCurve>(mesh::EdgeCurve::interpolate(
                            [&](double t) { return on_circle(radius, from + 0.5 * (t + 1) * (to - from)); }, 16)),
                        "annulus sector");
  }
  return mesh;
}

}  // namespace hpcontact::testing
