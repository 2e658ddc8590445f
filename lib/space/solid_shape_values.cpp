// Point values of hexahedral (tensor Lobatto) and tetrahedral (hierarchical) shapes.
#include "space/solid_shape_values.hpp"

#include <array>

#include "basis/lobatto.hpp"

namespace hpcontact::space {

const basis::SolidShapeValue& tetrahedron_mode(const basis::TetrahedronShapes& all, const SolidShape& shape) {
  switch (shape.role) {
    case SolidShapeRole::vertex:
      return all.vertex(shape.entity);
    case SolidShapeRole::edge:
      return all.edge(shape.entity, shape.index[0]);
    case SolidShapeRole::face:
      return all.face(shape.entity, shape.index[0], shape.index[1]);
    case SolidShapeRole::interior:
      break;
  }
  return all.interior(shape.index[0], shape.index[1], shape.index[2]);
}

Eigen::VectorXd local_shape_values(const SolidH1Space& space, int cell, const Eigen::Vector3d& xi) {
  const auto shapes = space.cell_shapes(cell);
  const int p = space.cell_degree(cell);
  Eigen::VectorXd out(static_cast<Eigen::Index>(shapes.size()));
  if (space.mesh().is_tetrahedral()) {
    const basis::TetrahedronShapes all(p, xi(0), xi(1), xi(2));
    for (std::size_t s = 0; s < shapes.size(); ++s)
      out(static_cast<Eigen::Index>(s)) = tetrahedron_mode(all, shapes[s]).v;
    return out;
  }
  std::array<Eigen::VectorXd, 3> values;
  Eigen::VectorXd slopes(p + 1);
  for (int d = 0; d < 3; ++d) {
    values[d].resize(p + 1);
    basis::lobatto_values(p, xi(d), values[d], slopes);
  }
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    const auto& index = shapes[s].index;
    out(static_cast<Eigen::Index>(s)) = values[0](index[0]) * values[1](index[1]) * values[2](index[2]);
  }
  return out;
}

}  // namespace hpcontact::space
