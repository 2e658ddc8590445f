// L² distance of multipliers on two boundary meshes.
#include "contact/multiplier_distance.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "basis/quadrature.hpp"

namespace hpcontact::contact {

double multiplier_l2_distance(const space::MultiplierSpace& a, const Eigen::VectorXd& ca,
                              const space::MultiplierSpace& b, const Eigen::VectorXd& cb,
                              const std::function<double(double)>& weight) {
  const auto& mesh_a = a.boundary_mesh();
  const auto& mesh_b = b.boundary_mesh();
  if (std::abs(mesh_a.length() - mesh_b.length()) > 1e-10 * mesh_a.length())
    throw std::invalid_argument(
        fmt::format("multiplier_l2_distance: the boundary meshes cover different lengths ({} and {})", mesh_a.length(),
                    mesh_b.length()));
  if (ca.size() != a.n_dofs() || cb.size() != b.n_dofs())
    throw std::invalid_argument("multiplier_l2_distance: coefficient vectors do not match their spaces");
  // The difference is a polynomial of degree ≤ max p_C on every interval of the common refinement;
  // a weight of degree ≤ 2 adds 2 points.
  const auto& rule = basis::gauss_legendre(std::max(a.max_degree(), b.max_degree()) + (weight ? 3 : 1));
  const auto nodes = mesh::common_refinement(mesh_a.nodes(), mesh_b.nodes());
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
    const double begin = nodes[i], end = nodes[i + 1], half = 0.5 * (end - begin);
    // Segments containing the interval: look them up at its midpoint.
    const double middle = 0.5 * (begin + end);
    const int ka = mesh_a.segment_at(middle), kb = mesh_b.segment_at(middle);
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const double s = middle + half * rule.points[q];
      const double va =
          a.basis_values(ka, a.local_coordinate(ka, s)).dot(ca.segment(a.first_dof(ka), a.segment_degree(ka) + 1));
      const double vb =
          b.basis_values(kb, b.local_coordinate(kb, s)).dot(cb.segment(b.first_dof(kb), b.segment_degree(kb) + 1));
      const double w = weight ? weight(s) : 1.0;
      sum += rule.weights[q] * half * w * w * (va - vb) * (va - vb);
    }
  }
  return std::sqrt(sum);
}

}  // namespace hpcontact::contact
