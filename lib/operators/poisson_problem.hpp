// The linear model problem behind the contact problems: -Δu = f in Ω, u = u_D (default 0) on Γ_D,
// ∂_n u = g on the rest of the boundary (Γ_N, and Γ_C when no contact is imposed).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <memory>

#include "assembly/dirichlet_lift.hpp"
#include "space/h1_space.hpp"

namespace hpcontact::operators {

struct PoissonData {
  std::function<double(const mesh::Point&)> f;
  /// Neumann data g(x, n) on every non-Dirichlet boundary edge; empty means g = 0.
  std::function<double(const mesh::Point& x, const mesh::Point& normal)> neumann;
  /// Dirichlet data u_D on Γ_D; empty means u = 0 there.
  std::function<double(const mesh::Point&)> dirichlet;
};

struct PoissonSolution {
  Eigen::VectorXd coefficients;  ///< shape (space.n_dofs()): u itself, or u_0 with Dirichlet data
  /// With Dirichlet data: the lift w, u = u_0 + w (assembly::total_field gives u).
  std::shared_ptr<const assembly::DirichletLift> lift;
  double assembly_seconds = 0.0;
  double solve_seconds = 0.0;  ///< sparse Cholesky factorization + solve
};

/// Assembles K and the load, factorizes K (CHOLMOD) and solves.
/// @throws NumericalError if K is not positive definite (e.g. Γ_D empty).
PoissonSolution solve_poisson(const space::H1Space& space, const PoissonData& data);

}  // namespace hpcontact::operators
