// Elastic load: the scalar volume and boundary loads cell by cell, once per component.
#include "assembly/elastic_load.hpp"

#include "assembly/poisson_assembly.hpp"

namespace hpcontact::assembly {

Eigen::VectorXd assemble_elastic_load(const space::VectorSpace& vector_space, const VectorFunction& body_force,
                                      const std::set<mesh::BoundaryPart>& parts, const TractionFunction& traction,
                                      const LocalRows& target) {
  const space::H1Space& space = vector_space.scalar();
  Eigen::VectorXd load = Eigen::VectorXd::Zero(target.size(vector_space.n_dofs()));
  for (int c = 0; c < space::kComponents; ++c) {
    const auto add = [&, c](int scalar_dof, double value) {
      if (const int k = vector_space.dof(scalar_dof, c); k >= 0) load(target.row(k)) += value;
    };
    if (body_force)
      visit_volume_load(
          space, [&](const mesh::Point& x) { return body_force(x)(c); }, target, add);
    if (traction && !parts.empty())
      visit_boundary_load(
          space, parts, [&](const mesh::Point& x, const mesh::Point& n) { return traction(x, n)(c); }, target, add);
  }
  return load;
}

}  // namespace hpcontact::assembly
