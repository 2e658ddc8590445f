// Nodal multiplier basis and constraint rows, segment by segment.
#include "contact/multiplier_constraints.hpp"

#include <fmt/format.h>

#include <Eigen/LU>
#include <limits>
#include <tuple>
#include <utility>

#include "basis/lobatto.hpp"
#include "basis/quadrature.hpp"
#include "core/error.hpp"
#include "space/multiplier_family.hpp"

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

// The bounds (lower, upper) of λ at the point s of Γ_C: λ ≤ 0 for (9); for (13) |λ| ≤ 1 where
// the support of λ there meets supp s (`in_support`), λ = 0 elsewhere; |λ| ≤ s(x) for (15).
std::pair<double, double> bounds_at(const ContactSetup& setup, const mesh::ContactBoundary& contact, double s,
                                    bool in_support) {
  if (setup.problem == ContactProblem::signorini) return {-std::numeric_limits<double>::infinity(), 0.0};
  const double bound = setup.bound(contact.point_at(s));
  if (!(bound >= 0.0))
    throw InputError(
        fmt::format("friction bound s = {} at x = {}: s must be >= 0 (and finite)", bound, contact.point_at(s).x()));
  const double limit = setup.problem == ContactProblem::friction ? (in_support ? 1.0 : 0.0) : bound;
  return {-limit, limit};
}

SegmentConstraints segment_constraints(const ContactSetup& setup, const mesh::ContactBoundary& contact, int pc, int q,
                                       const Eigen::MatrixXd& v_inverse, double a, double b) {
  SegmentConstraints segment;
  const auto tau = constraint_points(q);
  segment.rows.resize(q, pc + 1);
  // ℓ_i(τ_j) = Σ_m P_m(τ_j) (V⁻¹)_mi; at the nodal points exactly the identity.
  for (int j = 0; j < q; ++j) segment.rows.row(j) = basis::legendre_values(pc, tau[j]).transpose() * v_inverse;
  if (q == pc + 1) segment.rows.setIdentity();
  const bool in_support = setup.problem == ContactProblem::friction && meets_support(setup, contact, a, b);
  for (int j = 0; j < q; ++j) {
    const double s = a + 0.5 * (b - a) * (tau[j] + 1.0);
    segment.s.push_back(s);
    const auto [lower, upper] = bounds_at(setup, contact, s, in_support);
    segment.lower.push_back(lower);
    segment.upper.push_back(upper);
  }
  return segment;
}

// A standard or dual family: its functions are the basis (to_nodal = Tᵀ, so that B_family = Tᵀ B
// and λ_legendre = T c), and the bounds act on their coefficients at their nodes.
MultiplierConstraints family_constraints(const ContactSetup& setup, const space::MultiplierSpace& multipliers,
                                         const mesh::ContactBoundary& contact) {
  if (!setup.constraint_points.empty())
    throw InputError(
        fmt::format("constraint points are set for the multiplier family {}, whose constraints act on "
                    "its coefficients at its nodes: leave constraint_points out",
                    space::to_string(setup.family)));
  const space::FamilyBasis family = space::family_basis(multipliers, setup.family);
  MultiplierConstraints out;
  out.to_nodal = Eigen::MatrixXd(family.legendre.transpose());
  const int n = family.n_functions();
  out.matrix = Eigen::MatrixXd::Identity(n, n);
  out.lower.resize(n);
  out.upper.resize(n);
  const auto& mesh = multipliers.boundary_mesh();
  for (int i = 0; i < n; ++i) {
    const double s = family.node_s[static_cast<std::size_t>(i)];
    out.s.push_back(s);
    // (13): the function's support is its segments.
    bool in_support = false;
    if (setup.problem == ContactProblem::friction)
      for (int k : family.segments[static_cast<std::size_t>(i)])
        in_support = in_support || meets_support(setup, contact, mesh.segment_begin(k), mesh.segment_end(k));
    std::tie(out.lower(i), out.upper(i)) = bounds_at(setup, contact, s, in_support);
  }
  return out;
}

}  // namespace

MultiplierConstraints build_multiplier_constraints(const ContactSetup& setup, const space::MultiplierSpace& multipliers,
                                                   const mesh::ContactBoundary& contact) {
  if (setup.family.kind != space::MultiplierFamilyKind::discontinuous)
    return family_constraints(setup, multipliers, contact);
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
