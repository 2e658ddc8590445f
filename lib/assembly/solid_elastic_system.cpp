// Element matrices and unknowns of 3-D elasticity on hexahedra.
#include "assembly/solid_elastic_system.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstring>

#include "assembly/solid_cell_system.hpp"
#include "assembly/solid_cell_values.hpp"
#include "core/error.hpp"
#include "mesh/cell_partition.hpp"

namespace hpcontact::assembly {

SolidElasticCellSystem::SolidElasticCellSystem(const space::SolidVectorSpace& space, std::vector<Material> materials)
    : space_(&space), materials_(std::move(materials)) {
  if (static_cast<int>(materials_.size()) != n_cells())
    throw InputError(fmt::format("{} materials given for {} cells", materials_.size(), n_cells()));
  const mesh::SolidMesh& mesh = space.scalar().mesh();
  centre_ = mesh::SolidPoint::Zero();
  for (int v = 0; v < mesh.n_vertices(); ++v) centre_ += mesh.vertex(v);
  if (mesh.n_vertices() > 0) centre_ /= mesh.n_vertices();
}

Eigen::MatrixXd SolidElasticCellSystem::null_motions(int cell) const {
  const auto shapes = space_->scalar().cell_shapes(cell);
  const auto vertices = space_->scalar().mesh().cell_vertices(cell);
  Eigen::MatrixXd motions = Eigen::MatrixXd::Zero(3 * static_cast<Eigen::Index>(shapes.size()), 6);
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    if (shapes[s].role != space::SolidShapeRole::vertex) continue;
    const mesh::SolidPoint x = space_->scalar().mesh().vertex(vertices[shapes[s].entity]) - centre_;
    const auto row = 3 * static_cast<Eigen::Index>(s);
    for (int c = 0; c < 3; ++c) motions(row + c, c) = 1.0;
    // the rotations e_k × x: about z (−y, x, 0), about x (0, −z, y), about y (z, 0, −x)
    motions(row, 3) = -x.y(), motions(row + 1, 3) = x.x();
    motions(row + 1, 4) = -x.z(), motions(row + 2, 4) = x.y();
    motions(row, 5) = x.z(), motions(row + 2, 5) = -x.x();
  }
  return motions;
}

SolidElasticCellSystem SolidElasticCellSystem::vector_h1(const space::SolidVectorSpace& space) {
  SolidElasticCellSystem out(space, std::vector<Material>(space.scalar().mesh().n_cells()));
  out.materials_.clear();
  return out;
}

std::vector<int> SolidElasticCellSystem::split_cells_over_ranks(MPI_Comm ranks) const {
  int size = 1;
  HPC_VERIFY(MPI_Comm_size(ranks, &size) == MPI_SUCCESS, "the number of ranks");
  // (every rank holds the box whole and bisects it alike: no broadcast)
  return mesh::bisect_solid_cells(space_->scalar().mesh(), size, cell_work_weights(*this));
}

std::vector<char> SolidElasticCellSystem::boundary_unknowns(int cell) const {
  const std::vector<char> shapes = SolidScalarCellSystem(space_->scalar(), 1.0, 0.0).boundary_unknowns(cell);
  std::vector<char> out(3 * shapes.size());
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = shapes[k / 3];
  return out;
}

void SolidElasticCellSystem::cell_dofs(int cell, std::vector<CellDof>& out) const {
  const auto shapes = space_->scalar().cell_shapes(cell);
  out.resize(3 * shapes.size());
  for (std::size_t s = 0; s < shapes.size(); ++s)
    for (int c = 0; c < 3; ++c)
      out[3 * s + c] = {space_->dof(shapes[s].dof, c), shapes[s].sign,
                        shapes[s].role == space::SolidShapeRole::interior};
}

Eigen::MatrixXd SolidElasticCellSystem::element_matrix(int cell) const {
  const space::SolidH1Space& scalar = space_->scalar();
  if (materials_.empty()) {  // vector H¹: the scalar K + M on each component (signed basis already)
    const Eigen::MatrixXd e = SolidScalarCellSystem(scalar, 1.0, 1.0).element_matrix(cell);
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(3 * e.rows(), 3 * e.cols());
    for (int c = 0; c < 3; ++c) a(Eigen::seqN(c, e.rows(), 3), Eigen::seqN(c, e.cols(), 3)) = e;
    return a;
  }
  const SolidCellValues at = solid_cell_values(scalar, cell, solid_points_per_axis(scalar.cell_degree(cell)));
  const Eigen::Index n = at.values.rows();
  const Eigen::VectorXd w = at.weights;
  // D_ab = G_a W G_bᵀ, D_ba = D_abᵀ.
  std::array<std::array<Eigen::MatrixXd, 3>, 3> d;
  for (int a = 0; a < 3; ++a)
    for (int b = a; b < 3; ++b) {
      d[a][b] = at.gradients[a] * w.asDiagonal() * at.gradients[b].transpose();
      if (b != a) d[b][a] = d[a][b].transpose();
    }
  const Material& m = materials_[cell];
  const Eigen::MatrixXd trace = d[0][0] + d[1][1] + d[2][2];
  const auto shapes = scalar.cell_shapes(cell);
  Eigen::MatrixXd a(3 * n, 3 * n);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Eigen::MatrixXd block = m.lambda * d[i][j] + m.mu * d[j][i];
      if (i == j) block += m.mu * trace;
      for (Eigen::Index t = 0; t < n; ++t)
        for (Eigen::Index s = 0; s < n; ++s)
          // In the basis of the signed shapes, as CellSystem::element_matrix is defined.
          a(3 * s + i, 3 * t + j) = shapes[s].sign * shapes[t].sign * block(s, t);
    }
  return a;
}

std::optional<CongruenceKey> SolidElasticCellSystem::congruence_key(int cell) const {
  std::optional<CongruenceKey> key = SolidScalarCellSystem(space_->scalar(), 1.0, 0.0).congruence_key(cell);
  if (!key) return key;
  if (materials_.empty()) {  // (the vector H¹ system's cells never meet an elastic one's: one form per system)
    key->push_back(-1);
    return key;
  }
  // The material, exactly: cells of different materials never share an elimination.
  for (const double value : {materials_[cell].lambda, materials_[cell].mu}) {
    long long bits = 0;
    static_assert(sizeof(bits) == sizeof(value));
    std::memcpy(&bits, &value, sizeof(bits));
    key->push_back(bits);
  }
  return key;
}

}  // namespace hpcontact::assembly
