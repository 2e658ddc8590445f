// Coupling assembly interval by interval of the common refinement.
#include "assembly/coupling.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>

#include "assembly/cell_values.hpp"
#include "basis/quadrature.hpp"
#include "core/error.hpp"

namespace hpcontact::assembly {

void check_multiplier_mesh(const mesh::ContactBoundary& contact, const mesh::BoundaryMesh& boundary_mesh) {
  if (std::abs(boundary_mesh.length() - contact.length()) > 1e-10 * contact.length())
    throw InputError("the boundary mesh T_{C,H} spans [0, " + std::to_string(boundary_mesh.length()) +
                     "] but Γ_C has length " + std::to_string(contact.length()));
  // Multipliers are discontinuous, but no segment may join two zones of Γ_C; and the zones the
  // H^{-1/2} Gram matrices are built from must be Γ_C's.
  const auto& zones = boundary_mesh.zones();
  bool same = zones.size() == contact.zones().size();
  for (std::size_t z = 0; same && z < zones.size(); ++z)
    same = std::abs(zones[z].end - contact.zones()[z].s_end) <= 1e-10 * contact.length() &&
           zones[z].closed == contact.zones()[z].closed;
  if (!same)
    throw InputError("the boundary mesh T_{C,H} does not break at the ends of the " +
                     std::to_string(contact.zones().size()) + " zones of Γ_C (or disagrees on which are closed)");
}

std::vector<CommonInterval> common_intervals(const mesh::ContactBoundary& contact,
                                             const mesh::BoundaryMesh& boundary_mesh) {
  check_multiplier_mesh(contact, boundary_mesh);
  const auto nodes = mesh::common_refinement(contact.breakpoints(), boundary_mesh.nodes());
  std::vector<CommonInterval> intervals;
  for (std::size_t k = 0; k + 1 < nodes.size(); ++k) {
    const double middle = 0.5 * (nodes[k] + nodes[k + 1]);
    intervals.push_back({nodes[k], nodes[k + 1], contact.edge_index_at(middle), boundary_mesh.segment_at(middle)});
  }
  return intervals;
}

namespace {

// ∫ μ_i φ_j w ds over one interval of the common refinement: shape (p_C + 1, n_shapes) in the
// order of the trace cell's shapes; w(s, x) = 1 when not given.
using ArcWeight = std::function<double(double s, const mesh::Point& x)>;
Eigen::MatrixXd interval_coupling(const space::H1Space& space, const mesh::ContactBoundary& contact,
                                  const space::MultiplierSpace& multipliers, const CommonInterval& interval,
                                  const ArcWeight& weight) {
  const auto& trace = contact.edges()[interval.trace_edge];
  const int p = space.cell_degree(trace.cell), pc = multipliers.segment_degree(interval.segment);
  // On straight edges φ_j|edge has degree p in s and μ_i degree p_C: exact for p + p_C. Along a
  // curved edge t(s) is not polynomial: 8 more points.
  const int n_points = basis::gauss_points_for_degree(p + pc) + (weight ? 4 : 0) + (trace.arc ? 8 : 0);
  const auto& rule = basis::gauss_legendre(n_points);
  const double half = 0.5 * (interval.s_end - interval.s_begin);
  std::vector<double> t(n_points), s(n_points);
  for (int q = 0; q < n_points; ++q) {
    s[q] = interval.s_begin + half * (rule.points[q] + 1.0);
    t[q] = trace.local_parameter(s[q]);
  }
  const CellValues cell =
      tabulate_cell(space, trace.cell, edge_reference_points(space.mesh().cell_type(trace.cell), trace.local_edge, t));
  Eigen::MatrixXd mu(n_points, pc + 1);
  for (int q = 0; q < n_points; ++q) {
    double w = rule.weights[q] * half;
    if (weight) w *= weight(s[q], mesh::Point(cell.points(q, 0), cell.points(q, 1)));
    mu.row(q) =
        w *
        multipliers.basis_values(interval.segment, multipliers.local_coordinate(interval.segment, s[q])).transpose();
  }
  return mu.transpose() * cell.values;
}

}  // namespace

void add_cell_coupling(std::vector<Eigen::Triplet<double>>& triplets, const Eigen::MatrixXd& local,
                       std::span<const space::LocalShape> shapes, int first_multiplier) {
  for (std::size_t j = 0; j < shapes.size(); ++j) {
    if (shapes[j].dof < 0) continue;
    for (int i = 0; i < local.rows(); ++i)
      if (local(i, j) != 0.0) triplets.emplace_back(first_multiplier + i, shapes[j].dof, local(i, j));
  }
}

const BoundaryFunction& CouplingWeight::function() const {
  static const BoundaryFunction none;
  return function_ ? *function_ : none;
}

std::string CouplingWeight::identity() const {
  if (!*this) return "";
  return key_.empty() ? fmt::format("@{}", static_cast<const void*>(function_.get())) : key_;
}

linalg::Coupling assemble_coupling(const space::H1Space& space, const mesh::ContactBoundary& contact,
                                   const space::MultiplierSpace& multipliers, const BoundaryFunction& weight) {
  std::vector<Eigen::Triplet<double>> triplets;
  for (const auto& interval : common_intervals(contact, multipliers.boundary_mesh())) {
    const ArcWeight arc_weight =
        weight ? ArcWeight([&](double, const mesh::Point& x) { return weight(x); }) : ArcWeight();
    const Eigen::MatrixXd local = interval_coupling(space, contact, multipliers, interval, arc_weight);
    add_cell_coupling(triplets, local, space.cell_shapes(contact.edges()[interval.trace_edge].cell),
                      multipliers.first_dof(interval.segment));
  }
  linalg::Coupling coupling(multipliers.n_dofs(), space.n_dofs());
  coupling.setFromTriplets(triplets.begin(), triplets.end());
  return coupling;
}

mesh::Point trace_direction(const mesh::ContactBoundary& contact, double s, TraceDirection direction) {
  return direction == TraceDirection::normal ? contact.normal_at(s) : contact.tangent_at(s);
}

linalg::Coupling assemble_directional_coupling(const space::VectorSpace& space, const mesh::ContactBoundary& contact,
                                               const space::MultiplierSpace& multipliers, TraceDirection direction) {
  std::vector<Eigen::Triplet<double>> triplets;
  for (const auto& interval : common_intervals(contact, multipliers.boundary_mesh())) {
    // Straight edges: d is constant, one scalar coupling times d_c; curved: d_c weighs each point.
    std::array<Eigen::MatrixXd, space::kComponents> local;
    if (contact.edges()[interval.trace_edge].arc) {
      for (int c = 0; c < space::kComponents; ++c)
        local[c] = interval_coupling(space.scalar(), contact, multipliers, interval, [&](double s, const mesh::Point&) {
          return trace_direction(contact, s, direction)(c);
        });
    } else {
      const Eigen::MatrixXd scalar = interval_coupling(space.scalar(), contact, multipliers, interval, {});
      const mesh::Point d = trace_direction(contact, 0.5 * (interval.s_begin + interval.s_end), direction);
      for (int c = 0; c < space::kComponents; ++c) local[c] = scalar * d(c);
    }
    const auto& shapes = space.scalar().cell_shapes(contact.edges()[interval.trace_edge].cell);
    const int first = multipliers.first_dof(interval.segment);
    for (std::size_t j = 0; j < shapes.size(); ++j) {
      if (shapes[j].dof < 0) continue;
      for (int c = 0; c < space::kComponents; ++c) {
        const int column = space.dof(shapes[j].dof, c);
        for (int i = 0; column >= 0 && i < local[c].rows(); ++i)
          if (local[c](i, j) != 0.0) triplets.emplace_back(first + i, column, local[c](i, j));
      }
    }
  }
  linalg::Coupling coupling(multipliers.n_dofs(), space.n_dofs());
  coupling.setFromTriplets(triplets.begin(), triplets.end());
  return coupling;
}

Eigen::VectorXd assemble_multiplier_load(const mesh::ContactBoundary& contact,
                                         const space::MultiplierSpace& multipliers, const BoundaryFunction& g) {
  return assemble_multiplier_load(contact, multipliers, [&](double s) { return g(contact.point_at(s)); });
}

Eigen::VectorXd assemble_multiplier_load(const mesh::ContactBoundary& contact,
                                         const space::MultiplierSpace& multipliers,
                                         const std::function<double(double)>& g_of_arc) {
  Eigen::VectorXd load = Eigen::VectorXd::Zero(multipliers.n_dofs());
  for (const auto& interval : common_intervals(contact, multipliers.boundary_mesh())) {
    const int pc = multipliers.segment_degree(interval.segment);
    const auto& rule = basis::gauss_legendre(basis::gauss_points_for_degree(pc) + 6 +
                                             (contact.edges()[interval.trace_edge].arc ? 8 : 0));
    const double half = 0.5 * (interval.s_end - interval.s_begin);
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const double s = interval.s_begin + half * (rule.points[q] + 1.0);
      const double tau = multipliers.local_coordinate(interval.segment, s);
      load.segment(multipliers.first_dof(interval.segment), pc + 1) +=
          rule.weights[q] * half * g_of_arc(s) * multipliers.basis_values(interval.segment, tau);
    }
  }
  return load;
}

}  // namespace hpcontact::assembly
