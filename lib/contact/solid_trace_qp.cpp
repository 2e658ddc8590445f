// The dense and the products path of a 3-D multiplier problem.
#include "contact/solid_trace_qp.hpp"

#include <functional>

#include "contact/led_products.hpp"
#include "contact/mprgp.hpp"
#include "contact/schur_products.hpp"
#include "core/byte_buffer.hpp"

namespace hpcontact::contact {
namespace {

std::vector<char> solution_bytes(const Eigen::VectorXd& x, const QpReport& report) {
  ByteWriter out;
  out.put(std::vector<double>(x.data(), x.data() + x.size()));
  out.put(report.method);
  out.put(static_cast<char>(report.converged));
  out.put(report.kkt_residual);
  out.put(report.iterations);
  out.put(report.proximal_steps);
  out.put(report.log);
  out.put(report.fallback_reason);
  out.put(report.trace_operator);
  out.put(report.products);
  return out.take();
}

template <class Solution>
Solution solution_of_bytes(const std::vector<char>& bytes) {
  ByteReader in(bytes);
  Solution out;
  const auto x = in.get_vector<double>();
  out.x = Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size()));
  QpReport& report = out.report;
  report.method = in.get_string();
  report.converged = in.get<char>() != 0;
  report.kkt_residual = in.get<double>();
  report.iterations = in.get<int>();
  report.proximal_steps = in.get<int>();
  report.log = in.get_vector<QpIteration>();
  report.fallback_reason = in.get_string();
  report.trace_operator = in.get_string();
  report.products = in.get<long>();
  HPC_VERIFY(in.at_end(), "the bytes of a multiplier solution hold nothing more");
  return out;
}

/// `solve` on S's products: serially as it is; on a distributed factor by the first rank alone,
/// the others serving its products, and every rank returning its solution.
template <class Solution>
Solution solve_on_products(const SolidTraceOperator& s, const std::function<Solution(const TraceOperator&)>& solve) {
  if (!s.distribution.distributed()) return solve(*s.products);
  return solution_of_bytes<Solution>(
      run_with_products_led_by_first_rank(*s.products, s.distribution.ranks, [&](const TraceOperator& led) {
        const Solution solved = solve(led);
        return solution_bytes(solved.x, solved.report);
      }));
}

}  // namespace

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
  out.distribution = factor.distribution();
  return out;
}

MultiplierQpSolution solve_bounded_trace_qp(const SolidTraceOperator& s, const Eigen::VectorXd& d,
                                            const MultiplierConstraints& constraints, const BoxQpOptions& box,
                                            const InequalityQpOptions& interior_point) {
  if (!s.products) return solve_multiplier_qp(s.dense, d, constraints, box, interior_point);
  MprgpOptions options;
  options.tolerance = box.tolerance;
  return solve_on_products<MultiplierQpSolution>(s, [&](const TraceOperator& products) {
    BoxQpResult qp = solve_box_qp_by_products(products, d, constraints.lower, constraints.upper, options);
    MultiplierQpSolution out;
    out.x = std::move(qp.x);
    out.report = std::move(qp.report);
    out.report.trace_operator = "products";
    return out;
  });
}

DiscQpSolution solve_disc_trace_qp(const SolidTraceOperator& s, const Eigen::VectorXd& d,
                                   const Eigen::VectorXd& radius) {
  if (!s.products) return solve_disc_qp(s.dense, d, radius);
  return solve_on_products<DiscQpSolution>(s, [&](const TraceOperator& products) {
    const long before = products.products();
    DiscQpSolution out = solve_disc_qp_by_products(products, d, radius);
    out.report.trace_operator = "products";
    out.report.products = products.products() - before;
    return out;
  });
}

}  // namespace hpcontact::contact
