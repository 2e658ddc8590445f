// Elastic load: the scalar volume and boundary loads, once per component.
#include "assembly/elastic_load.hpp"

#include "assembly/poisson_assembly.hpp"

namespace hpcontact::assembly {

Eigen::VectorXd assemble_elastic_load(const space::VectorSpace& vector_space, const VectorFunction& body_force,
                                      const std::set<mesh::BoundaryPart>& parts, const TractionFunction& traction) {
  const space::H1Space& space = vector_space.scalar();
  std::array<Eigen::VectorXd, space::kComponents> component;
  for (int c = 0; c < space::kComponents; ++c) {
    component[c] = Eigen::VectorXd::Zero(space.n_dofs());
    if (body_force) component[c] += assemble_volume_load(space, [&](const mesh::Point& x) { return body_force(x)(c); });
    if (traction && !parts.empty())
      component[c] += assemble_boundary_load(
          space, parts, [&](const mesh::Point& x, const mesh::Point& n) { return traction(x, n)(c); });
  }
  return vector_space.from_components(component[0], component[1]);
}

}  // namespace hpcontact::assembly
