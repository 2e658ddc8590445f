// sample_elastic_boundary and sample_pair_boundary: the multiplier sampled along Γ_C with the
// displacements of one body or of both bodies of a pair.
#include "postprocess/elastic_boundary_samples.hpp"

#include "assembly/cell_values.hpp"
#include "assembly/coupling.hpp"
#include "basis/quadrature.hpp"
#include "mesh/cell_map.hpp"
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

namespace {

// ∫ (−p n + σ_nt t) ds per zone: 16 Gauss points per interval of the common refinement integrate
// the multiplier (degree p_C ≤ 30 on a straight edge) exactly, n and t of a curved edge to
// round-off for the degrees in use.
std::vector<Eigen::Vector2d> zone_contact_forces(const mesh::ContactBoundary& contact,
                                                 const mesh::BoundaryMesh& boundary_mesh,
                                                 const space::MultiplierSpace& multipliers,
                                                 const contact::ElasticContactSolution& solution) {
  std::vector<Eigen::Vector2d> forces(contact.zones().size(), Eigen::Vector2d::Zero());
  const auto& rule = basis::gauss_legendre(16);
  for (const auto& interval : assembly::common_intervals(contact, boundary_mesh)) {
    const int k = interval.segment, first = multipliers.first_dof(k), n_modes = multipliers.segment_degree(k) + 1;
    const double half = 0.5 * (interval.s_end - interval.s_begin);
    Eigen::Vector2d& force = forces[static_cast<std::size_t>(contact.edges()[interval.trace_edge].zone)];
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const double s = interval.s_begin + half * (rule.points[q] + 1.0);
      const Eigen::VectorXd basis = multipliers.basis_values(k, multipliers.local_coordinate(k, s));
      const double pressure = basis.dot(solution.pressure.segment(first, n_modes));
      const double shear = basis.dot(solution.shear.segment(first, n_modes));
      force += rule.weights[q] * half *
               (-pressure * assembly::trace_direction(contact, s, assembly::TraceDirection::normal) +
                shear * assembly::trace_direction(contact, s, assembly::TraceDirection::tangent));
    }
  }
  return forces;
}

// One sample: where it is, and the multiplier there.
struct Sample {
  Eigen::Index point = 0;  ///< its index among sample_points
  double s = 0.0;
  mesh::Point x, normal, tangent;
  double pressure = 0.0, shear = 0.0;
};

// Samples every interval of the common refinement of T_h|Γ_C and T_{C,H}; `row` makes a sample's
// row of `columns`. The contact set length and the forces come from the pressure.
ElasticBoundarySamples sample_pressure(const contact::ElasticContactSetup& setup,
                                       const contact::ElasticContactSolution& solution,
                                       std::vector<std::string> columns, int per_interval,
                                       const std::function<std::vector<io::CsvCell>(const Sample&)>& row) {
  const auto& contact = setup.operators->contact();
  const space::MultiplierSpace multipliers(*setup.boundary_mesh, setup.segment_degrees);
  ElasticBoundarySamples out{
      io::CsvTable(std::move(columns)), 0.0, 0.0, 0.0, Eigen::Vector2d::Zero(), {}, {}, {}, {}, {}};
  std::vector<double> arcs, pressures;  // for the bound: pressure ≥ 0
  std::vector<int> zones;
  out.total_force = total_force(multipliers, solution.pressure);
  out.zone_contact_set_length.assign(contact.zones().size(), 0.0);
  out.tangential_force = total_force(multipliers, solution.shear);
  for (std::size_t z = 0; z < contact.zones().size(); ++z) {
    out.zone_total_force.push_back(total_force(multipliers, solution.pressure, static_cast<int>(z)));
    out.zone_tangential_force.push_back(total_force(multipliers, solution.shear, static_cast<int>(z)));
  }
  out.zone_contact_force = zone_contact_forces(contact, *setup.boundary_mesh, multipliers, solution);
  for (const auto& force : out.zone_contact_force) out.contact_force += force;
  const double pressure_scale = solution.pressure.cwiseAbs().maxCoeff();
  Sample sample;
  for (const auto& interval : assembly::common_intervals(contact, *setup.boundary_mesh)) {
    const auto& trace = contact.edges()[interval.trace_edge];
    const int k = interval.segment, first = multipliers.first_dof(k), n_modes = multipliers.segment_degree(k) + 1;
    int in_contact = 0;
    for (int j = 0; j < per_interval; ++j, ++sample.point) {
      sample.s = sample_arc(interval, j, per_interval);
      sample.x = contact.point_at(sample.s);
      sample.normal = assembly::trace_direction(contact, sample.s, assembly::TraceDirection::normal);
      sample.tangent = assembly::trace_direction(contact, sample.s, assembly::TraceDirection::tangent);
      const Eigen::VectorXd basis = multipliers.basis_values(k, multipliers.local_coordinate(k, sample.s));
      sample.pressure = basis.dot(solution.pressure.segment(first, n_modes));
      sample.shear = basis.dot(solution.shear.segment(first, n_modes));
      auto cells = row(sample);
      cells.emplace_back(static_cast<long long>(trace.zone));
      out.table.add_row(std::move(cells));
      if (sample.pressure > 1e-10 * pressure_scale) ++in_contact;
      arcs.push_back(sample.s), pressures.push_back(sample.pressure), zones.push_back(trace.zone);
    }
    const double in_contact_length = (interval.s_end - interval.s_begin) * in_contact / per_interval;
    out.contact_set_length += in_contact_length;
    out.zone_contact_set_length[trace.zone] += in_contact_length;
  }
  out.bounds = bound_violation(arcs, zones, pressures, [](std::size_t) {
    return std::pair{0.0, std::numeric_limits<double>::infinity()};
  });
  out.bounds.at = contact.point_at(out.bounds.s);
  return out;
}

}  // namespace

ElasticBoundarySamples sample_elastic_boundary(const contact::ElasticContactSetup& setup,
                                               const contact::ElasticContactSolution& solution, int per_interval) {
  const auto& ops = *setup.operators;
  const auto& contact = ops.contact();
  const auto points = sample_points(contact, assembly::common_intervals(contact, *setup.boundary_mesh), per_interval);
  // u at the points from the ranks holding their cells (trace-sized, then the same on every rank)
  const auto u = assembly::vector_field(ops.vector_space(), solution.u, solution.u_rows, solution.lift);
  const Eigen::MatrixXd u_at = values_at(u, points, ops.distribution());
  // σ(u_h) from the cell beside Γ_C: the discrete stress, beside the multiplier's −σ_nn and σ_nt.
  const Eigen::MatrixXd sigma = stresses_at(u, ops.materials(), points, ops.distribution());
  return sample_pressure(setup, solution,
                         {"x", "y", "s_arc", "u_n", "u_t", "gap", "pressure", "traction_t", "sigma_xx", "sigma_yy",
                          "sigma_zz", "sigma_xy", "zone"},
                         per_interval, [&](const Sample& at) -> std::vector<io::CsvCell> {
                           const Eigen::Vector2d u = u_at.row(at.point).transpose();
                           const auto s = sigma.row(at.point);
                           return {at.x.x(),
                                   at.x.y(),
                                   at.s,
                                   u.dot(at.normal),
                                   u.dot(at.tangent),
                                   setup.gap(at.x) - u.dot(at.normal),
                                   at.pressure,
                                   at.shear,
                                   s(0),
                                   s(1),
                                   s(2),
                                   s(3)};
                         });
}

ElasticBoundarySamples sample_pair_boundary(const contact::TwoBodyContactSetup& setup,
                                            const contact::TwoBodyContactSolution& solution,
                                            const mesh::MasterProjection& projection, int per_interval) {
  const auto& slave_ops = *setup.slave.operators;
  const auto& master_ops = *setup.master.operators;
  const auto& contact = slave_ops.contact();
  const auto points =
      sample_points(contact, assembly::common_intervals(contact, *setup.slave.boundary_mesh), per_interval);
  const Eigen::MatrixXd slave_u = values_at(assembly::vector_field(slave_ops.vector_space(), solution.contact.u,
                                                                   solution.contact.u_rows, solution.contact.lift),
                                            points, slave_ops.distribution());
  // The master's displacement at Φ(x) of each sample: its point in the master's cells.
  // Φ(x) as a point of the master cell beneath its edge (from the edge parameter: a point search
  // by cell boxes can miss a curved edge), and the gap g = (Φ(x) − x)·n_s from the same projection.
  const auto& master_edges = master_ops.contact().edges();
  std::vector<CellPoint> images;
  std::vector<mesh::Point> offsets;  // Φ(x) − x
  for (const auto& point : points) {
    const mesh::Point x = mesh::CellMap(slave_ops.mesh(), point.cell).map(point.xi, point.eta);
    const auto image = projection.project(x);
    const auto& edge = master_edges[image.edge];
    const auto reference =
        assembly::edge_reference_points(master_ops.mesh().cell_type(edge.cell), edge.local_edge, {image.t});
    images.push_back({edge.cell, reference.xi.front(), reference.eta.front()});
    offsets.push_back(image.point - x);
  }
  const Eigen::MatrixXd master_u = values_at(assembly::vector_field(master_ops.vector_space(), solution.master.u,
                                                                    solution.master.u_rows, solution.master.lift),
                                             images, master_ops.distribution());
  return sample_pressure(setup.slave, solution.contact,
                         {"x", "y", "s_arc", "gap", "pressure", "traction_t", "u_n_slave", "u_n_master", "zone"},
                         per_interval, [&](const Sample& at) -> std::vector<io::CsvCell> {
                           const double u_n_slave = slave_u.row(at.point).dot(at.normal.transpose());
                           const double u_n_master = master_u.row(at.point).dot(at.normal.transpose());
                           const double gap = offsets[static_cast<std::size_t>(at.point)].dot(at.normal);
                           return {at.x.x(),    at.x.y(), at.s,      gap - (u_n_slave - u_n_master),
                                   at.pressure, at.shear, u_n_slave, u_n_master};
                         });
}

}  // namespace hpcontact::postprocess
