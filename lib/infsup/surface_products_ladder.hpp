// α of a 3-D pairing from products only: S_G x one solve with A_G's factor, G_ℓ x by the moments
// of the multipliers (norms/surface_gram_products.hpp), the ladder's levels climbed as the dense
// path climbs them (infsup_analysis.hpp: smallest_on_ladder), each level's eigenproblem started
// from the previous level's eigenvector.
#pragma once

#include <Eigen/SparseCore>

#include "contact/trace_operator.hpp"
#include "infsup/infsup_analysis.hpp"
#include "space/surface_multiplier_space.hpp"

namespace hpcontact::infsup {

/// The smallest eigenpair of (Rᵀ S R, Rᵀ diag(G_ℓ, …) R) (R = `basis`, `gram_copies` blocks of G_ℓ
/// on `multipliers`, a grid T_{C,H}) for ℓ = 1, 2, … until α's error estimate, α |√(xᵀG_ℓx /
/// xᵀG_{ℓ−1}x) − 1|, is below `tolerance` · α or the ladder ends. `s` is S on all multiplier
/// rows (gram_copies · n_dofs). LadderSolution::gram stays empty (G is never formed);
/// seconds_eigen includes the products.
LadderSolution smallest_on_products_ladder(const contact::TraceOperator& s, const Eigen::SparseMatrix<double>& basis,
                                           int gram_copies, const space::SurfaceMultiplierSpace& multipliers,
                                           double tolerance);

}  // namespace hpcontact::infsup
