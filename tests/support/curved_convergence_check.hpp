// Shared by the curved-geometry tests (quadrilaterals, triangles): a curved-domain convergence
// study's H¹ errors fall exponentially in p (below 1e-10 at p = 12) while the polygonal domain
// through the same vertices stalls, and h-refinement at p = 3 gives rate 3.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "studies/convergence_study.hpp"

namespace hpcontact::testing {

inline void expect_curved_convergence(const std::string& study_file, double rate_tolerance) {
  auto study = studies::read_convergence_study(study_file);
  study.points = {
      {4, 0, 0, "curved"}, {8, 0, 0, "curved"}, {12, 0, 0, "curved"}, {8, 0, 0, "polygonal"}, {12, 0, 0, "polygonal"}};
  const auto rows = studies::run_convergence_study(study);
  EXPECT_LT(rows[1].error_h1, 1e-3 * rows[0].error_h1);
  EXPECT_LT(rows[2].error_h1, 1e-10);
  EXPECT_GT(rows[3].error_h1, 1e-2);
  EXPECT_GT(rows[4].error_h1, 0.9 * rows[3].error_h1) << "the polygonal geometry's error does not fall with p";
  // Rates p under h-refinement on the curved domain.
  study.points = {{3, 0, 1, "curved"}, {3, 0, 2, "curved"}};
  const auto h_rows = studies::run_convergence_study(study);
  EXPECT_NEAR(std::log(h_rows[0].error_h1 / h_rows[1].error_h1) / std::log(h_rows[0].h / h_rows[1].h), 3.0,
              rate_tolerance);
}

}  // namespace hpcontact::testing
