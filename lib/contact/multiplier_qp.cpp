// The multiplier QP: active set on bounds with the interior-point method behind it.
#include "contact/multiplier_qp.hpp"

#include "core/error.hpp"

namespace hpcontact::contact {

MultiplierQpSolution solve_multiplier_qp(const Eigen::MatrixXd& s, const Eigen::VectorXd& d,
                                         const MultiplierConstraints& constraints, const BoxQpOptions& box,
                                         const InequalityQpOptions& interior_point) {
  std::string fallback_reason;
  if (constraints.bounds_only) {
    try {
      auto result = solve_box_qp(s, d, constraints.lower, constraints.upper, box);
      return {std::move(result.x), {}, std::move(result.report)};
    } catch (const NumericalError& error) {
      fallback_reason = error.what();
    }
  }
  try {
    auto result = solve_inequality_qp(s, d, constraints.matrix, constraints.lower, constraints.upper, interior_point);
    result.report.fallback_reason = fallback_reason;
    return {std::move(result.x), std::move(result.y), std::move(result.report)};
  } catch (const NumericalError& error) {
    throw NumericalError(fallback_reason.empty() ? std::string(error.what())
                                                 : fallback_reason + "; then " + error.what());
  }
}

namespace {

Eigen::MatrixXd block_diagonal(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(a.rows() + b.rows(), a.cols() + b.cols());
  out.topLeftCorner(a.rows(), a.cols()) = a;
  out.bottomRightCorner(b.rows(), b.cols()) = b;
  return out;
}

Eigen::VectorXd stacked(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  Eigen::VectorXd out(a.size() + b.size());
  out << a, b;
  return out;
}

template <class T>
std::vector<T> joined(std::vector<T> a, const std::vector<T>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

}  // namespace

MultiplierConstraints stack_constraints(const MultiplierConstraints& a, const MultiplierConstraints& b) {
  MultiplierConstraints out;
  out.to_nodal = block_diagonal(a.to_nodal, b.to_nodal);
  out.matrix = block_diagonal(a.matrix, b.matrix);
  out.lower = stacked(a.lower, b.lower);
  out.upper = stacked(a.upper, b.upper);
  out.s = joined(a.s, b.s);
  out.points_per_segment = joined(a.points_per_segment, b.points_per_segment);
  out.bounds_only = a.bounds_only && b.bounds_only;
  return out;
}

}  // namespace hpcontact::contact
