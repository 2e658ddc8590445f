// RankParts: the cells bucketed by rank (a counting sort, ascending within each rank), and each
// rank's part cut from the whole mesh and numbering with the work of the part alone.
#include "operators/rank_parts.hpp"

#include <algorithm>
#include <iterator>

#include "core/byte_buffer.hpp"
#include "core/error.hpp"

namespace hpcontact::operators {

RankParts::RankParts(const mesh::Mesh& mesh, const WholeNumbering& whole, const std::vector<int>& parts, int ranks,
                     const std::vector<assembly::Material>* materials)
    : mesh_(mesh), whole_(whole), parts_(parts), materials_(materials), contact_cells_(whole.contact_cells) {
  HPC_VERIFY(static_cast<int>(parts.size()) == mesh.n_cells(), "one rank per cell");
  HPC_VERIFY(!materials || static_cast<int>(materials->size()) == mesh.n_cells(), "one material per cell");
  std::sort(contact_cells_.begin(), contact_cells_.end());
  contact_cells_.erase(std::unique(contact_cells_.begin(), contact_cells_.end()), contact_cells_.end());
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

std::vector<int> RankParts::cells_of(int rank) const {
  HPC_VERIFY(rank >= 0 && rank + 1 < static_cast<int>(first_.size()), "a rank of the split");
  std::vector<int> cells;
  cells.reserve(first_[rank + 1] - first_[rank] + contact_cells_.size());
  std::set_union(by_rank_.begin() + first_[rank], by_rank_.begin() + first_[rank + 1], contact_cells_.begin(),
                 contact_cells_.end(), std::back_inserter(cells));
  return cells;
}

std::vector<char> RankParts::bytes_for(int rank) const {
  const std::vector<int> cells = cells_of(rank);
  std::vector<int> cell_parts;
  cell_parts.reserve(cells.size());
  for (int c : cells) cell_parts.push_back(parts_[c]);
  const mesh::Mesh part = mesh_.extract(cells);
  ByteWriter out;
  part.pack(out);
  whole_.space->restricted_to(part, false).pack(out);
  out.put(cell_parts);
  if (whole_.vector_space) whole_.vector_space->pack(out);
  out.put(static_cast<char>(whole_.kept != nullptr));
  if (whole_.kept) whole_.kept->restricted_to(part, false).pack(out);
  if (materials_) {
    std::vector<assembly::Material> own;
    own.reserve(cells.size());
    for (int c : cells) own.push_back((*materials_)[c]);
    out.put(own);
  }
  return out.take();
}

}  // namespace hpcontact::operators
