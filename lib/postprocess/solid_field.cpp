// Point values and ParaView grids of functions on hexahedral meshes.
#include "postprocess/solid_field.hpp"

#include <array>

#include "basis/lobatto.hpp"
#include "core/error.hpp"

namespace hpcontact::postprocess {

namespace {

/// The Lobatto values of degree p at ξ along each axis.
std::array<Eigen::VectorXd, 3> axis_values(const space::SolidH1Space& space, int cell, const Eigen::Vector3d& xi) {
  if (space.mesh().is_tetrahedral())
    throw InputError("point values and ParaView grids of functions on tetrahedra are not built");
  const int p = space.cell_degree(cell);
  std::array<Eigen::VectorXd, 3> values;
  Eigen::VectorXd slopes(p + 1);
  for (int d = 0; d < 3; ++d) {
    values[d].resize(p + 1);
    basis::lobatto_values(p, xi(d), values[d], slopes);
  }
  return values;
}

}  // namespace

double solid_value(const space::SolidH1Space& space, const Eigen::VectorXd& coefficients, int cell,
                   const Eigen::Vector3d& xi) {
  const auto values = axis_values(space, cell, xi);
  const Eigen::VectorXd local = space::local_coefficients(space, cell, coefficients);
  double sum = 0.0;
  for (Eigen::Index s = 0; s < local.size(); ++s) {
    const auto& index = space.cell_shapes(cell)[static_cast<std::size_t>(s)].index;
    sum += local(s) * values[0](index[0]) * values[1](index[1]) * values[2](index[2]);
  }
  return sum;
}

Eigen::Vector3d solid_displacement(const space::SolidVectorSpace& space, const Eigen::VectorXd& coefficients, int cell,
                                   const Eigen::Vector3d& xi) {
  const auto values = axis_values(space.scalar(), cell, xi);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto& shape : space.scalar().cell_shapes(cell)) {
    const double phi = shape.sign * values[0](shape.index[0]) * values[1](shape.index[1]) * values[2](shape.index[2]);
    for (int c = 0; c < 3; ++c)
      if (const int dof = space.dof(shape.dof, c); dof >= 0) sum(c) += phi * coefficients(dof);
  }
  return sum;
}

io::VtuGrid solid_vtu_grid(const space::SolidH1Space& space, const SolidPointField& field) {
  constexpr std::uint8_t kVtkHexahedron = 12;
  if (space.mesh().is_tetrahedral()) throw InputError("ParaView grids of functions on tetrahedra are not built");
  io::VtuGrid grid;
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
