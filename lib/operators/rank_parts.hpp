// RankParts: the first rank of a distributed run cuts each rank's part out of the whole mesh and
// numbering, as the bytes sent to that rank, and the rank reads its RankSpace back from them. The
// cells are bucketed by rank once, so that cutting every part costs the mesh once, not once per rank.
#pragma once

#include <memory>
#include <vector>

#include "assembly/material.hpp"
#include "operators/rank_space.hpp"
#include "space/h1_space.hpp"
#include "space/vector_space.hpp"

namespace hpcontact::operators {

/// The whole space's numberings, held by the first rank alone.
struct WholeNumbering {
  std::unique_ptr<space::H1Space> space, kept;       // kept: with Γ_D's dofs, where Γ_D exists
  std::unique_ptr<space::VectorSpace> vector_space;  // elasticity: the rollers' unknowns
  std::vector<int> contact_cells;                    // held by every rank (any order, repeats allowed)
};

/// The first rank's numberings of the whole space on `mesh` (numbering only: no cell's shapes),
/// with Γ_D's dofs kept too where Γ_D exists and the rollers' unknowns where `rollers` is given.
/// @throws InputError on a degree < 1.
WholeNumbering number_whole_space(const mesh::Mesh& mesh, std::vector<int> cell_degrees, const RollerMasks* rollers);

class RankParts {
 public:
  /// `parts`: the rank of each cell of `mesh` (all in [0, ranks)); `materials`: one per cell, or
  /// null. `mesh`, `whole` and `materials` must outlive this object; `parts` is read here only.
  RankParts(const mesh::Mesh& mesh, const WholeNumbering& whole, const std::vector<int>& parts, int ranks,
            const std::vector<assembly::Material>* materials);
  /// Rank `rank`'s part of the mesh (its own cells and Γ_C's, ascending) with each cell's rank and
  /// its share of the numberings and materials, read back by rank_space_from_bytes.
  std::vector<char> bytes_for(int rank) const;
  /// The whole mesh's cells of rank `rank`'s part, ascending, each once.
  std::vector<int> cells_of(int rank) const { return part_of(rank).cells; }

 private:
  struct Part {
    std::vector<int> cells, owners;  // ascending; the rank that owns each
  };
  Part part_of(int rank) const;

  const mesh::Mesh& mesh_;
  const WholeNumbering& whole_;
  const std::vector<assembly::Material>* materials_;
  std::vector<int> contact_cells_;   ///< Γ_C's cells, ascending, each once
  std::vector<int> contact_owners_;  ///< the rank owning each of them
  std::vector<int> first_;           ///< rank r owns by_rank_[first_[r] .. first_[r + 1])
  std::vector<int> by_rank_;         ///< the cells bucketed by rank, ascending within a rank
};

/// A rank's part as RankParts::bytes_for made it, its space with the local shapes added. `vector_space`
/// and `materials`: whether the first rank sent them (known alike on every rank).
RankSpace rank_space_from_bytes(const std::vector<char>& bytes, bool vector_space, bool materials);

}  // namespace hpcontact::operators
