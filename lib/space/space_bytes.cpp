// The spaces of a part of the mesh as bytes, and back: the numbering of S^p(T_h) restricted to a
// part (H1Space::restricted_to, without shapes) and the rollers of [S^p(T_h)]², so that the first
// rank of a distributed run can number the whole space and send each rank its part's share.
#include "core/byte_buffer.hpp"
#include "core/error.hpp"
#include "space/h1_space.hpp"
#include "space/vector_space.hpp"

namespace hpcontact::space {

void H1Space::pack(ByteWriter& out) const {
  HPC_VERIFY(mesh_->is_part() && !holds_shapes(), "the numbering of a space restricted to a part is sent");
  out.put(n_dofs_);
  out.put(n_skeleton_dofs_);
  out.put(max_degree_);
  out.put(cell_degrees_);
  out.put(edge_degrees_);
  out.put(vertex_dofs_);
  out.put(edge_first_dofs_);
  out.put(first_interior_);
}

H1Space H1Space::unpack(ByteReader& in, const mesh::Mesh& part) {
  H1Space out;
  out.mesh_ = &part;
  out.n_dofs_ = in.get<int>();
  out.n_skeleton_dofs_ = in.get<int>();
  out.max_degree_ = in.get<int>();
  out.cell_degrees_ = in.get_vector<int>();
  out.edge_degrees_ = in.get_vector<int>();
  out.vertex_dofs_ = in.get_vector<int>();
  out.edge_first_dofs_ = in.get_vector<int>();
  out.first_interior_ = in.get_vector<int>();
  HPC_VERIFY(part.is_part() && static_cast<int>(out.cell_degrees_.size()) == part.n_cells() &&
                 static_cast<int>(out.first_interior_.size()) == part.n_cells() &&
                 static_cast<int>(out.edge_degrees_.size()) == part.n_edges() &&
                 static_cast<int>(out.edge_first_dofs_.size()) == part.n_edges() &&
                 static_cast<int>(out.vertex_dofs_.size()) == part.n_vertices(),
             "a space's bytes of another part");
  out.first_shape_.assign(part.n_cells() + 1, 0);
  return out;
}

void VectorSpace::pack(ByteWriter& out) const {
  out.put(fixed_);
  out.put(n_dofs_);
  out.put(n_skeleton_dofs_);
}

VectorSpace VectorSpace::unpack(ByteReader& in, const H1Space& scalar) {
  VectorSpace out(scalar);
  out.fixed_ = in.get_vector<int>();
  out.n_dofs_ = in.get<int>();
  out.n_skeleton_dofs_ = in.get<int>();
  return out;
}

}  // namespace hpcontact::space
