// sample_boundary: the sample points first, u at them from the ranks holding their cells, then
// the rows (trace-sized, the same on every rank).
#include "postprocess/boundary_samples.hpp"

#include <memory>

#include "assembly/cell_values.hpp"
#include "assembly/coupling.hpp"
#include "core/petsc_session.hpp"
#include "mesh/contact_boundary.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::postprocess {

std::vector<CellPoint> sample_points(const mesh::ContactBoundary& contact,
                                     const std::vector<assembly::CommonInterval>& intervals, int per_interval) {
  std::vector<CellPoint> points;
  for (const auto& interval : intervals) {
    const auto& trace = contact.edges()[interval.trace_edge];
    for (int j = 0; j < per_interval; ++j) {
      const Eigen::Vector2d ref = mesh::local_edge_point(contact.mesh().cell_type(trace.cell), trace.local_edge,
                                                         trace.local_parameter(sample_arc(interval, j, per_interval)));
      points.push_back({trace.cell, ref.x(), ref.y()});
    }
  }
  return points;
}

Eigen::MatrixXd values_at(const assembly::CellField& field, const std::vector<CellPoint>& points,
                          linalg::Distribution distribution) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(points.size()), field.components);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const auto& point = points[k];
    if (!field.rows.holds(point.cell)) continue;
    const auto values = assembly::tabulate_cell(*field.space, point.cell, {{point.xi}, {point.eta}});
    const Eigen::MatrixXd coefficients = field.coefficients(point.cell);
    // (shape by shape, in order: the sums of postprocess::evaluate, so serial samples keep their bits)
    for (Eigen::Index s = 0; s < coefficients.rows(); ++s)
      for (int c = 0; c < field.components; ++c)
        out(static_cast<Eigen::Index>(k), c) += coefficients(s, c) * values.values(0, s);
  }
  // (one rank holds each cell: the sum adds zeros to its value, exactly)
  if (distribution.distributed()) sum_over_ranks(distribution.ranks, out.data(), out.size());
  return out;
}

Eigen::MatrixXd stresses_at(const assembly::CellField& displacement, const std::vector<assembly::Material>& materials,
                            const std::vector<CellPoint>& points, linalg::Distribution distribution) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(points.size()), 4);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const auto& point = points[k];
    if (!displacement.rows.holds(point.cell)) continue;
    const auto values = assembly::tabulate_cell(*displacement.space, point.cell, {{point.xi}, {point.eta}});
    const Eigen::MatrixXd coefficients = displacement.coefficients(point.cell);
    const Eigen::RowVectorXd dx = values.grad_x.row(0) * coefficients, dy = values.grad_y.row(0) * coefficients;
    const auto s =
        assembly::plane_stress_of(materials[static_cast<std::size_t>(point.cell)], dx(0), dy(1), 0.5 * (dy(0) + dx(1)));
    for (int c = 0; c < 4; ++c) out(static_cast<Eigen::Index>(k), c) = s[static_cast<std::size_t>(c)];
  }
  if (distribution.distributed()) sum_over_ranks(distribution.ranks, out.data(), out.size());
  return out;
}

BoundarySamples sample_boundary(const contact::ContactSetup& setup, const contact::ContactSolution& solution,
                                int per_interval) {
  const bool signorini = setup.problem == contact::ContactProblem::signorini;
  std::unique_ptr<space::H1Space> own_space;
  if (!setup.primal) own_space = std::make_unique<space::H1Space>(*setup.mesh, setup.cell_degrees);
  const space::H1Space& space = setup.primal ? setup.primal->space() : *own_space;
  const linalg::Distribution distribution = setup.primal ? setup.primal->distribution() : linalg::Distribution{};
  // Γ_C of the space's mesh (a rank's part, distributed): its trace edges name the space's cells.
  std::unique_ptr<mesh::ContactBoundary> own_contact;
  if (!setup.primal) own_contact = std::make_unique<mesh::ContactBoundary>(*setup.mesh);
  const mesh::ContactBoundary& contact = setup.primal ? setup.primal->contact() : *own_contact;
  const space::MultiplierSpace multipliers(*setup.boundary_mesh, setup.segment_degrees);
  const auto intervals = assembly::common_intervals(contact, *setup.boundary_mesh);
  const auto points = sample_points(contact, intervals, per_interval);
  const Eigen::MatrixXd u =
      values_at(assembly::scalar_field(space, solution.u, solution.u_rows, solution.lift), points, distribution);

  BoundarySamples out{io::CsvTable({"x", "u", signorini ? "obstacle" : "s", "lambda", "y", "s_arc", "zone"}),
                      0.0,
                      std::vector<double>(contact.zones().size(), 0.0),
                      {}};
  std::vector<double> arcs, lambdas, limits;  // for the bounds: λ ≤ 0 (9), |λ| ≤ 1 (13), |λ| ≤ s (15)
  std::vector<int> zones;
  const double lambda_scale = solution.lambda.cwiseAbs().maxCoeff();
  Eigen::Index point = 0;
  for (const auto& interval : intervals) {
    const auto& trace = contact.edges()[interval.trace_edge];
    const int k = interval.segment;
    const auto coefficients =
        solution.lambda_legendre.segment(multipliers.first_dof(k), multipliers.segment_degree(k) + 1);
    int in_contact = 0;
    for (int j = 0; j < per_interval; ++j, ++point) {
      const double s = sample_arc(interval, j, per_interval);
      const mesh::Point x = contact.point_at(s);
      const double lambda = multipliers.basis_values(k, multipliers.local_coordinate(k, s)).dot(coefficients);
      const double data = signorini ? setup.obstacle(x) : setup.bound(x);
      out.table.add_row({x.x(), u(point, 0), data, lambda, x.y(), s, static_cast<long long>(trace.zone)});
      arcs.push_back(s), lambdas.push_back(lambda), zones.push_back(trace.zone);
      limits.push_back(setup.problem == contact::ContactProblem::friction ? 1.0 : data);
      if (std::abs(lambda) > 1e-10 * lambda_scale) ++in_contact;
    }
    const double in_contact_length = (interval.s_end - interval.s_begin) * in_contact / per_interval;
    out.contact_set_length += in_contact_length;
    out.zone_contact_set_length[trace.zone] += in_contact_length;
  }
  out.bounds = bound_violation(arcs, zones, lambdas, [&](std::size_t i) {
    return signorini ? std::pair{-std::numeric_limits<double>::infinity(), 0.0} : std::pair{-limits[i], limits[i]};
  });
  out.bounds.at = contact.point_at(out.bounds.s);
  return out;
}

}  // namespace hpcontact::postprocess
