// Tied contact (the linear special case of two bodies): two blocks of one material on non-matching
// meshes bonded along y = 0 reproduce the smooth displacement u = ∇(eˣ sin y) (div u = 0 and
// Δu = 0, so no body force) with Dirichlet data on the outer sides: the error falls at least like
// h^p under refinement and exponentially in p.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "assembly/cell_field.hpp"
#include "contact/two_body_contact.hpp"
#include "mesh/boundary_mesh.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "postprocess/boundary_samples.hpp"
#include "postprocess/point_locator.hpp"

using namespace hpcontact;
using mesh::Point;

namespace {

constexpr double kEps = 1e-12;

Eigen::Vector2d exact(const Point& x) { return {std::exp(x.x()) * std::sin(x.y()), std::exp(x.x()) * std::cos(x.y())}; }

// (−1, 1) × (y_min, y_max) on n × n cells, Γ_C along y = 0, Γ_D the other three sides.
struct Block {
  mesh::Mesh mesh;
  std::unique_ptr<operators::ElasticOperators> operators;

  Block(double y_min, double y_max, int n, int p) : mesh(mesh::make_rectangle_mesh({-1.0, 1.0, y_min, y_max}, n, n)) {
    mesh::assign_boundary_part(mesh, mesh::BoundaryPart::contact,
                               [](const Point& x) { return std::abs(x.y()) < kEps; });
    mesh::assign_boundary_part(mesh, mesh::BoundaryPart::dirichlet,
                               [](const Point& x) { return std::abs(x.y()) >= kEps; });
    operators = std::make_unique<operators::ElasticOperators>(
        mesh, std::vector<int>(mesh.n_cells(), p),
        std::vector<assembly::Material>(mesh.n_cells(),
                                        assembly::lame_parameters(1.0, 0.3, assembly::PlaneModel::strain)));
  }

  // max |u_h − u| over a grid of points of the block.
  double error(const contact::BodyDisplacement& u, double y_min, double y_max) const {
    const postprocess::PointLocator locator(mesh);
    std::vector<postprocess::CellPoint> points;
    std::vector<Point> xs;
    for (int i = 0; i <= 16; ++i)
      for (int j = 0; j <= 8; ++j) {
        xs.emplace_back(-1.0 + 2.0 * i / 16.0, y_min + (y_max - y_min) * j / 8.0);
        points.push_back(*locator.locate(xs.back()));
      }
    const Eigen::MatrixXd values =
        postprocess::values_at(assembly::vector_field(operators->vector_space(), u.u, u.u_rows, u.lift), points, {});
    double largest = 0.0;
    for (std::size_t k = 0; k < xs.size(); ++k)
      largest = std::max(
          largest, (values.row(static_cast<Eigen::Index>(k)).transpose() - exact(xs[k])).lpNorm<Eigen::Infinity>());
    return largest;
  }
};

// The larger of both bodies' errors: the slave (−1, 1) × (0, 1) on n × n cells, the master
// (−1, 1) × (−1, 0) on 3n/2 × 3n/2 (n even), T_{C,H} the slave's trace, p_C = p − 1.
double tied_error(int n, int p) {
  const Block slave(0.0, 1.0, n, p), master(-1.0, 0.0, 3 * n / 2, p);
  const auto boundary = mesh::BoundaryMesh::uniform(2.0, n);
  contact::TwoBodyContactSetup setup;
  setup.slave.operators = slave.operators.get();
  setup.slave.boundary_mesh = &boundary;
  setup.slave.segment_degrees.assign(n, p - 1);
  setup.slave.problem = contact::ElasticContactProblem::tied;
  const std::array<contact::PointFunction, space::kComponents> data{[](const Point& x) { return exact(x)(0); },
                                                                    [](const Point& x) { return exact(x)(1); }};
  setup.slave.dirichlet = data;
  setup.master.operators = master.operators.get();
  setup.master.dirichlet = data;
  const auto solution = contact::solve_two_body_contact(setup);
  const contact::BodyDisplacement u_slave{solution.contact.u, solution.contact.u_rows, solution.contact.n_dofs,
                                          solution.contact.lift};
  return std::max(slave.error(u_slave, 0.0, 1.0), master.error(solution.master, -1.0, 0.0));
}

}  // namespace

TEST(TiedContact, ConvergesLikeHToThePAcrossANonMatchingInterface) {
  for (int p = 1; p <= 3; ++p) {
    std::vector<double> errors;
    for (int n : {2, 4, 8}) errors.push_back(tied_error(n, p));
    const double rate = std::log2(errors[1] / errors[2]);
    EXPECT_GE(rate, p) << "p = " << p << ": errors " << errors[0] << ", " << errors[1] << ", " << errors[2];
  }
}

TEST(TiedContact, ConvergesExponentiallyInP) {
  double previous = tied_error(2, 1);
  for (int p = 2; p <= 7; ++p) {
    const double error = tied_error(2, p);
    EXPECT_LT(error, 0.3 * previous) << "p = " << p << ": " << error << " after " << previous;
    previous = error;
  }
  EXPECT_LT(previous, 1e-7) << "p = 7 on 2 × 2 and 3 × 3 cells";
}
