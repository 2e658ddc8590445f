// The part of S^p(T_h) that one rank builds. Serial: the whole space. Distributed: the first rank
// alone holds the whole mesh; it numbers the space, splits the cells over the ranks (weighted by
// their unknowns) and sends each rank its part of the mesh (its own cells and Γ_C's: every rank
// assembles the couplings B, trace-sized) with the part's share of the numbering, so that no other
// rank holds an array of the whole mesh's length. The rank then adds the local shapes of its part.
#pragma once

#include <mpi.h>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "assembly/material.hpp"
#include "linalg/distribution.hpp"
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
  /// Distributed elasticity: the materials of the part's cells (the whole list when serial is the
  /// caller's).
  std::vector<assembly::Material> materials;

  /// Distributed: the space without elimination on the same cells (a Dirichlet lift's extended
  /// space, which a part cannot number alone; `space` itself without Γ_D); serial: null (the lift
  /// builds it from the whole mesh).
  const space::H1Space* lift_space() const { return kept ? kept.get() : part ? space.get() : nullptr; }
};

using RollerMasks = std::array<std::vector<char>, space::kComponents>;

/// The scalar space, or with `rollers` (elasticity: space::VectorSpace's masks over the whole
/// mesh's edges) also the vector space, whose two unknowns per scalar shape then weigh the cells.
/// Serial: on `mesh`, which must outlive the result. Distributed: `mesh`, `cell_degrees`, the masks
/// and `materials` (one per cell, restricted to the part) are read on the first rank of
/// `distribution.ranks` only (the others may pass null and empty ones; `rollers` and `materials`
/// given or not alike on every rank), and the result lives on the rank's part. Collective on
/// `distribution.ranks` when distributed; a failure (a degree < 1) is raised on every rank.
RankSpace build_rank_space(const mesh::Mesh* mesh, std::vector<int> cell_degrees, linalg::Distribution distribution,
                           const RollerMasks* rollers = nullptr,
                           const std::vector<assembly::Material>* materials = nullptr);

/// What an operator object remembers of the whole mesh it was built from: its address and sizes,
/// compared, never dereferenced, and the facts of it that a run asks later (h, whether Γ_D
/// exists, the smallest p_T), so that a distributed run may free the whole mesh and its cells'
/// degrees once the object holds its part (the address alone could be reused by a later mesh).
class WholeMeshFacts {
 public:
  /// The facts of `mesh`. Distributed, those of the first rank's mesh on every rank of
  /// `distribution.ranks` (collective), where `mesh` may be null on the others (is() is then false).
  WholeMeshFacts(const mesh::Mesh* mesh, const std::vector<int>& cell_degrees, linalg::Distribution distribution = {});
  /// Whether `mesh` is the mesh these facts were taken of (as far as address and sizes tell).
  bool is(const mesh::Mesh& mesh) const;
  /// h: the whole mesh's longest edge (a part's would be its own cells').
  double longest_edge() const { return longest_edge_; }
  /// Whether some edge of the whole mesh is on Γ_D (a part may have none).
  bool has_dirichlet() const { return has_dirichlet_; }
  /// The smallest p_T over the whole mesh (a part's own can be higher).
  int smallest_degree() const { return smallest_degree_; }
  /// The mean of the whole mesh's vertices (the rigid rotation's centre in elasticity).
  mesh::Point vertex_mean() const { return {vertex_mean_[0], vertex_mean_[1]}; }

 private:
  // Plain values only: the first rank sends the object as it is.
  std::uintptr_t address_ = 0;
  int cells_ = 0, vertices_ = 0, edges_ = 0, smallest_degree_ = 0;
  double longest_edge_ = 0.0;
  double vertex_mean_[2] = {0.0, 0.0};
  bool has_dirichlet_ = false;
};

/// Whether `space`, built from the whole mesh `built_from` identifies, is of `mesh` with these
/// degrees (compared on the space's cells): a shared operator object's check.
bool space_built_on(const space::H1Space& space, const WholeMeshFacts& built_from, const mesh::Mesh& mesh,
                    const std::vector<int>& cell_degrees);

}  // namespace hpcontact::operators
