// Point values and ParaView grids of functions on solid meshes.
#include "postprocess/solid_field.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <map>

#include "space/solid_shape_values.hpp"

namespace hpcontact::postprocess {

double solid_value(const space::SolidH1Space& space, const Eigen::VectorXd& coefficients, int cell,
                   const Eigen::Vector3d& xi) {
  return space::local_shape_values(space, cell, xi).dot(space::local_coefficients(space, cell, coefficients));
}

Eigen::Vector3d solid_displacement(const space::SolidVectorSpace& space, const Eigen::VectorXd& coefficients, int cell,
                                   const Eigen::Vector3d& xi) {
  const Eigen::VectorXd values = space::local_shape_values(space.scalar(), cell, xi);
  const auto shapes = space.scalar().cell_shapes(cell);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    const double phi = shapes[s].sign * values(static_cast<Eigen::Index>(s));
    for (int c = 0; c < 3; ++c)
      if (const int dof = space.dof(shapes[s].dof, c); dof >= 0) sum(c) += phi * coefficients(dof);
  }
  return sum;
}

namespace {

/// Tetrahedron c cut into p³ linear tetrahedra: the lattice points x ∈ {0 … p}³ with
/// p ≥ x₁ ≥ x₂ ≥ x₃ ≥ 0 fill the simplex of those inequalities, which the Kuhn tetrahedra of the
/// unit cubes inside it triangulate (Freudenthal's subdivision); ξ = 2 (x₁ − x₂, x₂ − x₃, x₃)/p − 1
/// maps it onto the reference tetrahedron.
void append_tetrahedron(const space::SolidH1Space& space, const SolidPointField& field, int c, io::VtuGrid& grid,
                        io::VtuGrid::PointArray& values) {
  constexpr std::uint8_t kVtkTetrahedron = 10;
  const mesh::SolidMesh& mesh = space.mesh();
  const int p = space.cell_degree(c);
  const auto inside = [p](const std::array<int, 3>& x) {
    return p >= x[0] && x[0] >= x[1] && x[1] >= x[2] && x[2] >= 0;
  };
  std::map<std::array<int, 3>, int> index;
  for (int a = 0; a <= p; ++a)
    for (int b = 0; b <= a; ++b)
      for (int k = 0; k <= b; ++k) {
        index[{a, b, k}] = static_cast<int>(grid.n_points());
        const Eigen::Vector3d xi(2.0 * (a - b) / p - 1.0, 2.0 * (b - k) / p - 1.0, 2.0 * k / p - 1.0);
        const mesh::SolidPoint x = mesh.map(c, xi);
        grid.xyz.insert(grid.xyz.end(), {x(0), x(1), x(2)});
        const Eigen::VectorXd value = field.evaluate(c, xi);
        values.values.insert(values.values.end(), value.data(), value.data() + value.size());
      }
  std::array<int, 3> axes{0, 1, 2};
  for (int a = 0; a < p; ++a)
    for (int b = 0; b <= a; ++b)
      for (int k = 0; k <= b; ++k) do {
          // The path from the cube's corner along axes[0], axes[1], axes[2] to the opposite corner.
          std::array<std::array<int, 3>, 4> path{};
          path[0] = {a, b, k};
          for (int step = 1; step < 4; ++step) {
            path[step] = path[step - 1];
            ++path[step][axes[step - 1]];
          }
          if (std::all_of(path.begin(), path.end(), inside)) {
            // VTK wants a positive volume: the path's orientation depends on the permutation and
            // on the sign of the cell map (vertices ascending).
            std::array<Eigen::Vector3d, 4> corner;
            for (int v = 0; v < 4; ++v) corner[v] = Eigen::Map<const Eigen::Vector3d>(&grid.xyz[3 * index.at(path[v])]);
            Eigen::Matrix3d edges;
            edges << corner[1] - corner[0], corner[2] - corner[0], corner[3] - corner[0];
            if (edges.determinant() < 0.0) std::swap(path[1], path[2]);
            for (const auto& x : path) grid.connectivity.push_back(index.at(x));
            grid.offsets.push_back(static_cast<std::int64_t>(grid.connectivity.size()));
            grid.types.push_back(kVtkTetrahedron);
            grid.degrees.push_back(p);
          }
        } while (std::next_permutation(axes.begin(), axes.end()));
}

}  // namespace

io::VtuGrid solid_vtu_grid(const space::SolidH1Space& space, const SolidPointField& field) {
  constexpr std::uint8_t kVtkHexahedron = 12;
  io::VtuGrid grid;
  if (space.mesh().is_tetrahedral()) {
    io::VtuGrid::PointArray values{field.name, field.components, {}};
    for (int c = 0; c < space.mesh().n_cells(); ++c) append_tetrahedron(space, field, c, grid, values);
    grid.point_data.push_back(std::move(values));
    return grid;
  }
  io::VtuGrid::PointArray values{field.name, field.components, {}};
  const mesh::SolidMesh& mesh = space.mesh();
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const int p = space.cell_degree(c), first = static_cast<int>(grid.n_points());
    const auto point = [&](int i, int j, int k) { return first + i + (p + 1) * (j + (p + 1) * k); };
    for (int k = 0; k <= p; ++k)
      for (int j = 0; j <= p; ++j)
        for (int i = 0; i <= p; ++i) {
          const Eigen::Vector3d xi(-1.0 + 2.0 * i / p, -1.0 + 2.0 * j / p, -1.0 + 2.0 * k / p);
          const mesh::SolidPoint x = mesh.map(c, xi);
          grid.xyz.insert(grid.xyz.end(), {x(0), x(1), x(2)});
          const Eigen::VectorXd value = field.evaluate(c, xi);
          values.values.insert(values.values.end(), value.data(), value.data() + value.size());
        }
    for (int k = 0; k < p; ++k)
      for (int j = 0; j < p; ++j)
        for (int i = 0; i < p; ++i) {
          for (const auto& [a, b] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}})
            grid.connectivity.push_back(point(i + a, j + b, k));
          for (const auto& [a, b] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}})
            grid.connectivity.push_back(point(i + a, j + b, k + 1));
          grid.offsets.push_back(static_cast<std::int64_t>(grid.connectivity.size()));
          grid.types.push_back(kVtkHexahedron);
          grid.degrees.push_back(p);
        }
  }
  grid.point_data.push_back(std::move(values));
  return grid;
}

}  // namespace hpcontact::postprocess
