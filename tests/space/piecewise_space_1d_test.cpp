// The 1-D continuous piecewise Lobatto space of the local α predictor: its dof count with and
// without its ends, and mass and stiffness against exact integrals.
#include "space/piecewise_space_1d.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace hpcontact;

// Degrees 1, 3, 2 on a non-uniform partition of [0.5, 3]: four hats and 2 + 1 bubbles.
TEST(PiecewiseSpace1D, CountsItsFunctionsWithAndWithoutItsEnds) {
  const std::vector<double> nodes{0.5, 1.0, 2.2, 3.0};
  EXPECT_EQ(space::PiecewiseSpace1D(nodes, {1, 3, 2}, true, true).n_dofs(), 7);
  EXPECT_EQ(space::PiecewiseSpace1D(nodes, {1, 3, 2}, false, true).n_dofs(), 6);
  EXPECT_EQ(space::PiecewiseSpace1D(nodes, {1, 3, 2}, false, false).n_dofs(), 5);
  EXPECT_EQ(space::PiecewiseSpace1D({0.0, 1.0}, {1}, false, false).n_dofs(), 0);
}

// The hats sum to 1 and interpolate s exactly: 1ᵀ M 1 = L, sᵀ K s = L, and the mass of s² in the
// degree-2 space: ∫ s² = (b³ − a³)/3 through the Gram of the interpolant of s (hats = s at nodes).
TEST(PiecewiseSpace1D, MassAndStiffnessIntegrateExactly) {
  const std::vector<double> nodes{0.5, 1.0, 2.2, 3.0};
  const space::PiecewiseSpace1D space(nodes, {1, 3, 2}, true, true);
  const Eigen::MatrixXd mass = space.mass(), stiffness = space.stiffness();
  Eigen::VectorXd one = Eigen::VectorXd::Zero(space.n_dofs()), s = Eigen::VectorXd::Zero(space.n_dofs());
  for (int v = 0; v < 4; ++v) one[v] = 1.0, s[v] = nodes[v];  // the hats come first, node by node
  EXPECT_NEAR(one.dot(mass * one), 2.5, 1e-13);
  EXPECT_NEAR(one.dot(stiffness * one), 0.0, 1e-13);
  EXPECT_NEAR(s.dot(stiffness * s), 2.5, 1e-13);
  EXPECT_NEAR(s.dot(mass * s), (27.0 - 0.125) / 3, 1e-12);
  EXPECT_NEAR((mass - mass.transpose()).norm(), 0.0, 1e-14);
  EXPECT_EQ(space.piece_at(1.0), 0);  // the left piece at a node
  EXPECT_EQ(space.piece_at(2.5), 2);
  EXPECT_EQ(space.piece_at(3.5), -1);
}
