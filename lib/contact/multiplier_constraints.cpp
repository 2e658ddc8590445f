// Nodal multiplier basis and constraint rows, segment by segment.
#include "contact/multiplier_constraints.hpp"

#include <fmt/format.h>

#include <Eigen/LU>
#include <limits>

#include "basis/lobatto.hpp"
#include "basis/quadrature.hpp"
#include "core/error.hpp"

namespace hpcontact::contact {
namespace {

// One segment's rows C_k (q × (p_C + 1)) and the bounds at its points.
struct SegmentConstraints {
  Eigen::MatrixXd rows;
  std::vector<double> s, lower, upper;
};

// (13) keeps λ = 0 only on segments outside supp s (a closed set: s vanishing at single points,
// like (1-x)² at x = 1, does not remove them).
bool meets_support(const ContactSetup& setup, const mesh::ContactBoundary& contact, double a, double b) {
  for (double t : basis::gauss_legendre(12).points)
    if (setup.bound(contact.point_at(a + 0.5 * (b - a) * (t + 1.0))) > 0.0) return true;
  return false;
}

SegmentConstraints segment_constraints(const ContactSetup& setup, const mesh::ContactBoundary& contact, int pc, int q,
                                       const Eigen::MatrixXd& v_inverse, double a, double b) {
  SegmentConstraints segment;
  const auto tau = constraint_points(q);
  segment.rows.resize(q, pc + 1);
  // ℓ_i(τ_j) = Σ_m P_m(τ_j) (V⁻¹)_mi; at the nodal points exactly the identity.
  for (int j = 0; j < q; ++j) segment.rows.row(j) = basis::legendre_values(pc, tau[j]).transpose() * v_inverse;
  if (q == pc + 1) segment.rows.setIdentity();
  const bool signorini = setup.problem == ContactProblem::signorini;
  const bool in_support = setup.problem == ContactProblem::friction && meets_support(setup, contact, a, b);
  for (int j = 0; j < q; ++j) {
    const double s = a + 0.5 * (b - a) * (tau[j] + 1.0);
    segment.s.push_back(s);
    if (signorini) {
      segment.lower.push_back(-std::numeric_limits<double>::infinity());
      segment.upper.push_back(0.0);
      continue;
    }
    const double bound = setup.bound(contact.point_at(s));
    if (!(bound >= 0.0))
      throw InputError(
          fmt::format("friction bound s = {} at x = {}: s must be >= 0 (and finite)", bound, contact.point_at(s).x()));
    // (13): |λ| ≤ 1 on supp s, λ = 0 off it; (15): |λ| ≤ s.
    const double limit = setup.problem == ContactProblem::friction ? (in_support ? 1.0 : 0.0) : bound;
    segment.lower.push_back(-limit);
    segment.upper.push_back(limit);
  }
  return segment;
}

}  // namespace

MultiplierConstraints build_multiplier_constraints(const ContactSetup& setup, const space::MultiplierSpace& multipliers,
                                                   const mesh::ContactBoundary& contact) {
  // Legendre → Lagrange at the nodal points, segment by segment: c_nodal = V c_legendre with
  // V_ik = P_k(τ_i), so the nodal basis functions are ℓ = V⁻ᵀ P and B_nodal = V⁻ᵀ B_legendre.
  const int n = multipliers.n_dofs();
  MultiplierConstraints out;
  out.to_nodal = Eigen::MatrixXd::Zero(n, n);
  std::vector<SegmentConstraints> segments;
  int n_rows = 0;
  for (int k = 0; k < multipliers.n_segments(); ++k) {
    const int pc = multipliers.segment_degree(k), first = multipliers.first_dof(k);
    const auto nodes = constraint_points(pc + 1);
    Eigen::MatrixXd v(pc + 1, pc + 1);
    for (int i = 0; i <= pc; ++i) v.row(i) = basis::legendre_values(pc, nodes[i]).transpose();
    const Eigen::MatrixXd v_inverse = v.inverse();
    out.to_nodal.block(first, first, pc + 1, pc + 1) = v_inverse.transpose();
    const int q = segment_constraint_points(
        setup.problem, pc, requested_constraint_points(setup.constraint_points, multipliers.boundary_mesh(), k));
    out.points_per_segment.push_back(q);
    out.bounds_only = out.bounds_only && q == pc + 1;
    segments.push_back(segment_constraints(setup, contact, pc, q, v_inverse, setup.boundary_mesh->segment_begin(k),
                                           setup.boundary_mesh->segment_end(k)));
    n_rows += q;
  }
  out.matrix = Eigen::MatrixXd::Zero(n_rows, n);
  out.lower.resize(n_rows);
  out.upper.resize(n_rows);
  for (int k = 0, row = 0; k < multipliers.n_segments(); ++k) {
    const auto& segment = segments[static_cast<std::size_t>(k)];
    const auto q = segment.rows.rows();
    out.matrix.block(row, multipliers.first_dof(k), q, segment.rows.cols()) = segment.rows;
    for (Eigen::Index j = 0; j < q; ++j, ++row) {
      out.lower(row) = segment.lower[static_cast<std::size_t>(j)];
      out.upper(row) = segment.upper[static_cast<std::size_t>(j)];
      out.s.push_back(segment.s[static_cast<std::size_t>(j)]);
    }
  }
  return out;
}

}  // namespace hpcontact::contact
