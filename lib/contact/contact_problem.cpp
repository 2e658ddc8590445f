// solve_contact: assemble, condense onto Γ_C in a nodal multiplier basis, solve the box QP,
// recover u.
#include "contact/contact_problem.hpp"

#include <Eigen/LU>
#include <cmath>
#include <numbers>

#include "assembly/coupling.hpp"
#include "assembly/poisson_assembly.hpp"
#include "basis/lobatto.hpp"
#include "basis/quadrature.hpp"
#include "core/error.hpp"
#include "core/timer.hpp"
#include "linalg/schur_complement.hpp"
#include "mesh/contact_boundary.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::contact {

std::vector<double> constraint_points(int q) {
  HPC_VERIFY(q >= 1, "at least one constraint point");
  if (q == 1) return {0.0};
  std::vector<double> points(q);
  for (int k = 0; k < q; ++k) points[k] = -std::cos(std::numbers::pi * k / (q - 1));
  return points;
}

ContactSolution solve_contact(const ContactSetup& setup) {
  HPC_VERIFY(setup.mesh && setup.boundary_mesh, "contact setup without meshes");
  const bool signorini = setup.problem == ContactProblem::signorini;
  if (!setup.f) throw InputError("contact problem: the volume load f is missing");
  if (signorini && !setup.obstacle) throw InputError("Signorini problem: the obstacle g is missing");
  if (!signorini && !setup.bound) throw InputError("friction problem: the friction bound s is missing");

  Stopwatch setup_clock;
  const space::H1Space space(*setup.mesh, setup.cell_degrees);
  const mesh::ContactBoundary contact(*setup.mesh);
  const space::MultiplierSpace multipliers(*setup.boundary_mesh, setup.segment_degrees);
  const auto stiffness = assembly::assemble_volume_matrices(space, {.stiffness = true, .mass = false}).stiffness;
  Eigen::VectorXd load = assembly::assemble_volume_load(space, setup.f);
  if (setup.traction)
    load += assembly::assemble_boundary_load(
        space, {mesh::BoundaryPart::neumann, mesh::BoundaryPart::contact}, setup.traction);
  const bool weighted = setup.problem == ContactProblem::friction;
  const Eigen::SparseMatrix<double> coupling_legendre = assembly::assemble_coupling(
      space, contact, multipliers, weighted ? setup.bound : assembly::BoundaryFunction{});

  // Legendre → Lagrange at the constraint points, segment by segment: c_nodal = V c_legendre with
  // V_ik = P_k(τ_i), so the nodal basis functions are ℓ = V⁻ᵀ P and B_nodal = V⁻ᵀ B_legendre.
  const int n = multipliers.n_dofs();
  Eigen::MatrixXd to_nodal = Eigen::MatrixXd::Zero(n, n);  // block diagonal V⁻ᵀ
  ContactSolution out;
  out.lower = Eigen::VectorXd::Constant(n, -std::numeric_limits<double>::infinity());
  out.upper = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::infinity());
  out.constraint_s.resize(n);
  for (int k = 0; k < multipliers.n_segments(); ++k) {
    const int q = multipliers.segment_degree(k) + 1, first = multipliers.first_dof(k);
    const auto tau = constraint_points(q);
    Eigen::MatrixXd v(q, q);
    for (int i = 0; i < q; ++i) v.row(i) = basis::legendre_values(q - 1, tau[i]).transpose();
    to_nodal.block(first, first, q, q) = v.inverse().transpose();
    const double a = setup.boundary_mesh->segment_begin(k), b = setup.boundary_mesh->segment_end(k);
    // (13) keeps λ = 0 only on segments outside supp s (a closed set: s vanishing at single
    // points, like (1-x)² at x = 1, does not remove them).
    bool meets_support = false;
    if (setup.problem == ContactProblem::friction)
      for (double t : basis::gauss_legendre(12).points)
        meets_support = meets_support || setup.bound(contact.point_at(a + 0.5 * (b - a) * (t + 1.0))) > 0.0;
    for (int i = 0; i < q; ++i) {
      const double s = a + 0.5 * (b - a) * (tau[i] + 1.0);
      out.constraint_s[first + i] = s;
      if (signorini) {
        out.upper(first + i) = 0.0;
        continue;
      }
      const double bound = setup.bound(contact.point_at(s));
      if (bound < 0.0)
        throw InputError("friction bound s = " + std::to_string(bound) + " < 0 at x = " +
                         std::to_string(contact.point_at(s).x()) + ": s must be >= 0");
      // (13): |λ| ≤ 1 on supp s, λ = 0 off it; (15): |λ| ≤ s.
      const double limit = setup.problem == ContactProblem::friction ? (meets_support ? 1.0 : 0.0) : bound;
      out.lower(first + i) = -limit;
      out.upper(first + i) = limit;
    }
  }
  const Eigen::SparseMatrix<double> to_nodal_sparse = to_nodal.sparseView();
  const Eigen::SparseMatrix<double> coupling = (to_nodal_sparse * coupling_legendre).pruned();
  Eigen::VectorXd gap_offset = Eigen::VectorXd::Zero(n);
  if (signorini) gap_offset = to_nodal * assembly::assemble_multiplier_load(contact, multipliers, setup.obstacle);

  const linalg::SparseCholesky k_factor(stiffness);
  const Eigen::VectorXd u_free = k_factor.solve(load);
  const Eigen::MatrixXd s = linalg::schur_complement(k_factor, coupling);
  const Eigen::VectorXd d = coupling * u_free - gap_offset;
  out.seconds_setup = setup_clock.seconds();

  Stopwatch qp_clock;
  out.qp = solve_box_qp(s, d, out.lower, out.upper, setup.qp);
  out.seconds_qp = qp_clock.seconds();
  out.lambda = out.qp.x;
  out.lambda_legendre = to_nodal.transpose() * out.lambda;  // V⁻¹ c_nodal
  const Eigen::VectorXd reduced_load = load - coupling.transpose() * out.lambda;
  out.u = k_factor.solve(reduced_load);
  out.gap = coupling * out.u - gap_offset;
  out.energy = 0.5 * out.u.dot(stiffness * out.u) - load.dot(out.u);
  return out;
}

}  // namespace hpcontact::contact
