// Rectangle mesh generator, random perturbation and boundary-part assignment.
#include "mesh/rectangle_mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

#include "core/error.hpp"

namespace hpcontact::mesh {

Mesh make_rectangle_mesh(const Rectangle& r, int n_x, int n_y) {
  if (n_x < 1) throw_bad_input("rectangle mesh", "n_x", std::to_string(n_x), "must be >= 1");
  if (n_y < 1) throw_bad_input("rectangle mesh", "n_y", std::to_string(n_y), "must be >= 1");
  if (!(r.x_max > r.x_min) || !(r.y_max > r.y_min))
    throw InputError("rectangle mesh: the bounds must satisfy x_min < x_max and y_min < y_max");
  std::vector<double> x(n_x + 1), y(n_y + 1);
  for (int i = 0; i <= n_x; ++i) x[i] = r.x_min + (r.x_max - r.x_min) * i / n_x;
  for (int j = 0; j <= n_y; ++j) y[j] = r.y_min + (r.y_max - r.y_min) * j / n_y;
  return make_tensor_mesh(x, y, "rectangle mesh");
}

Mesh make_tensor_mesh(const std::vector<double>& x, const std::vector<double>& y, const std::string& origin) {
  for (const auto* nodes : {&x, &y})
    if (nodes->size() < 2 || !std::is_sorted(nodes->begin(), nodes->end(), std::less_equal<>()))
      throw InputError(origin + ": the nodes must be strictly increasing, at least two in each direction");
  const int n_x = static_cast<int>(x.size()) - 1, n_y = static_cast<int>(y.size()) - 1;
  std::vector<Point> vertices;
  vertices.reserve(static_cast<std::size_t>(n_x + 1) * (n_y + 1));
  for (int j = 0; j <= n_y; ++j)
    for (int i = 0; i <= n_x; ++i) vertices.emplace_back(x[i], y[j]);
  auto index = [n_x](int i, int j) { return j * (n_x + 1) + i; };
  std::vector<std::array<int, 4>> cells;
  cells.reserve(static_cast<std::size_t>(n_x) * n_y);
  for (int j = 0; j < n_y; ++j)
    for (int i = 0; i < n_x; ++i) cells.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)});
  Mesh mesh(std::move(vertices), std::move(cells), origin);
  const double tol_x = 1e-9 * (x.back() - x.front()), tol_y = 1e-9 * (y.back() - y.front());
  for (int e : mesh.boundary_edges()) {
    const Point m = mesh.edge_midpoint(e);
    if (std::abs(m.y() - y.front()) < tol_y)
      mesh.set_edge_label(e, "bottom");
    else if (std::abs(m.x() - x.back()) < tol_x)
      mesh.set_edge_label(e, "right");
    else if (std::abs(m.y() - y.back()) < tol_y)
      mesh.set_edge_label(e, "top");
    else
      mesh.set_edge_label(e, "left");
  }
  return mesh;
}

std::vector<double> graded_nodes(double a, double b, int n, const std::vector<double>& points, double ratio, int layers,
                                 const std::string& origin, const std::vector<double>& snapped_only,
                                 const std::string& snapped_origin) {
  if (!(ratio > 0.0 && ratio < 1.0)) throw_bad_input(origin, "grading", fmt::format("{}", ratio), "must be in (0, 1)");
  if (n < 1) throw_bad_input(origin, "cells", std::to_string(n), "must be >= 1");
  std::vector<double> nodes(n + 1);
  for (int i = 0; i <= n; ++i) nodes[i] = a + (b - a) * i / n;
  const double h = (b - a) / n;
  // 1. Snap the nearest node to each point (end nodes only to points at the ends).
  std::vector<int> snapped;    // nodes of all points
  std::vector<int> layered;    // nodes of `points`, which get layers
  std::vector<double> placed;  // coordinates already snapped
  auto targets = points;
  targets.insert(targets.end(), snapped_only.begin(), snapped_only.end());
  std::vector<const std::string*> moved_by(n + 1, nullptr);  // which key moved each node, for the h/4 check
  for (std::size_t t = 0; t < targets.size(); ++t) {
    const double point = targets[t];
    const std::string& where = t < points.size() || snapped_origin.empty() ? origin : snapped_origin;
    const auto same =
        std::find_if(placed.begin(), placed.end(), [&](double q) { return std::abs(q - point) <= 1e-12 * (b - a); });
    if (same != placed.end()) {
      if (t < points.size()) layered.push_back(snapped[same - placed.begin()]);
      continue;
    }
    if (!(point >= a - 1e-12 * (b - a) && point <= b + 1e-12 * (b - a)))
      throw_bad_input(where, "grading point", fmt::format("{}", point), fmt::format("must lie in [{}, {}]", a, b));
    int i = static_cast<int>(std::lround((point - a) / h));
    if ((i == 0 || i == n) && std::abs(nodes[i] - point) > 1e-12 * (b - a)) i = i == 0 ? 1 : n - 1;
    if (i <= 0 || i >= n ? std::abs(nodes[i] - point) > 1e-12 * (b - a) : false)
      throw_bad_input(where, "grading point", fmt::format("{}", point),
                      "too close to an end of the interval for this many cells");
    if (std::find(snapped.begin(), snapped.end(), i) != snapped.end())
      throw_bad_input(where, "grading point", fmt::format("{}", point),
                      "two grading points share the nearest node: use more cells");
    nodes[i] = point;
    moved_by[i] = &where;
    snapped.push_back(i);
    placed.push_back(point);
    if (t < points.size()) layered.push_back(i);
  }
  for (int i = 0; i < n; ++i)
    if (!(nodes[i + 1] - nodes[i] > 0.25 * h)) {
      const int moved = moved_by[i + 1] ? i + 1 : i;
      throw_bad_input(moved_by[moved] ? *moved_by[moved] : origin, "grading point", fmt::format("{}", nodes[moved]),
                      "snapping it to the nearest node leaves a cell thinner than h/4: use more cells");
    }
  // 2. Geometric layers in both neighbouring cells of each snapped node: nodes at distance
  //    (cell size) · ratio^k, k = 1..layers, so that cell sizes shrink by `ratio` towards the point.
  std::vector<double> all = nodes;
  std::sort(layered.begin(), layered.end());
  layered.erase(std::unique(layered.begin(), layered.end()), layered.end());
  if (!layered.empty() && 0.25 * h * std::pow(ratio, layers) < kFinestRelativeCell * (b - a))
    throw_bad_input(
        origin, "grading_layers", std::to_string(layers),
        fmt::format("too deep for grading {}: the innermost cells would be below {:.0e} of the interval, where "
                    "round-off in the coordinates distorts them",
                    ratio, kFinestRelativeCell));
  for (int i : layered)
    for (int side : {-1, 1}) {
      const int neighbour = i + side;
      if (neighbour < 0 || neighbour > n) continue;
      const double size = std::abs(nodes[neighbour] - nodes[i]);
      for (int k = 1; k <= layers; ++k) all.push_back(nodes[i] + side * size * std::pow(ratio, k));
    }
  std::sort(all.begin(), all.end());
  return all;
}

void perturb_interior_vertices(Mesh& mesh, double amplitude, std::uint32_t seed) {
  if (!(amplitude >= 0.0 && amplitude < 0.25))
    throw_bad_input("mesh perturbation", "amplitude", std::to_string(amplitude),
                    "must be in [0, 0.25) so that cells stay convex");
  std::vector<bool> on_boundary(mesh.n_vertices(), false);
  std::vector<double> shortest(mesh.n_vertices(), INFINITY);
  for (int e = 0; e < mesh.n_edges(); ++e) {
    const double length = mesh.edge_length(e);
    for (int v : mesh.edge(e)) {
      shortest[v] = std::min(shortest[v], length);
      if (mesh.is_boundary_edge(e)) on_boundary[v] = true;
    }
  }
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<Point> moved = mesh.vertices();
  for (int v = 0; v < mesh.n_vertices(); ++v) {
    if (on_boundary[v]) continue;
    moved[v] += amplitude * shortest[v] * Point(uniform(generator), uniform(generator));
  }
  mesh.move_vertices(std::move(moved), "perturbed mesh");
}

int assign_boundary_part(Mesh& mesh, BoundaryPart part, const std::function<bool(const Point&)>& contains) {
  int count = 0;
  for (int e : mesh.boundary_edges())
    if (contains(mesh.edge_midpoint(e))) {
      mesh.set_edge_part(e, part);
      ++count;
    }
  return count;
}

int assign_boundary_parts_by_label(Mesh& mesh, const std::map<std::string, BoundaryPart>& part_of_label) {
  int count = 0;
  for (int e : mesh.boundary_edges()) {
    const auto it = part_of_label.find(mesh.edge_label(e));
    if (it == part_of_label.end()) continue;
    mesh.set_edge_part(e, it->second);
    ++count;
  }
  return count;
}

void assign_paper_boundary_parts(Mesh& mesh) {
  constexpr double tol = 1e-9;
  assign_boundary_part(mesh, BoundaryPart::contact, [](const Point& m) { return std::abs(m.y() + 1.0) < tol; });
  assign_boundary_part(mesh, BoundaryPart::dirichlet, [](const Point& m) {
    return std::abs(m.y() - 1.0) < tol || (std::abs(m.x() - 1.0) < tol && m.y() > 0.0);
  });
}

Mesh make_paper_square_mesh(int n) {
  if (n < 2 || n % 2 != 0)
    throw_bad_input("paper square", "n", std::to_string(n),
                    "must be even and >= 2 so that (1,0), where Γ_D ends, is a mesh vertex");
  Mesh mesh = make_rectangle_mesh(Rectangle{}, n, n);
  assign_paper_boundary_parts(mesh);
  return mesh;
}

}  // namespace hpcontact::mesh
