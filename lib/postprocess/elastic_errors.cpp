// compute_elastic_errors: cellwise quadrature of |e|² and 2μ ε(e):ε(e) + λ (div e)², e = u − u_h.
#include "postprocess/elastic_errors.hpp"

#include <cmath>

#include "assembly/cell_values.hpp"

namespace hpcontact::postprocess {

ElasticErrors compute_elastic_errors(const space::VectorSpace& vector_space,
                                     const std::vector<assembly::Material>& materials, const Eigen::VectorXd& u,
                                     const ExactDisplacement& exact) {
  const space::H1Space& space = vector_space.scalar();
  double l2_squared = 0.0, energy_squared = 0.0;
  for (int c = 0; c < space.mesh().n_cells(); ++c) {
    // Two points beyond the matrices' rule: the exact solution is not a polynomial.
    const auto rule = assembly::cell_rule(space, c, 2);
    const auto cell = assembly::tabulate_cell(space, c, rule.points);
    const auto& shapes = space.cell_shapes(c);
    Eigen::MatrixXd local = Eigen::MatrixXd::Zero(shapes.size(), 2);  // column = component
    for (std::size_t s = 0; s < shapes.size(); ++s)
      for (int k = 0; k < 2; ++k)
        if (const int dof = vector_space.dof(shapes[s].dof, k); dof >= 0) local(s, k) = u(dof);
    const Eigen::MatrixXd values = cell.values * local, dx = cell.grad_x * local, dy = cell.grad_y * local;
    const double lambda = materials[c].lambda, mu = materials[c].mu;
    for (int q = 0; q < rule.points.size(); ++q) {
      const double w = rule.weights[q] * cell.jacobians(q);
      const mesh::Point x(cell.points(q, 0), cell.points(q, 1));
      Eigen::Matrix2d grad_h;
      grad_h << dx(q, 0), dy(q, 0), dx(q, 1), dy(q, 1);
      const Eigen::Matrix2d e = exact.gradient(x) - grad_h;
      const Eigen::Matrix2d strain = 0.5 * (e + e.transpose());
      l2_squared += w * (exact.value(x) - values.row(q).transpose()).squaredNorm();
      energy_squared += w * (2.0 * mu * strain.squaredNorm() + lambda * std::pow(e.trace(), 2));
    }
  }
  return {std::sqrt(l2_squared), std::sqrt(energy_squared)};
}

}  // namespace hpcontact::postprocess
