// Numbering of the vector space on hexahedra with rollers.
#include "space/solid_vector_space.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/error.hpp"

namespace hpcontact::space {

std::vector<int> dofs_on_face(const SolidH1Space& space, const mesh::BoundaryFace& face) {
  std::vector<int> dofs;
  for (const auto& shape : space.cell_shapes(face.cell))
    if (shape.dof >= 0 && shape_on_face(space.mesh(), shape, face.local_face)) dofs.push_back(shape.dof);
  return dofs;
}

SolidVectorSpace::SolidVectorSpace(const SolidH1Space& scalar, const std::array<std::vector<char>, 3>& held_faces)
    : scalar_(&scalar) {
  const mesh::SolidMesh& mesh = scalar.mesh();
  std::vector<char> held(3 * static_cast<std::size_t>(scalar.n_dofs()), 0);
  for (int c = 0; c < 3; ++c) {
    if (held_faces[c].empty()) continue;
    HPC_VERIFY(static_cast<int>(held_faces[c].size()) == mesh.n_faces(), "one flag per face");
    for (int f = 0; f < mesh.n_faces(); ++f)
      if (held_faces[c][f] && !mesh.is_boundary_face(f))
        throw InputError(fmt::format("face {} is flagged to hold component {} but lies inside the mesh", f, c));
    for (const auto& face : mesh.boundary_faces())
      if (held_faces[c][mesh.cell_face(face.cell, face.local_face)])
        for (int d : dofs_on_face(scalar, face)) held[3 * static_cast<std::size_t>(d) + c] = 1;
  }
  dofs_.assign(held.size(), -1);
  for (std::size_t k = 0; k < held.size(); ++k) {
    if (k == 3 * static_cast<std::size_t>(scalar.n_skeleton_dofs())) n_skeleton_dofs_ = n_dofs_;
    if (!held[k]) dofs_[k] = n_dofs_++;
  }
  if (scalar.n_skeleton_dofs() == scalar.n_dofs()) n_skeleton_dofs_ = n_dofs_;
}

}  // namespace hpcontact::space
