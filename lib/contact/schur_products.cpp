// B K⁻¹ Bᵀ x by a skeleton solve: Bᵀ x has no interior entries, so K⁻¹ Bᵀ x on the skeleton is
// the skeleton Schur complement's solve, and B reads only skeleton rows.
#include "contact/schur_products.hpp"

#include <memory>

#include "core/error.hpp"

namespace hpcontact::contact {

TraceOperator schur_products(const assembly::CondensedFactor& factor, const linalg::Coupling& b) {
  HPC_VERIFY(b.cols() == factor.size(), "B K⁻¹ Bᵀ: B has the wrong number of columns");
  const int n_skeleton = factor.n_skeleton();
  for (int row = 0; row < b.outerSize(); ++row)
    for (linalg::Coupling::InnerIterator it(b, row); it; ++it)
      HPC_VERIFY(it.col() < n_skeleton || it.value() == 0.0, "B K⁻¹ Bᵀ by products: B has interior columns");
  auto skeleton_b =
      std::make_shared<const linalg::Coupling>(linalg::squeezed<linalg::Coupling>(b.leftCols(n_skeleton)));
  return {b.rows(), [&factor, skeleton_b](const Eigen::VectorXd& x) {
            const Eigen::MatrixXd rhs = skeleton_b->transpose() * x;
            return Eigen::VectorXd(*skeleton_b * factor.solve_skeleton(rhs).col(0));
          }};
}

}  // namespace hpcontact::contact
