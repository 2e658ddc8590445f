// compute_errors: cellwise quadrature of (u - u_h)² and |∇(u - u_h)|².
#include "postprocess/error_norms.hpp"

#include <cmath>

#include "assembly/cell_values.hpp"

namespace hpcontact::postprocess {

ErrorNorms compute_errors(const space::H1Space& space, const Eigen::VectorXd& coefficients,
                          const ExactSolution& exact) {
  double l2_squared = 0.0, energy_squared = 0.0;
  for (int c = 0; c < space.mesh().n_cells(); ++c) {
    // Two points beyond the matrices' rule: the exact solution is not a polynomial.
    const auto rule = assembly::cell_rule(space, c, 2);
    const auto cell = assembly::tabulate_cell(space, c, rule.points);
    const auto& shapes = space.cell_shapes(c);
    Eigen::VectorXd local(shapes.size());
    for (std::size_t s = 0; s < shapes.size(); ++s) local(s) = shapes[s].dof >= 0 ? coefficients(shapes[s].dof) : 0.0;
    const Eigen::VectorXd u = cell.values * local, ux = cell.grad_x * local, uy = cell.grad_y * local;
    for (int q = 0; q < rule.points.size(); ++q) {
      const double w = rule.weights[q] * cell.jacobians(q);
      const mesh::Point x(cell.points(q, 0), cell.points(q, 1));
      const Eigen::Vector2d gradient_error = exact.gradient(x) - Eigen::Vector2d(ux(q), uy(q));
      l2_squared += w * std::pow(exact.value(x) - u(q), 2);
      energy_squared += w * gradient_error.squaredNorm();
    }
  }
  return {std::sqrt(l2_squared), std::sqrt(energy_squared), std::sqrt(l2_squared + energy_squared)};
}

}  // namespace hpcontact::postprocess
