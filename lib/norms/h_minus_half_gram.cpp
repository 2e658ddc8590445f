// interpolation_norm_gram and extension_norm_gram.
#include "norms/h_minus_half_gram.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "assembly/coupling.hpp"
#include "assembly/poisson_assembly.hpp"
#include "basis/lobatto.hpp"
#include "basis/quadrature.hpp"
#include "core/error.hpp"
#include "linalg/sparse_cholesky.hpp"
#include "mesh/refine.hpp"

namespace hpcontact::norms {

Eigen::MatrixXd interpolation_norm_gram(const mesh::ContactBoundary& contact,
                                        const space::MultiplierSpace& multipliers,
                                        const InterpolationReference& reference) {
  if (reference.subdivisions < 1)
    throw_bad_input("interpolation norm", "subdivisions", std::to_string(reference.subdivisions),
                    "must be >= 1");
  const int q = reference.degree > 0 ? reference.degree : multipliers.max_degree() + 6;
  // W's mesh contains the breakpoints of T_{C,H}, so every W interval lies in one segment.
  std::vector<double> nodes;
  for (const auto& interval : assembly::common_intervals(contact, multipliers.boundary_mesh()))
    for (int k = 0; k < reference.subdivisions; ++k)
      nodes.push_back(interval.s_begin +
                      (interval.s_end - interval.s_begin) * k / reference.subdivisions);
  nodes.push_back(contact.length());
  const int n_intervals = static_cast<int>(nodes.size()) - 1;
  // Dofs: vertices 0..n_intervals, then q - 1 bubbles per interval.
  const int n_w = n_intervals + 1 + n_intervals * (q - 1);
  Eigen::MatrixXd stiffness_plus_mass = Eigen::MatrixXd::Zero(n_w, n_w);
  Eigen::MatrixXd mass = Eigen::MatrixXd::Zero(n_w, n_w);
  Eigen::MatrixXd coupling = Eigen::MatrixXd::Zero(n_w, multipliers.n_dofs());
  const int pc_max = multipliers.max_degree();
  const auto& rule = basis::gauss_legendre(basis::gauss_points_for_degree(2 * q + pc_max));
  const auto table = basis::tabulate_lobatto(q, rule.points);
  for (int k = 0; k < n_intervals; ++k) {
    std::vector<int> dofs{k, k + 1};
    for (int j = 2; j <= q; ++j) dofs.push_back(n_intervals + 1 + k * (q - 1) + (j - 2));
    const double half = 0.5 * (nodes[k + 1] - nodes[k]);
    const int segment = multipliers.boundary_mesh().segment_at(0.5 * (nodes[k] + nodes[k + 1]));
    const int first = multipliers.first_dof(segment), pc = multipliers.segment_degree(segment);
    for (std::size_t g = 0; g < rule.points.size(); ++g) {
      const double w = rule.weights[g] * half;
      const double s = nodes[k] + half * (rule.points[g] + 1.0);
      const Eigen::VectorXd mu =
          multipliers.basis_values(segment, multipliers.local_coordinate(segment, s));
      for (int a = 0; a <= q; ++a) {
        const double value_a = table.values(g, a), slope_a = table.derivatives(g, a) / half;
        for (int b = 0; b <= q; ++b) {
          const double product = w * value_a * table.values(g, b);
          mass(dofs[a], dofs[b]) += product;
          stiffness_plus_mass(dofs[a], dofs[b]) +=
              product + w * slope_a * table.derivatives(g, b) / half;
        }
        coupling.row(dofs[a]).segment(first, pc + 1) += w * value_a * mu.transpose();
      }
    }
  }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eigen(stiffness_plus_mass, mass);
  if (eigen.info() != Eigen::Success)
    throw NumericalError("interpolation norm: the reference eigenproblem K_W Φ = M_W Φ Λ failed");
  const Eigen::MatrixXd scaled =
      eigen.eigenvectors().transpose() * coupling;  // Φᵀ C, shape (n_w, n_mult)
  const Eigen::VectorXd inverse_sqrt = eigen.eigenvalues().cwiseSqrt().cwiseInverse();
  Eigen::MatrixXd gram = scaled.transpose() * inverse_sqrt.asDiagonal() * scaled;
  return 0.5 * (gram + gram.transpose());
}

Eigen::MatrixXd extension_norm_gram(const mesh::QuadMesh& mesh, const std::vector<int>& cell_degrees,
                                    const space::MultiplierSpace& multipliers,
                                    const ExtensionReference& reference) {
  if (reference.refinements < 0 || reference.extra_degree < 0)
    throw InputError("extension norm: refinements and extra_degree must be >= 0");
  mesh::QuadMesh fine = mesh;
  std::vector<int> degrees = cell_degrees;
  for (int level = 0; level < reference.refinements; ++level) {
    fine = mesh::refine_uniformly(fine);
    std::vector<int> children;
    for (int p : degrees) children.insert(children.end(), 4, p);  // children of cell c: 4c..4c+3
    degrees = std::move(children);
  }
  for (int& p : degrees) p += reference.extra_degree;
  const space::H1Space space(fine, degrees);
  const mesh::ContactBoundary contact(fine);
  const auto matrices = assembly::assemble_volume_matrices(space, {.stiffness = true, .mass = true});
  const auto coupling = assembly::assemble_coupling(space, contact, multipliers);
  const linalg::SparseCholesky a(matrices.stiffness + matrices.mass, linalg::nonzero_columns(coupling));
  return a.schur_complement(coupling);
}

}  // namespace hpcontact::norms
