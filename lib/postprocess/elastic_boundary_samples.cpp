// sample_elastic_boundary.
#include "postprocess/elastic_boundary_samples.hpp"

#include "assembly/cell_values.hpp"
#include "assembly/coupling.hpp"
#include "postprocess/boundary_samples.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::postprocess {

double total_force(const space::MultiplierSpace& multipliers, const Eigen::VectorXd& pressure, int zone) {
  double force = 0.0;
  const auto& boundary = multipliers.boundary_mesh();
  for (int k = 0; k < multipliers.n_segments(); ++k)
    if (zone < 0 || boundary.zone_of_segment(k) == zone)
      force += pressure(multipliers.first_dof(k)) * (boundary.segment_end(k) - boundary.segment_begin(k));
  return force;
}

ElasticBoundarySamples sample_elastic_boundary(const contact::ElasticContactSetup& setup,
                                               const contact::ElasticContactSolution& solution, int per_interval) {
  const auto& ops = *setup.operators;
  const auto& contact = ops.contact();
  const space::MultiplierSpace multipliers(*setup.boundary_mesh, setup.segment_degrees);
  const auto intervals = assembly::common_intervals(contact, *setup.boundary_mesh);
  const auto points = sample_points(contact, intervals, per_interval);
  // u at the points from the ranks holding their cells (trace-sized, then the same on every rank)
  const Eigen::MatrixXd u_at =
      values_at(assembly::vector_field(ops.vector_space(), solution.u, solution.u_rows, solution.lift), points,
                ops.distribution());
  ElasticBoundarySamples out{
      io::CsvTable({"x", "y", "s_arc", "u_n", "u_t", "gap", "pressure", "traction_t", "zone"}), 0.0, 0.0, {}, {}};
  out.total_force = total_force(multipliers, solution.pressure);
  out.zone_contact_set_length.assign(contact.zones().size(), 0.0);
  for (std::size_t z = 0; z < contact.zones().size(); ++z)
    out.zone_total_force.push_back(total_force(multipliers, solution.pressure, static_cast<int>(z)));
  const double pressure_scale = solution.pressure.cwiseAbs().maxCoeff();
  Eigen::Index point = 0;
  for (const auto& interval : intervals) {
    const auto& trace = contact.edges()[interval.trace_edge];
    const int k = interval.segment, first = multipliers.first_dof(k), n_modes = multipliers.segment_degree(k) + 1;
    int in_contact = 0;
    for (int j = 0; j < per_interval; ++j, ++point) {
      const double s = sample_arc(interval, j, per_interval);
      const Eigen::Vector2d u = u_at.row(point).transpose();
      const mesh::Point x = contact.point_at(s);
      const mesh::Point normal = assembly::trace_direction(contact, s, assembly::TraceDirection::normal);
      const mesh::Point tangent = assembly::trace_direction(contact, s, assembly::TraceDirection::tangent);
      const Eigen::VectorXd basis = multipliers.basis_values(k, multipliers.local_coordinate(k, s));
      const double pressure = basis.dot(solution.pressure.segment(first, n_modes));
      const double shear = basis.dot(solution.shear.segment(first, n_modes));
      out.table.add_row({x.x(), x.y(), s, u.dot(normal), u.dot(tangent), setup.gap(x) - u.dot(normal), pressure, shear,
                         static_cast<long long>(trace.zone)});
      if (pressure > 1e-10 * pressure_scale) ++in_contact;
    }
    const double in_contact_length = (interval.s_end - interval.s_begin) * in_contact / per_interval;
    out.contact_set_length += in_contact_length;
    out.zone_contact_set_length[trace.zone] += in_contact_length;
  }
  return out;
}

}  // namespace hpcontact::postprocess
