// Sampling a multiplier along Γ_C.
#include "postprocess/mode_samples.hpp"

#include <algorithm>

#include "mesh/contact_boundary.hpp"

namespace hpcontact::postprocess {

io::CsvTable sample_mode(const mesh::ContactBoundary& contact, const space::MultiplierSpace& multipliers,
                         const Eigen::VectorXd& mode, int samples_per_segment) {
  const bool two_parts = mode.size() == 2 * multipliers.n_dofs();
  io::CsvTable table(two_parts ? std::vector<std::string>{"x", "mu", "y", "s", "mu_t"}
                               : std::vector<std::string>{"x", "mu", "y", "s"});
  const int n = std::max(samples_per_segment, 2);
  for (int k = 0; k < multipliers.n_segments(); ++k) {
    const auto coefficients = mode.segment(multipliers.first_dof(k), multipliers.segment_degree(k) + 1);
    const double a = multipliers.boundary_mesh().segment_begin(k);
    const double b = multipliers.boundary_mesh().segment_end(k);
    for (int j = 0; j < n; ++j) {
      const double tau = -1.0 + 2.0 * j / (n - 1);
      const double s = a + 0.5 * (b - a) * (tau + 1.0);
      const mesh::Point x = contact.point_at(s);
      const Eigen::VectorXd basis = multipliers.basis_values(k, tau);
      std::vector<io::CsvCell> row{x.x(), basis.dot(coefficients), x.y(), s};
      if (two_parts)
        row.emplace_back(basis.dot(mode.segment(multipliers.n_dofs() + multipliers.first_dof(k), coefficients.size())));
      table.add_row(std::move(row));
    }
  }
  return table;
}

}  // namespace hpcontact::postprocess
