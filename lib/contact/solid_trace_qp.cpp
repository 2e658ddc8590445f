// The dense and the products path of a 3-D multiplier problem.
#include "contact/solid_trace_qp.hpp"

#include "contact/mprgp.hpp"
#include "contact/schur_products.hpp"

namespace hpcontact::contact {

std::vector<int> trailing_dofs(bool products, const linalg::Coupling& b) {
  return products ? std::vector<int>{} : linalg::nonzero_columns(b);
}

SolidTraceOperator condensed_operator(const assembly::CondensedFactor& factor, const linalg::Coupling& b,
                                      bool products) {
  SolidTraceOperator out;
  if (products)
    out.products = schur_products(factor, b);
  else
    out.dense = factor.schur_complement(b);
  return out;
}

MultiplierQpSolution solve_bounded_trace_qp(const SolidTraceOperator& s, const Eigen::VectorXd& d,
                                            const MultiplierConstraints& constraints, const BoxQpOptions& box,
                                            const InequalityQpOptions& interior_point) {
  if (!s.products) return solve_multiplier_qp(s.dense, d, constraints, box, interior_point);
  MprgpOptions options;
  options.tolerance = box.tolerance;
  BoxQpResult qp = solve_box_qp_by_products(*s.products, d, constraints.lower, constraints.upper, options);
  MultiplierQpSolution out;
  out.x = std::move(qp.x);
  out.report = std::move(qp.report);
  out.report.trace_operator = "products";
  return out;
}

DiscQpSolution solve_disc_trace_qp(const SolidTraceOperator& s, const Eigen::VectorXd& d,
                                   const Eigen::VectorXd& radius) {
  if (!s.products) return solve_disc_qp(s.dense, d, radius);
  const long before = s.products->products();
  DiscQpSolution out = solve_disc_qp_by_products(*s.products, d, radius);
  out.report.trace_operator = "products";
  out.report.products = s.products->products() - before;
  return out;
}

}  // namespace hpcontact::contact
