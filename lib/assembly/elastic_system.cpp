// The elasticity cell system.
#include "assembly/elastic_system.hpp"

#include <fmt/format.h>

#include <bit>

#include "core/error.hpp"

namespace hpcontact::assembly {

ElasticCellSystem::ElasticCellSystem(const space::VectorSpace& space, std::vector<Material> materials,
                                     double mass_weight, std::optional<mesh::Point> centre)
    : space_(&space), materials_(std::move(materials)), mass_weight_(mass_weight), element_(space.scalar()) {
  if (static_cast<int>(materials_.size()) != mesh().n_cells())
    throw InputError(fmt::format("{} materials given for {} cells", materials_.size(), mesh().n_cells()));
  if (centre)
    centre_ = *centre;
  else
    for (const auto& x : mesh().vertices()) centre_ += x / static_cast<double>(mesh().n_vertices());
}

int ElasticCellSystem::n_dofs() const { return space_->n_dofs(); }
int ElasticCellSystem::n_skeleton_dofs() const { return space_->n_skeleton_dofs(); }

namespace {

// Both components of each scalar shape, side by side.
void interleaved_dofs(const space::VectorSpace& space, int cell, std::vector<CellDof>& out) {
  const auto& shapes = space.scalar().cell_shapes(cell);
  out.resize(space::kComponents * shapes.size());
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    const bool interior = shapes[s].role == space::ShapeRole::interior;
    for (int c = 0; c < space::kComponents; ++c)
      out[space::kComponents * s + c] = {space.dof(shapes[s].dof, c), shapes[s].sign, interior};
  }
}

// The scalar matrix on each component: a[(s,c),(t,c)] = scalar[s,t].
Eigen::MatrixXd componentwise(const Eigen::MatrixXd& scalar) {
  const Eigen::Index n = scalar.rows();
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  a(Eigen::seqN(0, n, 2), Eigen::seqN(0, n, 2)) = scalar;
  a(Eigen::seqN(1, n, 2), Eigen::seqN(1, n, 2)) = scalar;
  return a;
}

}  // namespace

void ElasticCellSystem::cell_dofs(int cell, std::vector<CellDof>& out) const { interleaved_dofs(*space_, cell, out); }

Eigen::MatrixXd ElasticCellSystem::element_matrix(int cell) const {
  const auto d = element_.directional(cell);
  const double lambda = materials_[cell].lambda, mu = materials_[cell].mu;
  const Eigen::Index n = d.xx.rows();
  Eigen::MatrixXd a(2 * n, 2 * n);
  // Interleaved (s, c) ↔ 2s + c: each 2 × 2 block is one pair of shapes.
  a(Eigen::seqN(0, n, 2), Eigen::seqN(0, n, 2)) = (lambda + 2.0 * mu) * d.xx + mu * d.yy;
  a(Eigen::seqN(0, n, 2), Eigen::seqN(1, n, 2)) = lambda * d.xy + mu * d.yx;
  a(Eigen::seqN(1, n, 2), Eigen::seqN(0, n, 2)) = lambda * d.yx + mu * d.xy;
  a(Eigen::seqN(1, n, 2), Eigen::seqN(1, n, 2)) = (lambda + 2.0 * mu) * d.yy + mu * d.xx;
  if (mass_weight_ != 0.0) {
    Eigen::MatrixXd mass;
    element_.compute(cell, nullptr, &mass);
    a += mass_weight_ * componentwise(mass);
  }
  return a;
}

Eigen::MatrixXd ElasticCellSystem::null_motions(int cell) const {
  const auto& shapes = space_->scalar().cell_shapes(cell);
  const auto vertices = mesh().cell(cell);
  Eigen::MatrixXd motions = Eigen::MatrixXd::Zero(space::kComponents * shapes.size(), null_motion_count());
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    if (shapes[s].role != space::ShapeRole::vertex) continue;
    const mesh::Point& x = mesh().vertex(vertices[shapes[s].entity]);
    const auto row = static_cast<Eigen::Index>(space::kComponents * s);
    motions(row, 0) = 1.0, motions(row + 1, 1) = 1.0;
    // (about the vertices' centroid: about a far-away point the rotation is nearly a translation)
    motions(row, 2) = -(x.y() - centre_.y()), motions(row + 1, 2) = x.x() - centre_.x();
  }
  return motions;
}

std::optional<CongruenceKey> ElasticCellSystem::congruence_key(int cell) const {
  auto key = affine_key(space_->scalar(), cell, true);
  if (key) {  // equal geometry and degrees give equal matrices only with equal coefficients
    key->push_back(std::bit_cast<long long>(mass_weight_));
    key->push_back(std::bit_cast<long long>(materials_[cell].lambda));
    key->push_back(std::bit_cast<long long>(materials_[cell].mu));
  }
  return key;
}

ComponentwiseCellSystem::ComponentwiseCellSystem(const space::VectorSpace& space, double stiffness_weight,
                                                 double mass_weight)
    : space_(&space), scalar_(space.scalar(), stiffness_weight, mass_weight) {}

int ComponentwiseCellSystem::n_dofs() const { return space_->n_dofs(); }
int ComponentwiseCellSystem::n_skeleton_dofs() const { return space_->n_skeleton_dofs(); }

void ComponentwiseCellSystem::cell_dofs(int cell, std::vector<CellDof>& out) const {
  interleaved_dofs(*space_, cell, out);
}

Eigen::MatrixXd ComponentwiseCellSystem::element_matrix(int cell) const {
  return componentwise(scalar_.element_matrix(cell));
}

}  // namespace hpcontact::assembly
