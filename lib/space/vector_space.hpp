// [S^p(T_h)]², the displacement space of elasticity: two components per dof of the scalar space
// S^p(T_h) (whose Dirichlet elimination on Γ_D holds both components), and boundary edges on which
// one component alone vanishes (rollers: u_x = 0 or u_y = 0, the other component free).
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "space/h1_space.hpp"

namespace hpcontact::space {

inline constexpr int kComponents = 2;

class VectorSpace {
 public:
  /// `fixed[c][e]` non-zero: component c vanishes on boundary edge e (closed: with its
  /// vertices); each either empty (nowhere) or of size n_edges. Unknowns are numbered scalar dof
  /// by scalar dof, x before y, so that skeleton unknowns stay before interior ones.
  /// @throws InputError if a mask has the wrong size or marks an interior edge.
  explicit VectorSpace(const H1Space& scalar, const std::array<std::vector<char>, kComponents>& fixed = {});

  /// `numbering`'s rollers and unknowns on `scalar`, the same scalar space restricted to a part of
  /// the mesh (H1Space::restricted_to), whose edges cannot find the rollers alone.
  VectorSpace(const H1Space& scalar, const VectorSpace& numbering);

  /// The rollers and unknowns as bytes, and back on a scalar space of the same numbering (a part's:
  /// VectorSpace(scalar, numbering) without the whole mesh's numbering at hand).
  void pack(ByteWriter& out) const;
  static VectorSpace unpack(ByteReader& in, const H1Space& scalar);

  const H1Space& scalar() const { return *scalar_; }
  int n_dofs() const { return n_dofs_; }
  int n_skeleton_dofs() const { return n_skeleton_dofs_; }
  /// The unknown of component c of scalar dof d; -1 where it is eliminated (d < 0, or fixed).
  int dof(int scalar_dof, int component) const {
    if (scalar_dof < 0) return -1;
    const int slot = kComponents * scalar_dof + component;
    return fixed_.empty() ? slot : dof_with_rollers(slot);
  }
  /// Whether some edge fixes one component alone.
  bool has_rollers() const { return !fixed_.empty(); }
  /// The coefficients of one component over the scalar dofs (0 where fixed), shape (scalar n_dofs).
  Eigen::VectorXd component(const Eigen::VectorXd& u, int component) const;
  /// The unknowns of the field with these component coefficients (each of scalar size).
  Eigen::VectorXd from_components(const Eigen::VectorXd& x, const Eigen::VectorXd& y) const;

 private:
  int dof_with_rollers(int slot) const;

  const H1Space* scalar_;
  /// The slots kComponents · d + c that rollers fix, ascending: an unknown is its slot less the
  /// fixed slots before it. Boundary-sized, where a table of every slot would be of the global
  /// length on every rank.
  std::vector<int> fixed_;
  int n_dofs_ = 0, n_skeleton_dofs_ = 0;
};

}  // namespace hpcontact::space
