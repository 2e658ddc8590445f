// RankParts: the cells bucketed by rank (a counting sort, ascending within each rank), each rank's
// part cut from the whole mesh and numbering with the work of the part alone, and read back.
#include "operators/rank_parts.hpp"

#include <algorithm>

#include "core/byte_buffer.hpp"
#include "core/error.hpp"
#include "mesh/contact_boundary.hpp"

namespace hpcontact::operators {

WholeNumbering number_whole_space(const mesh::Mesh& mesh, std::vector<int> cell_degrees, const RollerMasks* rollers) {
  WholeNumbering whole;
  const std::vector<char> none(mesh.n_cells(), 0);  // holding no cell, the numbering still counts every shape
  whole.space = std::make_unique<space::H1Space>(mesh, cell_degrees, space::DirichletDofs::eliminated, none);
  // The rollers' unknowns are numbered from the whole mesh's roller edges (boundary-sized).
  if (rollers) whole.vector_space = std::make_unique<space::VectorSpace>(*whole.space, *rollers);
  if (mesh.has_part(mesh::BoundaryPart::dirichlet))
    whole.kept = std::make_unique<space::H1Space>(mesh, std::move(cell_degrees), space::DirichletDofs::kept, none);
  const mesh::ContactBoundary contact(mesh);
  for (const auto& edge : contact.edges()) whole.contact_cells.push_back(edge.cell);
  return whole;
}

RankParts::RankParts(const mesh::Mesh& mesh, const WholeNumbering& whole, const std::vector<int>& parts, int ranks,
                     const std::vector<assembly::Material>* materials)
    : mesh_(mesh), whole_(whole), materials_(materials), contact_cells_(whole.contact_cells) {
  HPC_VERIFY(static_cast<int>(parts.size()) == mesh.n_cells(), "one rank per cell");
  HPC_VERIFY(!materials || static_cast<int>(materials->size()) == mesh.n_cells(), "one material per cell");
  std::sort(contact_cells_.begin(), contact_cells_.end());
  contact_cells_.erase(std::unique(contact_cells_.begin(), contact_cells_.end()), contact_cells_.end());
  for (int c : contact_cells_) contact_owners_.push_back(parts[c]);
  first_.assign(ranks + 1, 0);
  for (int rank : parts) {
    HPC_VERIFY(rank >= 0 && rank < ranks, "a cell's rank within the ranks");
    ++first_[rank + 1];
  }
  for (int r = 0; r < ranks; ++r) first_[r + 1] += first_[r];
  by_rank_.resize(parts.size());
  std::vector<int> next(first_.begin(), first_.end() - 1);
  for (int c = 0; c < mesh.n_cells(); ++c) by_rank_[next[parts[c]]++] = c;
}

RankParts::Part RankParts::part_of(int rank) const {
  HPC_VERIFY(rank >= 0 && rank + 1 < static_cast<int>(first_.size()), "a rank of the split");
  // Merge the rank's own cells with Γ_C's, both ascending; a cell in both is the rank's own.
  Part part;
  auto own = by_rank_.begin() + first_[rank];
  const auto own_end = by_rank_.begin() + first_[rank + 1];
  std::size_t k = 0;
  while (own != own_end || k < contact_cells_.size()) {
    if (k == contact_cells_.size() || (own != own_end && *own < contact_cells_[k])) {
      part.cells.push_back(*own++), part.owners.push_back(rank);
    } else {
      if (own != own_end && *own == contact_cells_[k]) ++own;
      part.cells.push_back(contact_cells_[k]), part.owners.push_back(contact_owners_[k]);
      ++k;
    }
  }
  return part;
}

std::vector<char> RankParts::bytes_for(int rank) const {
  const Part own = part_of(rank);
  const mesh::Mesh part = mesh_.extract(own.cells);
  ByteWriter out;
  part.pack(out);
  whole_.space->restricted_to(part, false).pack(out);
  out.put(own.owners);
  if (whole_.vector_space) whole_.vector_space->pack(out);
  out.put(static_cast<char>(whole_.kept != nullptr));
  if (whole_.kept) whole_.kept->restricted_to(part, false).pack(out);
  if (materials_) {
    std::vector<assembly::Material> materials;
    materials.reserve(own.cells.size());
    for (int c : own.cells) materials.push_back((*materials_)[c]);
    out.put(materials);
  }
  return out.take();
}

RankSpace rank_space_from_bytes(const std::vector<char>& bytes, bool vector_space, bool materials) {
  RankSpace out;
  ByteReader in(bytes);
  out.part = std::make_unique<mesh::Mesh>(mesh::Mesh::unpack(in));
  out.space = std::make_unique<space::H1Space>(space::H1Space::unpack(in, *out.part).with_shapes());
  out.cell_parts = in.get_vector<int>();
  if (vector_space) out.vector_space = std::make_unique<space::VectorSpace>(space::VectorSpace::unpack(in, *out.space));
  if (in.get<char>()) out.kept = std::make_unique<space::H1Space>(space::H1Space::unpack(in, *out.part));
  if (materials) out.materials = in.get_vector<assembly::Material>();
  HPC_VERIFY(in.at_end(), "a rank's part was not read to its end");
  HPC_VERIFY(static_cast<int>(out.cell_parts.size()) == out.part->n_cells() &&
                 (!materials || static_cast<int>(out.materials.size()) == out.part->n_cells()),
             "a rank's part with one owner and material per cell");
  return out;
}

}  // namespace hpcontact::operators
