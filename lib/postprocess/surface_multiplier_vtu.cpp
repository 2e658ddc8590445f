// The lattice of each T_{C,H} cell as VTK_QUAD cells (rectangles) or VTK_TRIANGLE cells (triangles).
#include "postprocess/surface_multiplier_vtu.hpp"

#include <cstdint>
#include <initializer_list>
#include <string>
#include <utility>

#include "core/error.hpp"

namespace hpcontact::postprocess {

io::VtuGrid surface_multiplier_vtu_grid(const space::SurfaceMultiplierSpace& multipliers,
                                        const Eigen::VectorXd& coefficients, const std::vector<std::string>& names) {
  const auto n = static_cast<Eigen::Index>(multipliers.n_dofs());
  const auto copies = static_cast<Eigen::Index>(names.size());
  HPC_VERIFY(copies >= 1 && coefficients.size() == copies * n, "surface_multiplier_vtu_grid: one multiplier per name");
  constexpr std::uint8_t kVtkQuad = 9, kVtkTriangle = 5;
  const auto& mesh = multipliers.mesh();
  const int q = std::max(multipliers.degree(), 1);
  io::VtuGrid vtu;
  std::vector<io::VtuGrid::PointArray> fields;
  for (const auto& name : names) fields.push_back({name, 1, {}});
  // One cell's lattice points a(i, j) and the small cells through them: q × q quadrilaterals on a
  // rectangle, q² triangles on a triangle (lattice index i + j ≤ q).
  const bool grid = mesh.is_grid();
  const auto lattice = [&](int i, int j) { return grid ? i + (q + 1) * j : j * (q + 1) - j * (j - 1) / 2 + i; };
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const std::vector<Eigen::Vector2d> corners = mesh.cell_polygon(c);
    const Eigen::Vector2d e1 = corners[1] - corners[0], e2 = corners.back() - corners[0];
    const auto first = static_cast<std::int64_t>(vtu.n_points());
    for (int j = 0; j <= q; ++j)
      for (int i = 0; i <= q - (grid ? 0 : j); ++i) {
        const Eigen::Vector2d a = corners[0] + (double(i) / q) * e1 + (double(j) / q) * e2;
        const mesh::SolidPoint x = mesh.surface().from_plane(a);
        vtu.xyz.insert(vtu.xyz.end(), {x(0), x(1), x(2)});
        const Eigen::VectorXd shapes = multipliers.values(c, a);
        for (Eigen::Index k = 0; k < copies; ++k)
          fields[static_cast<std::size_t>(k)].values.push_back(
              shapes.dot(coefficients.segment(k * n + multipliers.first_dof(c), multipliers.per_cell())));
      }
    const auto add_cell = [&](std::initializer_list<std::pair<int, int>> points, std::uint8_t type) {
      for (const auto& [i, j] : points) vtu.connectivity.push_back(first + lattice(i, j));
      vtu.offsets.push_back(static_cast<std::int64_t>(vtu.connectivity.size()));
      vtu.types.push_back(type);
      vtu.degrees.push_back(multipliers.degree());
    };
    for (int j = 0; j < q; ++j)
      for (int i = 0; i < q - (grid ? 0 : j); ++i) {
        if (grid) {
          add_cell({{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}}, kVtkQuad);
          continue;
        }
        add_cell({{i, j}, {i + 1, j}, {i, j + 1}}, kVtkTriangle);
        if (i + 1 < q - j) add_cell({{i + 1, j}, {i + 1, j + 1}, {i, j + 1}}, kVtkTriangle);
      }
  }
  for (auto& field : fields) vtu.point_data.push_back(std::move(field));
  return vtu;
}

}  // namespace hpcontact::postprocess
