// Point evaluation through the cell tabulation at one reference point.
#include "postprocess/fe_function.hpp"

#include "assembly/cell_values.hpp"
#include "core/error.hpp"

namespace hpcontact::postprocess {

PointValue evaluate(const space::H1Space& space, const Eigen::VectorXd& coefficients, const CellPoint& where) {
  const auto cell = assembly::tabulate_cell(space, where.cell, {{where.xi}, {where.eta}});
  PointValue out;
  const auto& shapes = space.cell_shapes(where.cell);
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    if (shapes[s].dof < 0) continue;
    const double u = coefficients(shapes[s].dof);
    out.value += u * cell.values(0, s);
    out.gradient += u * Eigen::Vector2d(cell.grad_x(0, s), cell.grad_y(0, s));
  }
  return out;
}

PointValue evaluate_at(const space::H1Space& space, const Eigen::VectorXd& coefficients, const PointLocator& locator,
                       const mesh::Point& x) {
  const auto where = locator.locate(x);
  if (!where)
    throw InputError("evaluation point (" + std::to_string(x.x()) + ", " + std::to_string(x.y()) +
                     ") lies outside the mesh");
  return evaluate(space, coefficients, *where);
}

}  // namespace hpcontact::postprocess
