// The operators of the elasticity problem on [S^p(T_h)]² that its contact problems share, built
// on first use: the stiffness A (a(u, v) = (λ div u, div v) + (2μ ε(u), ε(v))) factorized by
// static condensation with every Γ_C trace dof last, and the couplings of multiplier spaces on
// Γ_C with the normal and the tangential trace. A itself is never assembled.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "assembly/condensed_factor.hpp"
#include "assembly/coupling.hpp"
#include "assembly/elastic_system.hpp"
#include "core/operator_log.hpp"
#include "mesh/contact_boundary.hpp"
#include "operators/rank_space.hpp"
#include "space/h1_space.hpp"
#include "space/multiplier_space.hpp"
#include "space/vector_space.hpp"

namespace hpcontact::operators {

/// The norm of the displacement space in the inf-sup analysis: the vector H¹ norm
/// (‖∇v‖² + ‖v‖², componentwise: the scalar analysis's norm, independent of the material) or the
/// energy norm a(v, v) + ‖v‖², which depends on E and ν.
enum class PrimalNorm { h1, energy };
std::string to_string(PrimalNorm norm);

class ElasticOperators {
 public:
  /// `mesh` and `log` as for PrimalOperators (distributed, `mesh` may be freed once the object is
  /// built); `materials` one per cell.
  /// Γ_D clamps both components (u = 0 there); `fixed[c]` marks the boundary edges where
  /// component c alone vanishes (rollers; see space::VectorSpace).
  /// `distribution` other than serial: the factors are factorized over its ranks (every one of
  /// them must build the same operators in the same order), with one split of the cells, and
  /// everything lives on the rank's part of the mesh (as PrimalOperators).
  /// Distributed, `mesh`, the degrees, the materials and the masks are read on the first rank only
  /// (the others may pass null and empty ones: PrimalOperators).
  ElasticOperators(const mesh::Mesh* mesh, std::vector<int> cell_degrees, std::vector<assembly::Material> materials,
                   OperatorLog* log = nullptr, const std::array<std::vector<char>, space::kComponents>& fixed = {},
                   linalg::Distribution distribution = {});
  /// The same with the whole mesh at hand on every rank.
  ElasticOperators(const mesh::Mesh& mesh, std::vector<int> cell_degrees, std::vector<assembly::Material> materials,
                   OperatorLog* log = nullptr, const std::array<std::vector<char>, space::kComponents>& fixed = {},
                   linalg::Distribution distribution = {});
  ~ElasticOperators();

  /// The mesh the spaces live on: the whole one, or distributed the rank's part.
  const mesh::Mesh& mesh() const { return rank_.space->mesh(); }
  /// Whether the object was built on `mesh` with these degrees (PrimalOperators::built_on).
  bool built_on(const mesh::Mesh& mesh, const std::vector<int>& cell_degrees) const;
  /// What the object remembers of the whole mesh (h, Γ_D), which may be freed by now.
  const WholeMeshFacts& whole_mesh() const { return whole_; }
  /// The scalar space S^p(T_h), and the displacement space [S^p(T_h)]² with its rollers;
  /// distributed, on the rank's own cells and Γ_C's only, with the whole spaces' dofs.
  const space::H1Space& space() const { return *rank_.space; }
  const space::VectorSpace& vector_space() const { return *rank_.vector_space; }
  int n_dofs() const { return rank_.vector_space->n_dofs(); }
  const mesh::ContactBoundary& contact() const { return *contact_; }
  /// One per cell of mesh().
  const std::vector<assembly::Material>& materials() const { return materials_; }
  /// Distributed: the scalar space without elimination on the same cells (a lift's extended
  /// space; PrimalOperators::lift_space); null otherwise.
  const space::H1Space* lift_space() const { return rank_.lift_space(); }

  /// A factorized with the trace last ("factor(A)").
  /// @throws InputError if the body has neither a Dirichlet part nor rollers (A would be singular:
  /// rigid motions); NumericalError if rollers alone leave a rigid motion free.
  const assembly::CondensedFactor& stiffness_factor() const;
  /// The Gram matrix of `norm` on [S^p(T_h)]² factorized with the trace last ("factor(K+M)^2" or
  /// "factor(A+M)").
  const assembly::CondensedFactor& gram_factor(PrimalNorm norm) const;
  /// Frees every factorization (rebuilt on a later use), as PrimalOperators::release_factors.
  void release_factors() const;
  /// B^n or B^t of a multiplier space on Γ_C ("B_n", "B_t"), kept per multiplier space layout.
  const linalg::Coupling& coupling(const space::MultiplierSpace& multipliers, assembly::TraceDirection direction) const;
  /// Both components of every scalar dof with a trace on Γ_C (the trailing set of the factor).
  const std::vector<int>& trace_dofs() const;
  OperatorLog* log() const { return log_; }
  linalg::Distribution distribution() const { return distribution_; }

 private:
  WholeMeshFacts whole_;  ///< of the mesh given to the constructor
  RankSpace rank_;        ///< the space (distributed: on the rank's part of the mesh) and its split
  /// The rigid rotation's centre for BDDC's near null space: the whole mesh's vertex centroid, the
  /// same on every rank.
  mesh::Point rotation_centre_ = mesh::Point(0.0, 0.0);
  std::unique_ptr<mesh::ContactBoundary> contact_;
  std::vector<assembly::Material> materials_;
  OperatorLog* log_;
  linalg::Distribution distribution_;
  mutable std::unique_ptr<assembly::CondensedFactor> stiffness_factor_;
  mutable std::map<PrimalNorm, std::unique_ptr<assembly::CondensedFactor>> gram_factors_;
  mutable std::unique_ptr<std::vector<int>> trace_dofs_;
  mutable std::map<std::string, linalg::Coupling> couplings_;
};

}  // namespace hpcontact::operators
