// The lattice of each T_{C,H} cell as VTK_QUAD cells.
#include "postprocess/surface_multiplier_vtu.hpp"

#include <cstdint>
#include <string>

#include "core/error.hpp"

namespace hpcontact::postprocess {

io::VtuGrid surface_multiplier_vtu_grid(const space::SurfaceMultiplierSpace& multipliers,
                                        const Eigen::VectorXd& coefficients, const std::vector<std::string>& names) {
  const auto n = static_cast<Eigen::Index>(multipliers.n_dofs());
  const auto copies = static_cast<Eigen::Index>(names.size());
  HPC_VERIFY(copies >= 1 && coefficients.size() == copies * n, "surface_multiplier_vtu_grid: one multiplier per name");
  constexpr std::uint8_t kVtkQuad = 9;
  const auto& mesh = multipliers.mesh();
  const int q = std::max(multipliers.degree(), 1);
  io::VtuGrid grid;
  std::vector<io::VtuGrid::PointArray> fields;
  for (const auto& name : names) fields.push_back({name, 1, {}});
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const auto [lo, hi] = mesh.cell_bounds(c);
    const auto first = static_cast<std::int64_t>(grid.n_points());
    for (int j = 0; j <= q; ++j)
      for (int i = 0; i <= q; ++i) {
        const Eigen::Vector2d a = lo + (Eigen::Array2d(double(i) / q, double(j) / q) * (hi - lo).array()).matrix();
        const mesh::SolidPoint x = mesh.surface().from_plane(a);
        grid.xyz.insert(grid.xyz.end(), {x(0), x(1), x(2)});
        const Eigen::VectorXd shapes = multipliers.values(c, a);
        for (Eigen::Index k = 0; k < copies; ++k)
          fields[static_cast<std::size_t>(k)].values.push_back(
              shapes.dot(coefficients.segment(k * n + multipliers.first_dof(c), multipliers.per_cell())));
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
  for (auto& field : fields) grid.point_data.push_back(std::move(field));
  return grid;
}

}  // namespace hpcontact::postprocess
