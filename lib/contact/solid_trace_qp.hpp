// The multiplier problem of a 3-D solve on whichever path applies S = B K⁻¹ Bᵀ: dense (S from
// the factor's trailing block, the active-set method) or by products (MPRGP, FISTA; on a
// distributed factor run by its first rank alone, the others serving its products), so that the
// scalar and elastic solvers choose the path in one place.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "assembly/condensed_factor.hpp"
#include "contact/disc_qp.hpp"
#include "contact/multiplier_qp.hpp"
#include "contact/trace_operator.hpp"
#include "linalg/coupling_matrix.hpp"
#include "linalg/distribution.hpp"

namespace hpcontact::contact {

/// S of one solve: `dense` on the dense path, `products` on the other; `distribution`: the
/// factor's, over whose ranks each product is collective.
struct SolidTraceOperator {
  Eigen::MatrixXd dense;
  std::optional<TraceOperator> products;
  linalg::Distribution distribution;
};

/// The dofs K's factor orders last: the trace on the dense path (S is its trailing block), none on
/// the products path (the fill-reducing ordering is free).
std::vector<int> trailing_dofs(bool products, const linalg::Coupling& b);

/// S for B (m, n), a trace coupling; the products refer to `factor`, which must outlive them.
SolidTraceOperator condensed_operator(const assembly::CondensedFactor& factor, const linalg::Coupling& b,
                                      bool products);

/// min ½ λᵀ S λ − dᵀ λ over the bounds of `constraints` (C = I): the active-set method (dense) or
/// MPRGP to the box QP's tolerance; the report says which and counts the products. On the products
/// path of a distributed factor, collective on its ranks: the first runs MPRGP, every rank returns
/// its λ and report (contact/led_products.hpp: a method run on every rank alike would hang them
/// all on one step more on one rank).
MultiplierQpSolution solve_bounded_trace_qp(const SolidTraceOperator& s, const Eigen::VectorXd& d,
                                            const MultiplierConstraints& constraints, const BoxQpOptions& box,
                                            const InequalityQpOptions& interior_point);

/// The sign-and-disc problem of Tresca contact on either path (contact/disc_qp.hpp), led by the
/// first rank as above.
DiscQpSolution solve_disc_trace_qp(const SolidTraceOperator& s, const Eigen::VectorXd& d,
                                   const Eigen::VectorXd& radius);

}  // namespace hpcontact::contact
