// Cell-by-cell assembly: element matrices (element_matrices.hpp) scattered as triplets, exact zeros
// left out (the Lobatto matrices have many, and they would become fill-in of the factorization);
// loads by Gauss quadrature.
#include "assembly/poisson_assembly.hpp"

#include <vector>

#include "assembly/cell_values.hpp"
#include "assembly/element_matrices.hpp"
#include "basis/quadrature.hpp"
#include "mesh/cell_map.hpp"

namespace hpcontact::assembly {
namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

void scatter_matrix(std::span<const space::LocalShape> shapes, const Eigen::MatrixXd& local, Triplets& triplets) {
  const int n = static_cast<int>(shapes.size());
  for (int s = 0; s < n; ++s) {
    if (shapes[s].dof < 0) continue;
    for (int t = 0; t < n; ++t)
      if (shapes[t].dof >= 0 && local(s, t) != 0.0) triplets.emplace_back(shapes[s].dof, shapes[t].dof, local(s, t));
  }
}

}  // namespace

VolumeMatrices assemble_volume_matrices(const space::H1Space& space, const VolumeMatrixRequest& request) {
  Triplets stiffness, mass;
  const int n = space.n_dofs();
  ElementMatrices element(space, request.kronecker_parallelograms);
  Eigen::MatrixXd local_stiffness, local_mass;
  for (int c = 0; c < space.mesh().n_cells(); ++c) {
    element.compute(c, request.stiffness ? &local_stiffness : nullptr, request.mass ? &local_mass : nullptr);
    if (request.stiffness) scatter_matrix(space.cell_shapes(c), local_stiffness, stiffness);
    if (request.mass) scatter_matrix(space.cell_shapes(c), local_mass, mass);
  }
  VolumeMatrices out;
  if (request.stiffness) {
    out.stiffness.resize(n, n);
    out.stiffness.setFromTriplets(stiffness.begin(), stiffness.end());
  }
  if (request.mass) {
    out.mass.resize(n, n);
    out.mass.setFromTriplets(mass.begin(), mass.end());
  }
  return out;
}

void visit_volume_load(const space::H1Space& space, const std::function<double(const mesh::Point&)>& f,
                       const LocalRows& target, const DofContribution& add) {
  for (int c = 0; c < space.mesh().n_cells(); ++c) {
    if (!target.holds(c)) continue;
    // Two extra points beyond the matrices: f is general data, not a polynomial.
    const CellQuadrature rule = cell_rule(space, c, 2);
    const CellValues cell = tabulate_cell(space, c, rule.points);
    Eigen::VectorXd weighted_f(cell.jacobians.size());
    for (int q = 0; q < rule.points.size(); ++q)
      weighted_f(q) = rule.weights[q] * cell.jacobians(q) * f(mesh::Point(cell.points(q, 0), cell.points(q, 1)));
    const Eigen::VectorXd local = cell.values.transpose() * weighted_f;
    const auto& shapes = space.cell_shapes(c);
    for (std::size_t s = 0; s < shapes.size(); ++s)
      if (shapes[s].dof >= 0) add(shapes[s].dof, local(s));
  }
}

void visit_boundary_load(const space::H1Space& space, const std::set<mesh::BoundaryPart>& parts,
                         const std::function<double(const mesh::Point& x, const mesh::Point& normal)>& g,
                         const LocalRows& target, const DofContribution& add) {
  const auto& mesh = space.mesh();
  for (int e : mesh.boundary_edges()) {
    if (!parts.contains(mesh.edge_part(e))) continue;
    const int c = mesh.edge_cells(e)[0];
    if (!target.holds(c)) continue;
    const int local_edge = mesh.local_edge_of(e, 0);
    // Curved edges: the speed |dΨ/dt| and the normal vary along the edge and are not polynomial.
    const bool curved = mesh.cell_geometry(c) != nullptr;
    const auto& rule = basis::gauss_legendre(space.cell_degree(c) + (curved ? 12 : 4));
    const CellValues values =
        tabulate_cell(space, c, edge_reference_points(mesh.cell_type(c), local_edge, rule.points));
    const mesh::CellMap map(mesh, c);
    Eigen::VectorXd weighted_g(rule.points.size());
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const double t = rule.points[q];
      weighted_g(q) = rule.weights[q] * map.edge_tangent(local_edge, t).norm() *
                      g(mesh::Point(values.points(q, 0), values.points(q, 1)), mesh.boundary_normal(e, t));
    }
    const Eigen::VectorXd local = values.values.transpose() * weighted_g;
    const auto& shapes = space.cell_shapes(c);
    for (std::size_t s = 0; s < shapes.size(); ++s)
      if (shapes[s].dof >= 0) add(shapes[s].dof, local(s));
  }
}

Eigen::VectorXd assemble_volume_load(const space::H1Space& space, const std::function<double(const mesh::Point&)>& f,
                                     const LocalRows& target) {
  Eigen::VectorXd load = Eigen::VectorXd::Zero(target.size(space.n_dofs()));
  visit_volume_load(space, f, target, [&](int dof, double value) { load(target.row(dof)) += value; });
  return load;
}

Eigen::VectorXd assemble_boundary_load(const space::H1Space& space, const std::set<mesh::BoundaryPart>& parts,
                                       const std::function<double(const mesh::Point& x, const mesh::Point& normal)>& g,
                                       const LocalRows& target) {
  Eigen::VectorXd load = Eigen::VectorXd::Zero(target.size(space.n_dofs()));
  visit_boundary_load(space, parts, g, target, [&](int dof, double value) { load(target.row(dof)) += value; });
  return load;
}

}  // namespace hpcontact::assembly
