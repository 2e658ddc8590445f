// 3-D Hertz through `hpcontact solve studies/three_d/hertz.toml`: the contact radius from the
// pressure's second moment (Σ w p r² / Σ w p = 2a²/5) against Hertz's a³ = 3PR/(4E*) for the run's
// own P, and the pressure against Hertz's in L²(Γ_C), over the whole of Γ_C and inside r < 0.8 a
// (away from the free boundary, which the grid T_{C,H} does not follow). A 35 s, 3.3 GB solve:
// Release builds only.
#include <gtest/gtest.h>

#include <cmath>

#include "support/cli_runner.hpp"

namespace hpcontact::testing {
namespace {

TEST(SolidHertz, ContactRadiusAndPressureOfTheSphere) {
  if (HPCONTACT_SANITIZED) GTEST_SKIP() << "a 190k-unknown 3-D solve: Release builds only";
  const auto out = scratch("solid_hertz") / "out";
  const auto solve =
      run("solve " + std::string(HPCONTACT_SOURCE_DIR) + "/studies/three_d/hertz.toml --out " + out.string());
  ASSERT_EQ(solve.exit_code, 0) << solve.output;
  const auto columns = read_csv(out / "boundary_frictionless.csv").numeric_columns();
  const auto& x = columns.at("x");
  const auto& y = columns.at("y");
  const auto& w = columns.at("w");
  const auto& p = columns.at("pressure");
  double force = 0.0, moment = 0.0;
  for (std::size_t k = 0; k < w.size(); ++k) {
    force += w[k] * p[k];
    moment += w[k] * p[k] * (x[k] * x[k] + y[k] * y[k]);
  }
  const double modulus = 1.0 / (1.0 - 0.3 * 0.3), radius = 1.0;
  // (the quarter's force times four: the whole sphere's)
  const double a_hertz = std::cbrt(3.0 * 4.0 * force * radius / (4.0 * modulus));
  const double a_moment = std::sqrt(2.5 * moment / force);
  EXPECT_LT(std::abs(a_moment / a_hertz - 1.0), 0.01) << a_moment << " against " << a_hertz;
  const double p0 = 3.0 * 4.0 * force / (2.0 * M_PI * a_hertz * a_hertz);
  std::array<double, 2> error{}, size{};  // whole Γ_C, r < 0.8 a
  for (std::size_t k = 0; k < w.size(); ++k) {
    const double r2 = x[k] * x[k] + y[k] * y[k];
    const double hertz = p0 * std::sqrt(std::max(0.0, 1.0 - r2 / (a_hertz * a_hertz)));
    for (int part = 0; part < 2; ++part) {
      if (part == 1 && r2 >= 0.64 * a_hertz * a_hertz) continue;
      error[part] += w[k] * std::pow(p[k] - hertz, 2);
      size[part] += w[k] * hertz * hertz;
    }
  }
  // Measured: 8.6 % over Γ_C (the free boundary smeared over one cell of T_{C,H}), 2.0 % inside.
  EXPECT_LT(std::sqrt(error[0] / size[0]), 0.10);
  EXPECT_LT(std::sqrt(error[1] / size[1]), 0.03);
  std::printf("a: %.6f (moment) against %.6f (Hertz); pressure L2 errors %.4f (Γ_C), %.4f (r < 0.8 a)\n", a_moment,
              a_hertz, std::sqrt(error[0] / size[0]), std::sqrt(error[1] / size[1]));
}

}  // namespace
}  // namespace hpcontact::testing
