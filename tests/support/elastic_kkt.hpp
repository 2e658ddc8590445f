// KKT of an elastic contact solution at its constraint points (nodal constraints, C = I): the
// bounds, the sign of the gap at each bound, and complementarity, relative to the sizes involved.
#pragma once

#include <gtest/gtest.h>

#include "contact/elastic_contact.hpp"

namespace hpcontact::testing {

// max over the constraint rows of the violation of lo ≤ Cλ ≤ hi, of gap ≥ 0 where λ is at its
// upper bound, and of complementarity, relative to the sizes involved.
inline void expect_kkt(const contact::ElasticContactSolution& solution, double tolerance) {
  ASSERT_EQ(solution.constraint_matrix.rows(), solution.lambda.size()) << "nodal constraints expected";
  const Eigen::VectorXd c_lambda = solution.constraint_matrix * solution.lambda;
  const double lambda_scale = solution.lambda.lpNorm<Eigen::Infinity>(), gap_scale = solution.gap_scale;
  for (Eigen::Index j = 0; j < c_lambda.size(); ++j) {
    EXPECT_GE(c_lambda(j), solution.lower(j) - tolerance * lambda_scale) << "row " << j;
    EXPECT_LE(c_lambda(j), solution.upper(j) + tolerance * lambda_scale) << "row " << j;
    // Stationarity with C = I: the gap (dual gradient) is ≥ 0 at the upper bound, ≤ 0 at the lower
    // one, and 0 in between.
    const double to_upper = solution.upper(j) - c_lambda(j), to_lower = c_lambda(j) - solution.lower(j);
    const double gap = solution.gap(j);
    if (gap > tolerance * gap_scale) {
      EXPECT_LE(to_upper, tolerance * lambda_scale) << "row " << j << ", gap " << gap;
    }
    if (gap < -tolerance * gap_scale) {
      EXPECT_LE(to_lower, tolerance * lambda_scale) << "row " << j << ", gap " << gap;
    }
  }
}

}  // namespace hpcontact::testing
