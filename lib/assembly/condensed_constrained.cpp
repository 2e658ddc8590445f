// CondensedFactor::constrained_solver: constrained solves on the whole system, the cells'
// interiors condensed before and recovered after the skeleton solver's constrained solve (a trace
// coupling has no interior columns, so the constraints live on the skeleton alone).
#include <fmt/format.h>

#include "assembly/condensed_factor.hpp"
#include "core/error.hpp"

namespace hpcontact::assembly {

class CondensedFactor::Constrained : public linalg::ConstrainedSolver {
 public:
  Constrained(const CondensedFactor& factor, std::unique_ptr<linalg::ConstrainedSolver> skeleton)
      : factor_(factor), skeleton_(std::move(skeleton)) {}

  linalg::ConstrainedSolution solve(const Eigen::VectorXd& rhs, const std::vector<int>& active,
                                    const Eigen::VectorXd& values, const Eigen::VectorXd& start,
                                    double relative_tolerance) override {
    HPC_VERIFY(start.size() == factor_.size(), "start of the wrong size");
    linalg::ConstrainedSolution out;
    const Eigen::VectorXd skeleton_start = start.head(factor_.n_skeleton());
    const Eigen::MatrixXd u = factor_.solve_around(rhs, [&](const Eigen::MatrixXd& skeleton_rhs) {
      out = skeleton_->solve(skeleton_rhs.col(0), active, values, skeleton_start, relative_tolerance);
      return Eigen::MatrixXd(out.x);
    });
    out.x = u.col(0);
    return out;
  }
  long preconditioner_applications() const override { return skeleton_->preconditioner_applications(); }
  long iterations() const override { return skeleton_->iterations(); }
  double relative_tolerance() const override { return skeleton_->relative_tolerance(); }

 private:
  const CondensedFactor& factor_;
  std::unique_ptr<linalg::ConstrainedSolver> skeleton_;
};

std::unique_ptr<linalg::ConstrainedSolver> CondensedFactor::constrained_solver(const linalg::Coupling& b) const {
  HPC_VERIFY(b.cols() == size_, "constraints with the wrong number of columns");
  const int n_skeleton = this->n_skeleton();
  for (int k = 0; k < b.outerSize(); ++k)
    for (linalg::Coupling::InnerIterator it(b, k); it; ++it)
      HPC_VERIFY(it.col() < n_skeleton || it.value() == 0.0, "constraints on interior modes");
  std::unique_ptr<linalg::ConstrainedSolver> skeleton =
      skeleton_solver_->constrained(linalg::squeezed<linalg::Coupling>(b.leftCols(n_skeleton)));
  if (!skeleton) return nullptr;
  return std::make_unique<Constrained>(*this, std::move(skeleton));
}

}  // namespace hpcontact::assembly
