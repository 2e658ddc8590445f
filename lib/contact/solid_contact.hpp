// The paper's scalar contact problems (9), (13), (15) on a hexahedral mesh with a flat Γ_C and a
// surface multiplier mesh T_{C,H}, condensed onto Γ_C as in 2-D:
//     [K  Bᵀ] [u]   [F]
//     [B  0 ] [λ] ≤ [G]   (complementarity on the multiplier's constraint set)
// With u = K⁻¹(F − Bᵀλ) the multiplier solves min ½ λᵀ S λ − λᵀ d, S = B K⁻¹ Bᵀ (dense, from the
// trailing block of the condensed factor, or applied by products: contact/solid_trace_qp.hpp),
// d = B K⁻¹ F − G. Multipliers are nodal at the tensor
// Chebyshev–Lobatto points, so the constraints are bounds on the coefficients.
#pragma once

#include <Eigen/Core>

#include "assembly/solid_load.hpp"
#include "contact/box_qp.hpp"
#include "contact/contact_problem.hpp"
#include "contact/inequality_qp.hpp"
#include "contact/qp_report.hpp"
#include "contact/trace_operator.hpp"
#include "linalg/distribution.hpp"
#include "space/solid_space.hpp"
#include "space/surface_multiplier_space.hpp"

namespace hpcontact::contact {

struct SolidContactSetup {
  const space::SolidH1Space* space = nullptr;
  const space::SurfaceMultiplierSpace* multipliers = nullptr;
  ContactProblem problem = ContactProblem::signorini;
  assembly::SolidFunction f;         ///< volume load
  assembly::SolidFunction obstacle;  ///< g: (9) only
  assembly::SolidFunction bound;     ///< s ≥ 0: (13) and (15)
  BoxQpOptions qp;
  InequalityQpOptions interior_point;
  SchurPath trace_solve = SchurPath::automatic;  ///< S dense or by products (trace_operator.hpp)
  /// K factorized over these ranks (each eliminates its part of the box; every rank makes the same
  /// calls and receives the whole solution), or serial
  linalg::Distribution distribution;
};

/// Wall time of a 3-D contact solve's phases (seconds).
struct SolidSolveSeconds {
  double assembly = 0.0;       ///< F, B, G, the bounds
  double factorization = 0.0;  ///< K by static condensation, the trace last
  double condensation = 0.0;   ///< S = B K⁻¹ Bᵀ (dense path) and d
  double qp = 0.0;             ///< the multiplier problem
  double recovery = 0.0;       ///< u, the gap, the energy
};

struct SolidContactSolution {
  Eigen::VectorXd u;             ///< coefficients on the space
  Eigen::VectorXd lambda;        ///< λ at the nodal points of SurfaceMultiplierSpace
  Eigen::VectorXd lower, upper;  ///< the bounds of λ
  /// (ℓ_i, γ_C u − g) (9), (ℓ_i, s γ_C u) (13) or (ℓ_i, γ_C u) (15): the dual gradient −(Sλ − d).
  Eigen::VectorXd gap;
  double energy = 0.0;  ///< ½ a(u, u) − F(u)
  int n_trace = 0;      ///< trace dofs ordered last in the factor
  QpReport qp;
  SolidSolveSeconds seconds;
};

/// @throws InputError for missing data or s < 0 at a nodal point; NumericalError if the QP fails.
SolidContactSolution solve_solid_contact(const SolidContactSetup& setup);

}  // namespace hpcontact::contact
