// The operators of S^p(T_h) that the contact problems and the inf-sup analysis share, built on
// first use and never twice: the couplings with multiplier spaces on Γ_C, and the factorizations
// of K and A_G = K + M (cell interiors condensed out, every Γ_C trace dof ordered last), so that
// B A⁻¹ Bᵀ for ANY multiplier space on Γ_C (any p_C, H, weight s) is dense work on the trace
// only. K and M themselves are never assembled. One object per (T_h, p): a `solve` with α, or
// all sweep points on (n, p), share it.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "assembly/condensed_factor.hpp"
#include "assembly/coupling.hpp"
#include "core/operator_log.hpp"
#include "mesh/contact_boundary.hpp"
#include "operators/rank_space.hpp"
#include "space/h1_space.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::operators {

class PrimalOperators {
 public:
  /// `log`, when given, must outlive the object, and so must `mesh` when serial (the space lives on
  /// it); distributed, the object keeps only the rank's part, and `mesh` may be freed once it is
  /// built (built_on then cannot be asked of it). Builds the space and Γ_C only, and,
  /// distributed, splits the cells over the ranks first (collectively: operators/rank_space.hpp)
  /// and builds everything on the rank's part of the mesh (its own cells and Γ_C's).
  /// `distribution` other than serial: the factors are factorized over its ranks (every one of
  /// them must construct the object and make the same calls on it, in the same order).
  /// `mesh` and `cell_degrees` are read on the first rank of a distributed run only: it numbers
  /// the space, splits the cells and sends each rank its part (operators/rank_space.hpp), so the
  /// others may pass null and nothing (built_on is then false for any mesh).
  PrimalOperators(const mesh::Mesh* mesh, std::vector<int> cell_degrees, OperatorLog* log = nullptr,
                  linalg::Distribution distribution = {});
  /// The same with the whole mesh at hand on every rank.
  PrimalOperators(const mesh::Mesh& mesh, std::vector<int> cell_degrees, OperatorLog* log = nullptr,
                  linalg::Distribution distribution = {});
  ~PrimalOperators();

  /// The mesh the space lives on: the whole one, or distributed the rank's part (global_cell etc.
  /// give the whole mesh's indices), so that cell indices of space(), contact() and cell_parts()
  /// agree.
  const mesh::Mesh& mesh() const { return rank_.space->mesh(); }
  /// Whether the object was built on `mesh` (the whole mesh given to the constructor) with these
  /// degrees (compared on the space's cells).
  bool built_on(const mesh::Mesh& mesh, const std::vector<int>& cell_degrees) const;
  /// What the object remembers of the whole mesh (h, Γ_D), which may be freed by now.
  const WholeMeshFacts& whole_mesh() const { return whole_; }
  /// Distributed, the rank's own cells and Γ_C's only, with the whole space's dofs.
  const space::H1Space& space() const { return *rank_.space; }
  /// Distributed: the space without elimination on the same cells (a Dirichlet lift's extended
  /// space, which a part cannot number alone; space() itself without Γ_D); serial: null (the lift
  /// builds it).
  const space::H1Space* lift_space() const { return rank_.lift_space(); }
  const mesh::ContactBoundary& contact() const { return *contact_; }

  /// Where a factorization puts Γ_C's trace: last, so that a Schur complement B A⁻¹ Bᵀ costs dense
  /// algebra of the trace's size (linalg/sparse_cholesky.hpp), or wherever the fill-reducing
  /// ordering wants it, so that it costs one pair of triangular solves per row of B.
  enum class TraceOrdering { last, free };

  /// K factorized with the trace last ("factor(K)"), and A_G = K + M ("factor(K+M)") with the
  /// trace as `ordering` says on its first use (later calls get that factorization), both by static
  /// condensation from the element matrices (neither needs K or M assembled).
  const assembly::CondensedFactor& stiffness_factor() const;
  const assembly::CondensedFactor& gram_factor(TraceOrdering ordering = TraceOrdering::last) const;
  /// Frees both factorizations (rebuilt on a later use): a run's output phase, which needs none,
  /// then does not hold them beside its files' text.
  void release_factors() const;
  /// B_ij = ∫ μ_i φ_j ("B"), or with the weight s ("B^s"), for a multiplier space on Γ_C; kept per
  /// (name, weight, multiplier space layout), so that the contact solve and α share it. The weight
  /// is kept alive with it (its identity is part of the key).
  const linalg::Coupling& coupling(const space::MultiplierSpace& multipliers, const assembly::CouplingWeight& weight,
                                   const std::string& name) const;
  /// The key under which `coupling` keeps B: `name`, the weight's identity and the multiplier
  /// space's layout.
  static std::string coupling_key(const space::MultiplierSpace& multipliers, const std::string& name,
                                  const assembly::CouplingWeight& weight = {});
  /// A vector or dense matrix derived from the operators above (the load F of one f, the
  /// condensed S = B K⁻¹ Bᵀ of one coupling), built by `build` on first use under `key` and
  /// logged as `name`, so that problems sharing data share it (Signorini and (15) share B and S).
  const Eigen::VectorXd& derived_vector(const std::string& name, const std::string& key,
                                        const std::function<Eigen::VectorXd()>& build) const;
  const Eigen::MatrixXd& derived_matrix(const std::string& name, const std::string& key,
                                        const std::function<Eigen::MatrixXd()>& build) const;
  /// Every dof with a trace on Γ_C (the trailing set of factor(K), and of factor(K+M) unless it is
  /// ordered freely).
  const std::vector<int>& trace_dofs() const;
  /// Distributed: the rank that eliminates each cell of mesh() (the rank's part: its own cells and
  /// Γ_C's), computed once (collectively, when the object is built) for both factorizations,
  /// weighted by the cells' unknowns; empty when serial (operators/rank_space.hpp).
  const std::vector<int>& cell_parts() const { return rank_.cell_parts; }
  OperatorLog* log() const { return log_; }
  linalg::Distribution distribution() const { return distribution_; }

 private:
  WholeMeshFacts whole_;  ///< of the mesh given to the constructor
  RankSpace rank_;        ///< the space (distributed: on the rank's part of the mesh) and its split
  std::unique_ptr<mesh::ContactBoundary> contact_;
  OperatorLog* log_;
  linalg::Distribution distribution_;
  mutable std::unique_ptr<assembly::CondensedFactor> stiffness_factor_, gram_factor_;
  mutable std::unique_ptr<std::vector<int>> trace_dofs_;
  mutable std::map<std::string, linalg::Coupling> couplings_;
  /// The weights of couplings_, kept so that the identities of those without a key stay unique.
  mutable std::vector<assembly::CouplingWeight> weights_;
  mutable std::map<std::string, Eigen::VectorXd> derived_vectors_;
  mutable std::map<std::string, Eigen::MatrixXd> derived_matrices_;
};

/// `shared` when given (checked to belong to `mesh` and the degrees when `mesh` is given: a
/// distributed run may have freed it), else a new object on `mesh` kept in `own`.
/// @pre `shared` or `mesh` is given.
const PrimalOperators& shared_or_own(const PrimalOperators* shared, const mesh::Mesh* mesh,
                                     const std::vector<int>& cell_degrees, std::unique_ptr<PrimalOperators>& own);

}  // namespace hpcontact::operators
