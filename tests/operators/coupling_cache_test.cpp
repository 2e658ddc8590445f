// The operators' cache of couplings: B^s is kept per weight, not per name alone, so two weights on
// the same operators get their own B^s, and weights with the same key share one.
#include <gtest/gtest.h>

#include "assembly/coupling.hpp"
#include "core/operator_log.hpp"
#include "mesh/boundary_mesh.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "operators/primal_operators.hpp"
#include "space/multiplier_space.hpp"

using namespace hpcontact;

namespace {

double entry_sum(const linalg::Coupling& b) { return Eigen::MatrixXd(b).sum(); }

}  // namespace

TEST(CouplingCache, TwoWeightsUnderOneNameGetTheirOwnCoupling) {
  const auto mesh = mesh::make_paper_square_mesh(4);
  OperatorLog log;
  const operators::PrimalOperators primal(mesh, std::vector<int>(mesh.n_cells(), 2), &log);
  const auto boundary = mesh::BoundaryMesh::uniform(2.0, 2);
  const space::MultiplierSpace multipliers(boundary, 1);
  const assembly::CouplingWeight one([](const mesh::Point&) { return 1.0; });
  const assembly::CouplingWeight two([](const mesh::Point&) { return 2.0; });
  const double b_one = entry_sum(primal.coupling(multipliers, one, "B^s"));
  const double b_two = entry_sum(primal.coupling(multipliers, two, "B^s"));
  EXPECT_NEAR(b_two, 2.0 * b_one, 1e-12 * std::abs(b_one));
  EXPECT_NE(b_one, 0.0);
  // A copy of a weight is the same weight: its B^s is not built again.
  const auto built = log.records().size();
  const assembly::CouplingWeight copy = two;
  EXPECT_EQ(entry_sum(primal.coupling(multipliers, copy, "B^s")), b_two);
  EXPECT_EQ(log.records().size(), built);
  EXPECT_NE(operators::PrimalOperators::coupling_key(multipliers, "B^s", one),
            operators::PrimalOperators::coupling_key(multipliers, "B^s", two));
}

TEST(CouplingCache, WeightsWithOneKeyShareTheirCoupling) {
  const auto mesh = mesh::make_paper_square_mesh(4);
  OperatorLog log;
  const operators::PrimalOperators primal(mesh, std::vector<int>(mesh.n_cells(), 1), &log);
  const auto boundary = mesh::BoundaryMesh::uniform(2.0, 4);
  const space::MultiplierSpace multipliers(boundary, 0);
  const assembly::CouplingWeight first([](const mesh::Point& x) { return 1.0 + x.x() * x.x(); }, "s = 1 + x^2");
  const assembly::CouplingWeight second([](const mesh::Point& x) { return 1.0 + x.x() * x.x(); }, "s = 1 + x^2");
  const auto* b = &primal.coupling(multipliers, first, "B^s");
  const auto built = log.records().size();
  EXPECT_EQ(&primal.coupling(multipliers, second, "B^s"), b);
  EXPECT_EQ(log.records().size(), built);
  // No weight is B, kept apart from B^s.
  EXPECT_NE(&primal.coupling(multipliers, {}, "B"), b);
}
