// analyse_infsup and sample_mode.
#include "infsup/infsup_analysis.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/timer.hpp"
#include "infsup/generalized_eigen.hpp"
#include "mesh/contact_boundary.hpp"

namespace hpcontact::infsup {

EigenBackend parse_eigen_backend(const std::string& text, const std::string& origin) {
  if (text == "slepc") return EigenBackend::slepc;
  if (text == "dense") return EigenBackend::dense;
  throw_bad_input(origin, "eigensolver", text, "must be one of: slepc, dense");
}

InfSupResult analyse_infsup(const InfSupSetup& setup, EigenBackend backend) {
  Stopwatch clock;
  const InfSupOperators operators = assemble_infsup_operators(setup);
  Stopwatch eigen_clock;
  const SmallestEigenpair pair = backend == EigenBackend::slepc
                                     ? smallest_eigenpair_slepc(operators.s_g, operators.gram)
                                     : smallest_eigenpair_dense(operators.s_g, operators.gram);
  InfSupResult result;
  result.lambda_min = std::max(pair.eigenvalue, 0.0);
  result.alpha = std::sqrt(result.lambda_min);
  result.lambda_max = pair.largest_eigenvalue;
  result.singular = result.lambda_min <= kRoundOffZero * result.lambda_max;
  result.mode = Eigen::VectorXd::Zero(operators.n_multiplier_dofs);
  for (std::size_t i = 0; i < operators.active_dofs.size(); ++i)
    result.mode(operators.active_dofs[i]) = pair.eigenvector(static_cast<Eigen::Index>(i));
  const int min_p = *std::min_element(setup.cell_degrees.begin(), setup.cell_degrees.end());
  const int max_pc = *std::max_element(setup.segment_degrees.begin(), setup.segment_degrees.end());
  result.pi = stability_indicator(operators.h, operators.H, min_p, max_pc);
  result.h = operators.h;
  result.H = operators.H;
  result.n_primal_dofs = operators.n_primal_dofs;
  result.n_multiplier_dofs = operators.n_multiplier_dofs;
  result.method = pair.method;
  result.residual = pair.residual;
  result.seconds_eigen = eigen_clock.seconds();
  result.seconds_assembly = operators.seconds_assembly;
  result.seconds_primal = operators.seconds_primal;
  result.seconds_gram = operators.seconds_gram;
  result.seconds = clock.seconds();
  return result;
}

io::CsvTable sample_mode(const mesh::QuadMesh& mesh, const space::MultiplierSpace& multipliers,
                         const Eigen::VectorXd& mode, int samples_per_segment) {
  const mesh::ContactBoundary contact(mesh);
  io::CsvTable table({"x", "mu", "y", "s"});
  const int n = std::max(samples_per_segment, 2);
  for (int k = 0; k < multipliers.n_segments(); ++k) {
    const auto coefficients = mode.segment(multipliers.first_dof(k), multipliers.segment_degree(k) + 1);
    const double a = multipliers.boundary_mesh().segment_begin(k);
    const double b = multipliers.boundary_mesh().segment_end(k);
    for (int j = 0; j < n; ++j) {
      const double tau = -1.0 + 2.0 * j / (n - 1);
      const double s = a + 0.5 * (b - a) * (tau + 1.0);
      const mesh::Point x = contact.point_at(s);
      table.add_row({x.x(), multipliers.basis_values(k, tau).dot(coefficients), x.y(), s});
    }
  }
  return table;
}

}  // namespace hpcontact::infsup
