// Element matrices, unknowns and congruence of the scalar cell system on solid meshes.
#include "assembly/solid_cell_system.hpp"

#include <algorithm>
#include <cmath>

#include "assembly/solid_cell_values.hpp"
#include "core/error.hpp"
#include "mesh/cell_partition.hpp"

namespace hpcontact::assembly {

SolidScalarCellSystem::SolidScalarCellSystem(const space::SolidH1Space& space, double stiffness_weight,
                                             double mass_weight)
    : space_(&space), stiffness_weight_(stiffness_weight), mass_weight_(mass_weight) {
  HPC_VERIFY(stiffness_weight >= 0.0 && mass_weight >= 0.0 && stiffness_weight + mass_weight > 0.0,
             "a K + b M with a, b ≥ 0, not both 0");
}

std::vector<int> SolidScalarCellSystem::split_cells_over_ranks(MPI_Comm ranks) const {
  int size = 1;
  HPC_VERIFY(MPI_Comm_size(ranks, &size) == MPI_SUCCESS, "the number of ranks");
  // (every rank holds the box whole and bisects it alike: no broadcast)
  return mesh::bisect_solid_cells(space_->mesh(), size, cell_work_weights(*this));
}

std::vector<char> SolidScalarCellSystem::boundary_unknowns(int cell) const {
  const mesh::SolidMesh& mesh = space_->mesh();
  const auto shapes = space_->cell_shapes(cell);
  std::vector<char> on(shapes.size(), 0);
  for (int f = 0; f < mesh.n_cell_faces(); ++f)
    if (mesh.is_boundary_face(mesh.cell_face(cell, f)))
      for (std::size_t s = 0; s < shapes.size(); ++s) on[s] = on[s] || space::shape_on_face(mesh, shapes[s], f);
  return on;
}

void SolidScalarCellSystem::cell_dofs(int cell, std::vector<CellDof>& out) const {
  const auto shapes = space_->cell_shapes(cell);
  out.resize(shapes.size());
  for (std::size_t s = 0; s < shapes.size(); ++s)
    out[s] = {shapes[s].dof, shapes[s].sign, shapes[s].role == space::SolidShapeRole::interior};
}

Eigen::MatrixXd SolidScalarCellSystem::element_matrix(int cell) const {
  const SolidCellValues at = solid_cell_values(*space_, cell, solid_points_per_axis(space_->cell_degree(cell)));
  const Eigen::Index n = at.values.rows();
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  // Σ_q w_q g(q) g(q)ᵀ as products of (shapes × points) tables scaled by √w (BLAS-3).
  const Eigen::VectorXd root = at.weights.cwiseSqrt();
  if (stiffness_weight_ > 0.0)
    for (const auto& gradient : at.gradients) {
      const Eigen::MatrixXd scaled = gradient * root.asDiagonal();
      a.selfadjointView<Eigen::Lower>().rankUpdate(scaled, stiffness_weight_);
    }
  if (mass_weight_ > 0.0) {
    const Eigen::MatrixXd scaled = at.values * root.asDiagonal();
    a.selfadjointView<Eigen::Lower>().rankUpdate(scaled, mass_weight_);
  }
  // In the basis of the signed shapes, as CellSystem::element_matrix is defined.
  const auto shapes = space_->cell_shapes(cell);
  Eigen::VectorXd sign(n);
  for (Eigen::Index s = 0; s < n; ++s) sign(s) = shapes[s].sign;
  return sign.asDiagonal() * Eigen::MatrixXd(a.selfadjointView<Eigen::Lower>()) * sign.asDiagonal();
}

std::optional<CongruenceKey> SolidScalarCellSystem::congruence_key(int cell) const {
  const mesh::SolidMesh& mesh = space_->mesh();
  if (!mesh.is_affine(cell)) return std::nullopt;
  // As affine_key in 2-D: the degrees, the Jacobian to 1e-12 of its largest entry and the size.
  const Eigen::Matrix3d jacobian = mesh.jacobian(cell, Eigen::Vector3d::Zero());
  const double largest = jacobian.cwiseAbs().maxCoeff(), unit = 1e-12 * largest;
  CongruenceKey key{space_->cell_degree(cell)};
  for (int e = 0; e < mesh.n_cell_edges(); ++e) key.push_back(space_->edge_degree(mesh.cell_edge(cell, e)));
  for (int f = 0; f < mesh.n_cell_faces(); ++f) key.push_back(space_->face_degree(mesh.cell_face(cell, f)));
  for (int k = 0; k < 9; ++k) key.push_back(std::llround(jacobian(k % 3, k / 3) / unit));
  key.push_back(std::llround(1e11 * std::log(largest)));
  return key;
}

}  // namespace hpcontact::assembly
