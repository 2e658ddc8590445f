// The part of S^p(T_h) that one rank builds. Serial: the whole space. Distributed: the cells are
// split over the ranks first (weighted by their unknowns), and the rank keeps the local shapes of
// its own cells and of the cells on Γ_C (trace-sized: every rank assembles the couplings B), not
// the whole mesh's table, which was the largest array every rank held whole.
#pragma once

#include <memory>
#include <vector>

#include "linalg/distribution.hpp"
#include "mesh/contact_boundary.hpp"
#include "space/h1_space.hpp"

namespace hpcontact::operators {

struct RankSpace {
  std::unique_ptr<space::H1Space> space;
  /// The rank that eliminates each cell (split_cells_over_ranks); empty when serial.
  std::vector<int> cell_parts;
};

/// `components` unknowns per scalar shape (1, or 2 for elasticity) weigh the cells. Collective on
/// `distribution.ranks` when distributed.
RankSpace build_rank_space(const mesh::Mesh& mesh, std::vector<int> cell_degrees, const mesh::ContactBoundary& contact,
                           int components, linalg::Distribution distribution);

}  // namespace hpcontact::operators
