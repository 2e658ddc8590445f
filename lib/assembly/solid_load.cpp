// Cell-by-cell load assembly on hexahedra.
#include "assembly/solid_load.hpp"

#include "assembly/solid_cell_values.hpp"

namespace hpcontact::assembly {

Eigen::VectorXd solid_load(const space::SolidH1Space& space, const SolidFunction& f) {
  Eigen::VectorXd load = Eigen::VectorXd::Zero(space.n_dofs());
  for (int c = 0; c < space.mesh().n_cells(); ++c) {
    const SolidCellValues at = solid_cell_values(space, c, solid_points_per_axis(space.cell_degree(c)));
    Eigen::VectorXd weighted(at.weights.size());
    for (Eigen::Index q = 0; q < weighted.size(); ++q) weighted(q) = at.weights(q) * f(at.points[q]);
    const Eigen::VectorXd local = at.values * weighted;
    const auto shapes = space.cell_shapes(c);
    for (std::size_t s = 0; s < shapes.size(); ++s)
      if (shapes[s].dof >= 0) load(shapes[s].dof) += shapes[s].sign * local(static_cast<Eigen::Index>(s));
  }
  return load;
}

}  // namespace hpcontact::assembly
