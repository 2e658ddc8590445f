// The lattice of each T_{C,H} cell as VTK_QUAD cells.
#include "postprocess/surface_multiplier_vtu.hpp"

#include <cstdint>

#include "core/error.hpp"

namespace hpcontact::postprocess {

io::VtuGrid surface_multiplier_vtu_grid(const space::SurfaceMultiplierSpace& multipliers,
                                        const Eigen::VectorXd& coefficients, const std::string& name) {
  HPC_VERIFY(coefficients.size() == multipliers.n_dofs(), "surface_multiplier_vtu_grid: one coefficient per dof");
  constexpr std::uint8_t kVtkQuad = 9;
  const auto& mesh = multipliers.mesh();
  const int q = std::max(multipliers.degree(), 1);
  io::VtuGrid grid;
  io::VtuGrid::PointArray values{name, 1, {}};
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const auto [lo, hi] = mesh.cell_bounds(c);
    const auto first = static_cast<std::int64_t>(grid.n_points());
    const Eigen::VectorXd local = coefficients.segment(multipliers.first_dof(c), multipliers.per_cell());
    for (int j = 0; j <= q; ++j)
      for (int i = 0; i <= q; ++i) {
        const Eigen::Vector2d a = lo + (Eigen::Array2d(double(i) / q, double(j) / q) * (hi - lo).array()).matrix();
        const mesh::SolidPoint x = mesh.surface().from_plane(a);
        grid.xyz.insert(grid.xyz.end(), {x(0), x(1), x(2)});
        values.values.push_back(multipliers.values(c, a).dot(local));
      }
    for (int j = 0; j < q; ++j)
      for (int i = 0; i < q; ++i) {
        for (const auto& [di, dj] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}})
          grid.connectivity.push_back(first + (i + di) + (q + 1) * (j + dj));
        grid.offsets.push_back(static_cast<std::int64_t>(grid.connectivity.size()));
        grid.types.push_back(kVtkQuad);
        grid.degrees.push_back(multipliers.degree());
      }
  }
  grid.point_data.push_back(std::move(values));
  return grid;
}

}  // namespace hpcontact::postprocess
