// L² and H¹ errors on hexahedra by quadrature.
#include "postprocess/solid_errors.hpp"

#include <cmath>

#include "assembly/solid_cell_values.hpp"
#include "core/error.hpp"

namespace hpcontact::postprocess {

SolidErrors solid_errors(const space::SolidH1Space& space, const Eigen::VectorXd& coefficients,
                         const std::function<double(const mesh::SolidPoint&)>& exact,
                         const std::function<Eigen::Vector3d(const mesh::SolidPoint&)>& exact_gradient,
                         int extra_points) {
  HPC_VERIFY(coefficients.size() == space.n_dofs(), "one coefficient per dof");
  SolidErrors errors;
  for (int c = 0; c < space.mesh().n_cells(); ++c) {
    const auto at =
        assembly::solid_cell_values(space, c, assembly::solid_points_per_axis(space.cell_degree(c)) + extra_points);
    const Eigen::VectorXd local = space::local_coefficients(space, c, coefficients);
    const Eigen::VectorXd values = at.values.transpose() * local;
    Eigen::MatrixXd gradients(values.size(), 3);
    for (int d = 0; d < 3; ++d) gradients.col(d) = at.gradients[d].transpose() * local;
    for (Eigen::Index q = 0; q < values.size(); ++q) {
      const Eigen::Vector3d gradient = exact_gradient(at.points[q]);
      errors.l2 += at.weights(q) * std::pow(exact(at.points[q]) - values(q), 2);
      errors.h1_semi += at.weights(q) * (gradient - gradients.row(q).transpose()).squaredNorm();
      errors.exact_h1_semi += at.weights(q) * gradient.squaredNorm();
    }
  }
  errors.l2 = std::sqrt(errors.l2);
  errors.h1_semi = std::sqrt(errors.h1_semi);
  errors.exact_h1_semi = std::sqrt(errors.exact_h1_semi);
  return errors;
}

}  // namespace hpcontact::postprocess
