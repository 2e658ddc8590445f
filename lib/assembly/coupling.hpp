// Coupling between S^p(T_h) and M^{p_C}(T_{C,H}) on Γ_C, integrated exactly on the common
// refinement of T_h|Γ_C and T_{C,H} (H need not be a multiple of h):
//   B_ij   = ∫_{Γ_C} μ_i φ_j ds,        B^s_ij = ∫_{Γ_C} s μ_i φ_j ds,      g_i = ∫_{Γ_C} g μ_i ds.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "linalg/coupling_matrix.hpp"
#include "mesh/contact_boundary.hpp"
#include "space/h1_space.hpp"
#include "space/multiplier_space.hpp"
#include "space/vector_space.hpp"

namespace hpcontact::assembly {

using BoundaryFunction = std::function<double(const mesh::Point&)>;

/// The weight s of B^s with its identity. The operators' caches key B^s and S^s = B^s K⁻¹ (B^s)ᵀ
/// on identity(), so that two weights on the same operators never share a cached matrix, which a
/// name ("B^s") alone could not tell apart. A weight given with a key (a scene's text of s) is
/// identified by it: weights with the same key must be the same function, and then share B^s.
/// Without a key a weight is identified by its object, shared by its copies. Empty: no weight (B).
class CouplingWeight {
 public:
  CouplingWeight() = default;
  template <class F>
  requires(!std::is_same_v<std::decay_t<F>, CouplingWeight> &&
           std::is_invocable_r_v<double, const F&, const mesh::Point&>)
      CouplingWeight(F function, std::string key = {})  // NOLINT(google-explicit-constructor): a weight is its function
      : function_(std::make_shared<const BoundaryFunction>(std::move(function))), key_(std::move(key)) {}
  double operator()(const mesh::Point& x) const { return (*function_)(x); }
  explicit operator bool() const { return function_ && *function_; }
  /// The function; empty for no weight.
  const BoundaryFunction& function() const;
  /// The key, else the address of the function shared by the copies (unique while they live);
  /// empty for no weight.
  std::string identity() const;
  /// The key given at construction (e.g. the scene file and key of the data), empty if none.
  const std::string& key() const { return key_; }

 private:
  std::shared_ptr<const BoundaryFunction> function_;
  std::string key_;
};

/// B (no weight) or B^s (weight s): shape (n_multiplier_dofs, n_primal_dofs). With a weight the
/// rule gets 4 extra Gauss points (s is data, not a polynomial).
/// @throws InputError if the boundary mesh does not span Γ_C.
linalg::Coupling assemble_coupling(const space::H1Space& space, const mesh::ContactBoundary& contact,
                                   const space::MultiplierSpace& multipliers, const BoundaryFunction& weight = {});

/// Adds `local` (rows: the multipliers of one segment from `first_multiplier` on; columns: one
/// cell's shapes in the order of `shapes`) to `triplets`, leaving out shapes without a dof and
/// zeros.
void add_cell_coupling(std::vector<Eigen::Triplet<double>>& triplets, const Eigen::MatrixXd& local,
                       std::span<const space::LocalShape> shapes, int first_multiplier);

/// The normal of Γ_C (outward from Ω) or its unit tangent (along increasing arc length s).
enum class TraceDirection { normal, tangent };
/// That direction at arc length s (constant along a straight trace edge).
mesh::Point trace_direction(const mesh::ContactBoundary& contact, double s, TraceDirection direction);

/// B^d_{i,(j,c)} = ∫_{Γ_C} μ_i φ_j d_c ds with d the normal or the tangent: the pairing of a
/// multiplier with the normal (tangential) component of a field of [S^p(T_h)]², shape
/// (n_multiplier_dofs, space.n_dofs()), columns numbered by space::VectorSpace::dof.
linalg::Coupling assemble_directional_coupling(const space::VectorSpace& space, const mesh::ContactBoundary& contact,
                                               const space::MultiplierSpace& multipliers, TraceDirection direction);

/// g_i = ∫ g μ_i ds, shape (n_multiplier_dofs).
Eigen::VectorXd assemble_multiplier_load(const mesh::ContactBoundary& contact,
                                         const space::MultiplierSpace& multipliers, const BoundaryFunction& g);
/// The same for g given as a function of the arc length s on Γ_C.
Eigen::VectorXd assemble_multiplier_load(const mesh::ContactBoundary& contact,
                                         const space::MultiplierSpace& multipliers,
                                         const std::function<double(double)>& g_of_arc);

/// @throws InputError unless `boundary_mesh` spans Γ_C of `contact` and breaks at the ends of its
/// zones (open and closed alike): what a coupling between the two needs.
void check_multiplier_mesh(const mesh::ContactBoundary& contact, const mesh::BoundaryMesh& boundary_mesh);

/// The sub-intervals of the common refinement of T_h|Γ_C and T_{C,H}, each inside one trace
/// edge and one segment.
struct CommonInterval {
  double s_begin, s_end;
  int trace_edge;  ///< index into contact.edges()
  int segment;
};
std::vector<CommonInterval> common_intervals(const mesh::ContactBoundary& contact,
                                             const mesh::BoundaryMesh& boundary_mesh);

}  // namespace hpcontact::assembly
