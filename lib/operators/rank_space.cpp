// build_rank_space: the first rank numbers the space (a numbering-only space weighs the cells),
// the split follows, then each rank's part with its share of the numbering is sent to it
// (operators/rank_parts), and the rank adds the shapes of its cells.
#include "operators/rank_space.hpp"

#include <algorithm>

#include "core/byte_buffer.hpp"
#include "core/petsc_session.hpp"
#include "core/rank_agreement.hpp"
#include "mesh/cell_partition.hpp"
#include "operators/rank_parts.hpp"

namespace hpcontact::operators {

RankSpace build_rank_space(const mesh::Mesh* mesh, std::vector<int> cell_degrees, linalg::Distribution distribution,
                           const RollerMasks* rollers, const std::vector<assembly::Material>* materials) {
  if (!distribution.distributed()) {
    HPC_VERIFY(mesh, "a serial space without a mesh");
    RankSpace out;
    out.space = std::make_unique<space::H1Space>(*mesh, std::move(cell_degrees));
    if (rollers) out.vector_space = std::make_unique<space::VectorSpace>(*out.space, *rollers);
    return out;
  }
  MPI_Comm ranks = distribution.ranks;
  const bool first = rank_and_size(ranks).first == 0;
  // The first rank numbers the whole space and weighs the cells (a bad degree fails there, and on
  // every rank alike). Holding no cell, the numbering still counts every cell's shapes.
  WholeNumbering whole;
  std::vector<int> weights;
  run_on_all_ranks_agreeing(
      [&] {
        if (!first) return;
        HPC_VERIFY(mesh, "the first rank of a distributed run holds the whole mesh");
        whole = number_whole_space(*mesh, std::move(cell_degrees), rollers);
        const int components = rollers ? space::kComponents : 1;
        for (int c = 0; c < mesh->n_cells(); ++c) weights.push_back(components * whole.space->shape_count(c));
      },
      ranks);
  const std::vector<int> parts = mesh::split_cells_on_first_rank(mesh, weights, ranks);
  weights = {};
  std::unique_ptr<RankParts> cutter;  // the first rank's
  run_on_all_ranks_agreeing(
      [&] {
        if (first) cutter = std::make_unique<RankParts>(*mesh, whole, parts, rank_and_size(ranks).second, materials);
      },
      ranks);
  const std::vector<char> bytes =
      bytes_made_by_first_rank_for_each([&](int rank) { return cutter->bytes_for(rank); }, ranks);
  cutter.reset();
  return rank_space_from_bytes(bytes, rollers != nullptr, materials != nullptr);
}

WholeMeshFacts::WholeMeshFacts(const mesh::Mesh* mesh, const std::vector<int>& cell_degrees,
                               linalg::Distribution distribution) {
  static_assert(std::is_trivially_copyable_v<WholeMeshFacts>, "the facts are sent as they are");
  if (mesh) {
    cells_ = mesh->n_cells(), vertices_ = mesh->n_vertices(), edges_ = mesh->n_edges();
    smallest_degree_ = cell_degrees.empty() ? 0 : *std::min_element(cell_degrees.begin(), cell_degrees.end());
    longest_edge_ = mesh->longest_edge();
    has_dirichlet_ = mesh->has_part(mesh::BoundaryPart::dirichlet);
    mesh::Point sum = mesh::Point::Zero();
    for (const auto& x : mesh->vertices()) sum += x / static_cast<double>(mesh->n_vertices());
    vertex_mean_[0] = sum.x(), vertex_mean_[1] = sum.y();
  }
  if (distribution.distributed()) {
    // (a first rank without the mesh sends zeros, and build_rank_space refuses it on every rank)
    HPC_VERIFY(MPI_Bcast(this, sizeof(WholeMeshFacts), MPI_BYTE, 0, distribution.ranks) == MPI_SUCCESS,
               "broadcast of the whole mesh's facts");
  }
  address_ = reinterpret_cast<std::uintptr_t>(mesh);
}

bool WholeMeshFacts::is(const mesh::Mesh& mesh) const {
  return reinterpret_cast<std::uintptr_t>(&mesh) == address_ && mesh.n_cells() == cells_ &&
         mesh.n_vertices() == vertices_ && mesh.n_edges() == edges_;
}

bool space_built_on(const space::H1Space& space, const WholeMeshFacts& built_from, const mesh::Mesh& mesh,
                    const std::vector<int>& cell_degrees) {
  if (!built_from.is(mesh) || static_cast<int>(cell_degrees.size()) != mesh.n_cells()) return false;
  const auto& space_mesh = space.mesh();
  for (int c = 0; c < space_mesh.n_cells(); ++c)
    if (space.cell_degree(c) != cell_degrees[space_mesh.global_cell(c)]) return false;
  return true;
}

}  // namespace hpcontact::operators
