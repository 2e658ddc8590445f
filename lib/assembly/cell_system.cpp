// Affine-cell congruence keys and the scalar cell system a K + b M.
#include "assembly/cell_system.hpp"

#include <array>
#include <cmath>

#include "core/error.hpp"
#include "mesh/cell_map.hpp"
#include "mesh/cell_partition.hpp"
#include "mesh/reference_cell.hpp"

namespace hpcontact::assembly {

std::optional<CongruenceKey> affine_key(const space::H1Space& space, int cell, bool enabled) {
  if (!enabled) return std::nullopt;
  const mesh::CellMap map(space.mesh(), cell);
  if (!map.is_affine()) return std::nullopt;
  // Cells of a uniform mesh whose vertex coordinates differ in the last bits share their
  // elimination, at a relative change of the element matrix far below 1e-12; similar cells of
  // different sizes (the layers of a geometric mesh) must not share a block of K + M.
  const Eigen::Matrix2d jacobian = map.jacobian(0.0, 0.0);
  const double largest = jacobian.cwiseAbs().maxCoeff(), unit = 1e-12 * largest;
  CongruenceKey key{space.cell_degree(cell), space.mesh().cell_size(cell)};
  for (int e = 0; e < space.mesh().cell_size(cell); ++e)
    key.push_back(space.edge_degree(space.mesh().cell_edge(cell, e)));
  for (int k = 0; k < 4; ++k) key.push_back(std::llround(jacobian(k % 2, k / 2) / unit));
  key.push_back(std::llround(1e11 * std::log(largest)));
  return key;
}

std::vector<int> cell_work_weights(const CellSystem& system) {
  std::vector<int> weights(system.n_cells());
  for (int c = 0; c < system.n_cells(); ++c) weights[c] = system.cell_size(c);
  return weights;
}

std::vector<int> PlanarCellSystem::split_cells_over_ranks(MPI_Comm ranks) const {
  HPC_VERIFY(!mesh().is_part(), "a part's cells are split by the whole mesh's owner");
  return mesh::split_cells_over_ranks(mesh(), cell_work_weights(*this), ranks);
}

std::vector<char> PlanarCellSystem::boundary_unknowns(int cell) const {
  const std::vector<char> shapes = boundary_shapes(scalar_space(), cell);
  const int fields = field_count();
  std::vector<char> unknowns(shapes.size() * static_cast<std::size_t>(fields));
  for (std::size_t s = 0; s < unknowns.size(); ++s) unknowns[s] = shapes[s / static_cast<std::size_t>(fields)];
  return unknowns;
}

std::vector<char> boundary_shapes(const space::H1Space& space, int cell) {
  const auto& mesh = space.mesh();
  const mesh::CellType type = mesh.cell_type(cell);
  std::array<char, 4> edge_on{}, vertex_on{};
  for (int e = 0; e < mesh.cell_size(cell); ++e) {
    if (!mesh.is_boundary_edge(mesh.cell_edge(cell, e))) continue;
    edge_on[e] = 1;
    for (int v : mesh::local_edge_vertices(type, e)) vertex_on[v] = 1;
  }
  const auto& shapes = space.cell_shapes(cell);
  std::vector<char> on(shapes.size(), 0);
  for (std::size_t s = 0; s < shapes.size(); ++s)
    if (shapes[s].role != space::ShapeRole::interior)
      on[s] = (shapes[s].role == space::ShapeRole::vertex ? vertex_on : edge_on)[shapes[s].entity];
  return on;
}

ScalarCellSystem::ScalarCellSystem(const space::H1Space& space, double stiffness_weight, double mass_weight)
    : space_(&space), stiffness_weight_(stiffness_weight), mass_weight_(mass_weight), element_(space) {}

void ScalarCellSystem::cell_dofs(int cell, std::vector<CellDof>& out) const {
  const auto& shapes = space_->cell_shapes(cell);
  out.resize(shapes.size());
  for (std::size_t s = 0; s < shapes.size(); ++s)
    out[s] = {shapes[s].dof, shapes[s].sign, shapes[s].role == space::ShapeRole::interior};
}

Eigen::MatrixXd ScalarCellSystem::element_matrix(int cell) const {
  Eigen::MatrixXd stiffness, mass;
  element_.compute(cell, stiffness_weight_ != 0.0 ? &stiffness : nullptr, mass_weight_ != 0.0 ? &mass : nullptr);
  const int n = static_cast<int>(space_->cell_shapes(cell).size());
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  if (stiffness_weight_ != 0.0) a += stiffness_weight_ * stiffness;
  if (mass_weight_ != 0.0) a += mass_weight_ * mass;
  return a;
}

std::optional<CongruenceKey> ScalarCellSystem::congruence_key(int cell) const {
  return affine_key(*space_, cell, true);
}

}  // namespace hpcontact::assembly
