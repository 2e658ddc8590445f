// The part of S^p(T_h) that one rank builds. Serial: the whole space. Distributed: the cells are
// split over the ranks first (weighted by their unknowns), and the rank keeps the local shapes of
// its own cells and of the cells on Γ_C (trace-sized: every rank assembles the couplings B), not
// the whole mesh's table: either as a space on the whole mesh holding those cells, or, on the
// rank's part of the mesh (mesh::Mesh::extract), as the whole space restricted to the part, whose
// tables all have the part's length.
#pragma once

#include <memory>
#include <vector>

#include "linalg/distribution.hpp"
#include "mesh/contact_boundary.hpp"
#include "space/h1_space.hpp"

namespace hpcontact::operators {

struct RankSpace {
  /// Distributed on a part: the rank's own cells and Γ_C's, on which `space` (and `kept`) live.
  std::unique_ptr<mesh::Mesh> part;
  std::unique_ptr<space::H1Space> space;
  /// On a part with a Dirichlet part of the boundary: the space on the same cells with Γ_D's dofs
  /// kept (where a Dirichlet lift lives; a part cannot number it alone). Null otherwise.
  std::unique_ptr<space::H1Space> kept;
  /// The rank that eliminates each cell of the space's mesh; empty when serial.
  std::vector<int> cell_parts;
};

/// Where a distributed rank's space lives: on the whole mesh holding the rank's cells, or on its part.
enum class RankLayout { whole_mesh, part };

/// `components` unknowns per scalar shape (1, or 2 for elasticity) weigh the cells. Collective on
/// `distribution.ranks` when distributed.
RankSpace build_rank_space(const mesh::Mesh& mesh, std::vector<int> cell_degrees, const mesh::ContactBoundary& contact,
                           int components, linalg::Distribution distribution, RankLayout layout);

}  // namespace hpcontact::operators
