// sample_boundary.
#include "postprocess/boundary_samples.hpp"

#include "assembly/cell_values.hpp"
#include "assembly/coupling.hpp"
#include "mesh/contact_boundary.hpp"
#include "postprocess/fe_function.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::postprocess {

BoundarySamples sample_boundary(const contact::ContactSetup& setup, const contact::ContactSolution& solution,
                                int per_interval) {
  const bool signorini = setup.problem == contact::ContactProblem::signorini;
  const space::H1Space space(*setup.mesh, setup.cell_degrees);
  const auto u_field = assembly::total_field(solution.lift.get(), space, solution.u);
  const mesh::ContactBoundary contact(*setup.mesh);
  const space::MultiplierSpace multipliers(*setup.boundary_mesh, setup.segment_degrees);
  BoundarySamples out{io::CsvTable({"x", "u", signorini ? "obstacle" : "s", "lambda", "y", "s_arc", "zone"}), 0.0,
                      std::vector<double>(contact.zones().size(), 0.0)};
  const double lambda_scale = solution.lambda.cwiseAbs().maxCoeff();
  for (const auto& interval : assembly::common_intervals(contact, *setup.boundary_mesh)) {
    const auto& trace = contact.edges()[interval.trace_edge];
    const int k = interval.segment;
    const auto coefficients =
        solution.lambda_legendre.segment(multipliers.first_dof(k), multipliers.segment_degree(k) + 1);
    int in_contact = 0;
    for (int j = 0; j < per_interval; ++j) {
      const double s = interval.s_begin + (interval.s_end - interval.s_begin) * j / (per_interval - 1);
      const double t = trace.local_parameter(s);
      const Eigen::Vector2d ref = mesh::local_edge_point(contact.mesh().cell_type(trace.cell), trace.local_edge, t);
      const auto u = postprocess::evaluate(u_field.space, u_field.coefficients, {trace.cell, ref.x(), ref.y()});
      const mesh::Point x = contact.point_at(s);
      const double lambda = multipliers.basis_values(k, multipliers.local_coordinate(k, s)).dot(coefficients);
      const double data = signorini ? setup.obstacle(x) : setup.bound(x);
      out.table.add_row({x.x(), u.value, data, lambda, x.y(), s, static_cast<long long>(trace.zone)});
      if (std::abs(lambda) > 1e-10 * lambda_scale) ++in_contact;
    }
    const double in_contact_length = (interval.s_end - interval.s_begin) * in_contact / per_interval;
    out.contact_set_length += in_contact_length;
    out.zone_contact_set_length[trace.zone] += in_contact_length;
  }
  return out;
}

}  // namespace hpcontact::postprocess
