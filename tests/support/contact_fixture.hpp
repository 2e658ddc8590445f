// Shared by the contact tests: the §7 contact problems on uniform meshes (data overridable) and
// the KKT check at the constraint points.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

#include "contact/contact_problem.hpp"
#include "mesh/rectangle_mesh.hpp"

namespace hpcontact::testing {

// Uniform degrees p and p_C on the given meshes (which must outlive the setup).
inline contact::ContactSetup uniform_setup(const mesh::Mesh& mesh, const mesh::BoundaryMesh& boundary, int p, int pc) {
  contact::ContactSetup setup;
  setup.mesh = &mesh;
  setup.cell_degrees.assign(mesh.n_cells(), p);
  setup.boundary_mesh = &boundary;
  setup.segment_degrees.assign(boundary.n_segments(), pc);
  return setup;
}

/// The §7 data: f = −1, g = −x², s = (1 − x)².
struct ContactData {
  contact::PointFunction f = [](const mesh::Point&) { return -1.0; };
  contact::PointFunction obstacle = [](const mesh::Point& x) { return -x.x() * x.x(); };
  contact::PointFunction bound = [](const mesh::Point& x) { return (1.0 - x.x()) * (1.0 - x.x()); };
};

/// Problem `problem` on the §7 square with n × n cells of degree p and m uniform segments of
/// degree p_C; `tune` may change the setup (solver options) before the solve.
inline contact::ContactSolution solve_paper_contact(contact::ContactProblem problem, int n, int p, int pc, int m,
                                                    std::optional<int> constraint_points = {},
                                                    const ContactData& data = {},
                                                    const std::function<void(contact::ContactSetup&)>& tune = {}) {
  const auto mesh = mesh::make_paper_square_mesh(n);
  const auto boundary = mesh::BoundaryMesh::uniform(2.0, m);
  auto setup = uniform_setup(mesh, boundary, p, pc);
  setup.problem = problem;
  if (constraint_points) setup.constraint_points = {*constraint_points};
  setup.f = data.f;
  setup.obstacle = data.obstacle;
  setup.bound = data.bound;
  if (tune) tune(setup);
  return contact::solve_contact(setup);
}

// At every constraint point j (values v = C λ, multipliers y with Cᵀ y = gap): v within its
// bounds; y_j > 0 only against a finite upper bound, y_j < 0 only against a finite lower bound;
// complementarity y_j⁺ (upper_j − v_j) = y_j⁻ (v_j − lower_j) = 0, relative to max(|y|, gap_scale)
// max(|λ|, 1).
// For the active-set path C = I and y = gap; the interior-point path reaches the same to 1e-10.
inline void expect_kkt(const contact::ContactSolution& s, const std::string& label) {
  const double scale = std::max(s.gap.lpNorm<Eigen::Infinity>(), s.gap_scale);
  const double lambda_scale = std::max(s.lambda.lpNorm<Eigen::Infinity>(), 1.0);
  const Eigen::VectorXd values = s.constraint_matrix * s.lambda;
  const Eigen::VectorXd& y = s.constraint_multiplier;
  const double y_scale = std::max(y.lpNorm<Eigen::Infinity>(), s.gap_scale);
  EXPECT_LT(s.qp.kkt_residual, 1e-12) << label;
  EXPECT_LT((s.constraint_matrix.transpose() * y - s.gap).lpNorm<Eigen::Infinity>(), 1e-10 * scale) << label;
  for (Eigen::Index j = 0; j < values.size(); ++j) {
    EXPECT_LE(values(j), s.upper(j) + 1e-12 * lambda_scale) << label << " j " << j;
    EXPECT_GE(values(j), s.lower(j) - 1e-12 * lambda_scale) << label << " j " << j;
    if (std::isfinite(s.upper(j))) {
      EXPECT_LE(std::max(y(j), 0.0) * (s.upper(j) - values(j)), 1e-10 * y_scale * lambda_scale) << label << " j " << j;
    } else {
      EXPECT_LE(y(j), 1e-10 * y_scale) << label << " j " << j;
    }
    if (std::isfinite(s.lower(j))) {
      EXPECT_LE(std::max(-y(j), 0.0) * (values(j) - s.lower(j)), 1e-10 * y_scale * lambda_scale) << label << " j " << j;
    } else {
      EXPECT_GE(y(j), -1e-10 * y_scale) << label << " j " << j;
    }
  }
}

}  // namespace hpcontact::testing
