// S = B K⁻¹ Bᵀ of a trace coupling B as products by one skeleton solve each (no dense S, no
// trailing block in the factor).
#pragma once

#include "assembly/condensed_factor.hpp"
#include "contact/trace_operator.hpp"
#include "linalg/coupling_matrix.hpp"

namespace hpcontact::contact {

/// x ↦ B K⁻¹ Bᵀ x for `factor` of K and B (m, n) with no interior columns (a trace coupling).
/// The operator refers to `factor`, which must outlive it.
/// @throws NumericalError (internal) if B has interior columns.
TraceOperator schur_products(const assembly::CondensedFactor& factor, const linalg::Coupling& b);

}  // namespace hpcontact::contact
