// [S^p(T_h)]³ on a hexahedral mesh: three displacement components on the shapes of one scalar space,
// with components held on chosen boundary faces (rollers) besides Γ_D, where the scalar space has
// eliminated every component.
#pragma once

#include <array>
#include <vector>

#include "space/solid_space.hpp"

namespace hpcontact::space {

/// Dof of component c of scalar dof d: numbered d by d, c by c, skipping held ones, so the
/// skeleton (the scalar skeleton's components) comes first.
class SolidVectorSpace {
 public:
  /// `held_faces[c]`: per face of the mesh, whether component c vanishes on it (empty: nowhere).
  /// @throws InputError if a flagged face is not a boundary face.
  SolidVectorSpace(const SolidH1Space& scalar, const std::array<std::vector<char>, 3>& held_faces = {});

  const SolidH1Space& scalar() const { return *scalar_; }
  int n_dofs() const { return n_dofs_; }
  int n_skeleton_dofs() const { return n_skeleton_dofs_; }
  /// The dof of component c of scalar dof d (−1 where it is held or d is −1).
  int dof(int scalar_dof, int component) const {
    return scalar_dof < 0 ? -1 : dofs_[3 * static_cast<std::size_t>(scalar_dof) + component];
  }

 private:
  const SolidH1Space* scalar_;
  std::vector<int> dofs_;  ///< 3 per scalar dof
  int n_dofs_ = 0, n_skeleton_dofs_ = 0;
};

/// The scalar dofs whose shapes do not vanish on the boundary face (vertex, edge and face dofs).
std::vector<int> dofs_on_face(const SolidH1Space& space, const mesh::BoundaryFace& face);

}  // namespace hpcontact::space
