// Frictionless contact on an iterative K without S: the primal–dual active set (semi-smooth
// Newton) on the saddle point
//     K u + B_Aᵀ P_A = F,   B_A u = G_A,   P = 0 off A,
// each step a constrained solve (linalg/constrained_solver.hpp: K's CG projected onto the active
// rows), warm-started from the previous step. The active set is then A' = {i ∈ A : P_i ≥ 0} ∪
// {i ∉ A : (G − B u)_i < 0}; the steps are solved loosely until the set settles, then ever more
// tightly (each tolerance confirming the set the looser one decided), so that contact costs a few
// linear solves however many multipliers Γ_C carries.
#pragma once

#include <Eigen/Core>

#include "contact/qp_report.hpp"
#include "linalg/constrained_solver.hpp"
#include "linalg/coupling_matrix.hpp"

namespace hpcontact::contact {

struct ActiveSetContactOptions {
  /// The relative tolerance of the first steps, while the set changes; each settled set is then
  /// solved 1e-3 tighter, down to the solver's own (ConstrainedSolver::relative_tolerance). On the
  /// elastic cube of the 3-D benchmark (n = 12) 1e-1, 1e-2 and 1e-3 took 230, 148 and 181 CG
  /// iterations in all.
  double loose_tolerance = 1e-2;
  int max_steps = 60;
};

struct ActiveSetContactSolution {
  Eigen::VectorXd u;
  Eigen::VectorXd pressure;  ///< P at the m constraint rows (0 off the active set)
  QpReport report;           ///< method "primal-dual-active-set", trace_operator "saddle_point"
};

/// min ½ uᵀ K u − Fᵀ u over B u ≤ G (B: m × n, the coupling of u·n with the pressure's nodal
/// functions), from the active set {G < 0} and u = 0. The report's products are CG's iterations,
/// its KKT residual the largest of CG's relative residual, max(−P)/max P and max(B u − G)/max|G|.
/// @throws NumericalError if the set has not settled in max_steps or a solve fails.
ActiveSetContactSolution solve_active_set_contact(linalg::ConstrainedSolver& solver, const linalg::Coupling& b,
                                                  const Eigen::VectorXd& load, const Eigen::VectorXd& g,
                                                  const ActiveSetContactOptions& options = {});

}  // namespace hpcontact::contact
