// The part of S^p(T_h) that one rank builds. Serial: the whole space. Distributed: the cells are
// split over the ranks first (weighted by their unknowns), and the rank keeps the local shapes of
// its own cells and of the cells on Γ_C (trace-sized: every rank assembles the couplings B), not
// the whole mesh's table: on the rank's part of the mesh (mesh::Mesh::extract), the whole space
// restricted to the part, whose tables all have the part's length.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "linalg/distribution.hpp"
#include "mesh/contact_boundary.hpp"
#include "space/h1_space.hpp"
#include "space/vector_space.hpp"

namespace hpcontact::operators {

struct RankSpace {
  /// Distributed: the rank's own cells and Γ_C's, on which `space` (and `kept`) live.
  std::unique_ptr<mesh::Mesh> part;
  std::unique_ptr<space::H1Space> space;
  /// Elasticity: [S^p(T_h)]² on `space` with the rollers asked for.
  std::unique_ptr<space::VectorSpace> vector_space;
  /// Distributed, with a Dirichlet part of the boundary: the space on the same cells with Γ_D's dofs
  /// kept (where a Dirichlet lift lives; a part cannot number it alone), its numbering only (a lift
  /// adds the shapes: H1Space::with_shapes). Null otherwise (without Γ_D it would be `space`).
  std::unique_ptr<space::H1Space> kept;
  /// The rank that eliminates each cell of the space's mesh; empty when serial.
  std::vector<int> cell_parts;

  /// Distributed: the space without elimination on the same cells (a Dirichlet lift's extended
  /// space, which a part cannot number alone; `space` itself without Γ_D); serial: null (the lift
  /// builds it from the whole mesh).
  const space::H1Space* lift_space() const { return kept ? kept.get() : part ? space.get() : nullptr; }
};

using RollerMasks = std::array<std::vector<char>, space::kComponents>;

/// The scalar space, or with `rollers` (elasticity: space::VectorSpace's masks over the whole
/// mesh's edges) also the vector space, whose two unknowns per scalar shape then weigh the cells.
/// Collective on `distribution.ranks` when distributed.
RankSpace build_rank_space(const mesh::Mesh& mesh, std::vector<int> cell_degrees, const mesh::ContactBoundary& contact,
                           linalg::Distribution distribution, const RollerMasks* rollers = nullptr);

/// What an operator object remembers of the whole mesh it was built from: its address and sizes,
/// compared, never dereferenced, and the facts of it that a run asks later (h, whether Γ_D
/// exists, the smallest p_T), so that a distributed run may free the whole mesh and its cells'
/// degrees once the object holds its part (the address alone could be reused by a later mesh).
class WholeMeshFacts {
 public:
  WholeMeshFacts(const mesh::Mesh& mesh, const std::vector<int>& cell_degrees);
  /// Whether `mesh` is the mesh these facts were taken of (as far as address and sizes tell).
  bool is(const mesh::Mesh& mesh) const;
  /// h: the whole mesh's longest edge (a part's would be its own cells').
  double longest_edge() const { return longest_edge_; }
  /// Whether some edge of the whole mesh is on Γ_D (a part may have none).
  bool has_dirichlet() const { return has_dirichlet_; }
  /// The smallest p_T over the whole mesh (a part's own can be higher).
  int smallest_degree() const { return smallest_degree_; }

 private:
  std::uintptr_t address_;
  int cells_, vertices_, edges_, smallest_degree_;
  double longest_edge_;
  bool has_dirichlet_;
};

/// Whether `space`, built from the whole mesh `built_from` identifies, is of `mesh` with these
/// degrees (compared on the space's cells): a shared operator object's check.
bool space_built_on(const space::H1Space& space, const WholeMeshFacts& built_from, const mesh::Mesh& mesh,
                    const std::vector<int>& cell_degrees);

}  // namespace hpcontact::operators
