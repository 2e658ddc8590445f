// MultiplierSpace.
#include "space/multiplier_space.hpp"

#include <algorithm>

#include "basis/lobatto.hpp"
#include "core/error.hpp"

namespace hpcontact::space {

MultiplierSpace::MultiplierSpace(const mesh::BoundaryMesh& boundary_mesh, int degree)
    : MultiplierSpace(boundary_mesh, std::vector<int>(boundary_mesh.n_segments(), degree)) {}

MultiplierSpace::MultiplierSpace(const mesh::BoundaryMesh& boundary_mesh, std::vector<int> segment_degrees)
    : mesh_(&boundary_mesh), degrees_(std::move(segment_degrees)) {
  if (static_cast<int>(degrees_.size()) != boundary_mesh.n_segments())
    throw InputError("multiplier degree distribution has " + std::to_string(degrees_.size()) +
                     " entries but the boundary mesh has " + std::to_string(boundary_mesh.n_segments()) + " segments");
  for (int k = 0; k < boundary_mesh.n_segments(); ++k) {
    if (degrees_[k] < 0)
      throw_bad_input("multiplier space", "pC", std::to_string(degrees_[k]),
                      "must be >= 0 (segment " + std::to_string(k) + ")");
    first_dof_.push_back(n_dofs_);
    n_dofs_ += degrees_[k] + 1;
    max_degree_ = std::max(max_degree_, degrees_[k]);
  }
}

double MultiplierSpace::local_coordinate(int k, double s) const {
  const double a = mesh_->segment_begin(k), b = mesh_->segment_end(k);
  return 2.0 * (s - a) / (b - a) - 1.0;
}

Eigen::VectorXd MultiplierSpace::basis_values(int k, double tau) const {
  return basis::legendre_values(degrees_[k], tau);
}

double MultiplierSpace::evaluate(const Eigen::VectorXd& coefficients, double s) const {
  const int k = mesh_->segment_at(s);
  return basis_values(k, local_coordinate(k, s)).dot(coefficients.segment(first_dof_[k], degrees_[k] + 1));
}

}  // namespace hpcontact::space
