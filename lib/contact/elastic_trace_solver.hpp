// The condensed trace solver of elastic contact, shared by one body against a rigid obstacle
// (elastic_contact.hpp) and two bodies coupled by a mortar multiplier (two_body_contact.hpp).
// Each body k is factorized with its Γ_C trace last and enters only through the rows C_k of the
// multiplier's pairing with its traces, so that with A_k u_k = F_k − C_kᵀ λ
//     S = Σ_k C_k A_k⁻¹ C_kᵀ,   d = Σ_k C_k A_k⁻¹ F_k − offset,
// and the multiplier QP (contact_problem.hpp) is the same for one body and for two.
#pragma once

#include <Eigen/Core>
#include <array>
#include <functional>
#include <memory>
#include <vector>

#include "assembly/coupling.hpp"
#include "assembly/dirichlet_lift.hpp"
#include "assembly/elastic_load.hpp"
#include "contact/elastic_contact.hpp"
#include "operators/elastic_operators.hpp"
#include "space/multiplier_space.hpp"
#include "space/vector_space.hpp"

namespace hpcontact::contact {

/// One elastic body: its operators and its data.
struct ElasticBody {
  const operators::ElasticOperators* operators = nullptr;  ///< required
  assembly::VectorFunction body_force;                     ///< f (may be empty)
  assembly::TractionFunction traction;                     ///< t on Γ_N (may be empty)
  /// u_D,x and u_D,y wherever the component is fixed (Γ_D, rollers); empty: 0.
  std::array<PointFunction, space::kComponents> dirichlet;
};

/// The displacement of one body, as ElasticContactSolution holds it.
struct BodyDisplacement {
  Eigen::VectorXd u;  ///< u, or u_0 with Dirichlet data (u = u_0 + w), at the rows of u_rows
  assembly::LocalRows u_rows;
  int n_dofs = 0;
  std::shared_ptr<const assembly::DirichletLift> lift;  ///< null without Dirichlet data
  double energy = 0.0;                                  ///< ½ a(u, u) − F(u) of the body
};

/// ∫ μ_i φ_j d_c ds over the slave's Γ_C for one body: its own traces (the slave) or their images
/// under Φ (the master), d the slave's normal or tangent. `space` is the body's displacement
/// space or its lift's extended space (assembly::DirichletLift::extended_vector).
using TraceCoupling = std::function<linalg::Coupling(
    const space::VectorSpace& space, const space::MultiplierSpace& multipliers, assembly::TraceDirection direction)>;

/// A body of the condensed problem. The gap rows are ∫ μ g − Σ_k sign_k ∫ μ (u_k·n) ≥ 0 and the
/// tangential rows Σ_k sign_k ∫ μ (u_k·t) (sign +1 for the slave or the only body, −1 for the
/// master), n and t the slave's.
struct TraceBody {
  ElasticBody body;
  double sign = 1.0;
  TraceCoupling coupling;
};

/// The body of `setup` (sign +1), paired through its own traces on its Γ_C: the only body against
/// a rigid obstacle, or the slave of a pair.
TraceBody body_on_own_traces(const ElasticContactSetup& setup);

struct TraceSolve {
  /// The multiplier and its KKT data; u, u_rows, n_dofs and lift of the first body, energy the
  /// sum over the bodies.
  ElasticContactSolution contact;
  std::vector<BodyDisplacement> bodies;  ///< one per TraceBody, in their order
};

/// Solves `setup`'s problem (its T_{C,H}, segment degrees, constraint points, threshold, friction
/// coefficient and solver options; its operators those of the body whose Γ_C carries T_{C,H})
/// between `bodies`, with the gap `gap_of_arc`(s) along that Γ_C in place of setup.gap.
/// @throws InputError, NumericalError as solve_elastic_contact.
TraceSolve solve_on_trace(const ElasticContactSetup& setup, const std::function<double(double)>& gap_of_arc,
                          const std::vector<TraceBody>& bodies);

}  // namespace hpcontact::contact
