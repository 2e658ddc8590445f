// RankParts: what the first rank of a distributed run holds while it cuts the parts (the whole
// space's numberings and the split of the cells), and each rank's part as the bytes sent to it.
// The cells are bucketed by rank once, so that cutting every part costs O(cells + ranks · Γ_C's
// cells) on the first rank, not a scan of the whole mesh per rank.
#pragma once

#include <memory>
#include <vector>

#include "assembly/material.hpp"
#include "space/h1_space.hpp"
#include "space/vector_space.hpp"

namespace hpcontact::operators {

/// The whole space's numberings, held by the first rank alone.
struct WholeNumbering {
  std::unique_ptr<space::H1Space> space, kept;       // kept: with Γ_D's dofs, where Γ_D exists
  std::unique_ptr<space::VectorSpace> vector_space;  // elasticity: the rollers' unknowns
  std::vector<int> contact_cells;                    // held by every rank
};

class RankParts {
 public:
  /// `parts`: the rank of each cell of `mesh` (all in [0, ranks)); `materials`: one per cell, or
  /// null. Everything must outlive this object.
  RankParts(const mesh::Mesh& mesh, const WholeNumbering& whole, const std::vector<int>& parts, int ranks,
            const std::vector<assembly::Material>* materials);
  /// Rank `rank`'s part of the mesh (its own cells and Γ_C's, ascending) with its share of the
  /// numberings and materials, read back by build_rank_space.
  std::vector<char> bytes_for(int rank) const;
  /// The whole mesh's cells of rank `rank`'s part.
  std::vector<int> cells_of(int rank) const;

 private:
  const mesh::Mesh& mesh_;
  const WholeNumbering& whole_;
  const std::vector<int>& parts_;
  const std::vector<assembly::Material>* materials_;
  std::vector<int> contact_cells_;  ///< Γ_C's cells, ascending, each once
  std::vector<int> first_;          ///< rank r owns by_rank_[first_[r] .. first_[r + 1])
  std::vector<int> by_rank_;        ///< the cells bucketed by rank, ascending within a rank
};

}  // namespace hpcontact::operators
