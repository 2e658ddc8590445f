// The linear model problem behind the contact problems: -Δu = f in Ω, u = 0 on Γ_D,
// ∂_n u = g on the rest of the boundary (Γ_N, and Γ_C when no contact is imposed).
#pragma once

#include <Eigen/Core>
#include <functional>

#include "space/h1_space.hpp"

namespace hpcontact::operators {

struct PoissonData {
  std::function<double(const mesh::Point&)> f;
  /// Neumann data g(x, n) on every non-Dirichlet boundary edge; empty means g = 0.
  std::function<double(const mesh::Point& x, const mesh::Point& normal)> neumann;
};

struct PoissonSolution {
  Eigen::VectorXd coefficients;  ///< shape (space.n_dofs())
  double assembly_seconds = 0.0;
  double solve_seconds = 0.0;  ///< sparse Cholesky factorization + solve
};

/// Assembles K and the load, factorizes K (CHOLMOD) and solves.
/// @throws NumericalError if K is not positive definite (e.g. Γ_D empty).
PoissonSolution solve_poisson(const space::H1Space& space, const PoissonData& data);

}  // namespace hpcontact::operators
