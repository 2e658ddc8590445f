// Helper of distributed_factor_test, run under mpirun: the first rank alone holds the mesh and
// sends every rank its part (operators::build_rank_space). Each rank also builds the whole mesh
// and space itself, here only, to check its part against them: the same global dofs, signs and
// modes on every cell of the part, the same rollers, the space with Γ_D's dofs kept, the
// materials, Γ_C's cells all held, every cell owned by exactly one rank, and a part smaller than
// the whole mesh on every rank. Rank 0 prints one line per mesh:
//   NAME mismatches M owned O cells C smaller S
//
//   rank_space_check          the p-graded square (quadrilaterals) and its triangles
//   rank_space_check bad      a degree 0 on the first rank: every rank must fail alike
#include <fmt/format.h>

#include <string>

#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "core/rank_agreement.hpp"
#include "mesh/contact_boundary.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "mesh/refine.hpp"
#include "operators/rank_space.hpp"
#include "support/helper_failure.hpp"

using namespace hpcontact;

namespace {

bool same_shape(const space::LocalShape& a, const space::LocalShape& b) {
  return a.i == b.i && a.j == b.j && a.dof == b.dof && a.sign == b.sign && a.role == b.role && a.entity == b.entity;
}

// Differences of `part`'s shapes from the whole space's on the same cells.
int shape_mismatches(const space::H1Space& part, const space::H1Space& whole) {
  int mismatches = 0;
  const auto& mesh = part.mesh();
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const auto mine = part.cell_shapes(c), theirs = whole.cell_shapes(mesh.global_cell(c));
    if (mine.size() != theirs.size()) {
      ++mismatches;
      continue;
    }
    for (std::size_t k = 0; k < mine.size(); ++k) mismatches += !same_shape(mine[k], theirs[k]);
  }
  return mismatches;
}

int sum_over_ranks(int value) {
  int sum = 0;
  MPI_Allreduce(&value, &sum, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  return sum;
}

void check(const std::string& name, const mesh::Mesh& mesh, const std::vector<int>& degrees) {
  const auto [rank, ranks] = mpi_rank_and_size();
  const auto distribution = linalg::distribution_over(MPI_COMM_WORLD, linalg::DistributedSolver::substructuring);
  // Rollers on the left side (component x), a material per cell.
  operators::RollerMasks rollers;
  rollers[0].assign(mesh.n_edges(), 0);
  for (int e : mesh.boundary_edges())
    if (mesh.edge_part(e) == mesh::BoundaryPart::neumann && mesh.edge_midpoint(e).x() < -0.999) rollers[0][e] = 1;
  std::vector<assembly::Material> materials(mesh.n_cells());
  for (int c = 0; c < mesh.n_cells(); ++c) materials[c] = {1.0 + c, 2.0 + c, 0.5 * c};
  const bool first = rank == 0;
  const operators::RollerMasks none;
  const std::vector<assembly::Material> no_materials;
  const auto got =
      operators::build_rank_space(first ? &mesh : nullptr, first ? degrees : std::vector<int>{}, distribution,
                                  first ? &rollers : &none, first ? &materials : &no_materials);
  const operators::WholeMeshFacts facts(first ? &mesh : nullptr, first ? degrees : std::vector<int>{}, distribution);

  const space::H1Space whole(mesh, degrees);
  const space::VectorSpace whole_vector(whole, rollers);
  const space::H1Space kept(mesh, degrees, space::DirichletDofs::kept);
  const auto& part = *got.part;
  int mismatches = shape_mismatches(*got.space, whole);
  mismatches += got.space->n_dofs() != whole.n_dofs() || got.space->n_skeleton_dofs() != whole.n_skeleton_dofs();
  mismatches += got.vector_space->n_dofs() != whole_vector.n_dofs() ||
                got.vector_space->n_skeleton_dofs() != whole_vector.n_skeleton_dofs();
  for (int c = 0; c < part.n_cells(); ++c)
    for (const auto& shape : got.space->cell_shapes(c))
      for (int k = 0; k < space::kComponents; ++k)
        mismatches += got.vector_space->dof(shape.dof, k) != whole_vector.dof(shape.dof, k);
  mismatches += got.kept ? shape_mismatches(got.kept->with_shapes(), kept) : 1;
  mismatches += static_cast<int>(got.materials.size()) != part.n_cells();
  for (int c = 0; c < part.n_cells() && c < static_cast<int>(got.materials.size()); ++c) {
    const auto &mine = got.materials[c], &theirs = materials[part.global_cell(c)];
    mismatches += mine.lambda != theirs.lambda || mine.mu != theirs.mu || mine.out_of_plane != theirs.out_of_plane;
  }
  mismatches += facts.longest_edge() != mesh.longest_edge() || facts.smallest_degree() != 1 || !facts.has_dirichlet() ||
                facts.is(mesh) != first;
  // Γ_C's cells all held; each cell owned by one rank.
  const mesh::ContactBoundary contact(mesh);
  std::vector<char> held(mesh.n_cells(), 0);
  for (int c = 0; c < part.n_cells(); ++c) held[part.global_cell(c)] = 1;
  for (const auto& edge : contact.edges()) mismatches += !held[edge.cell];
  int owned = 0;
  for (int c = 0; c < part.n_cells(); ++c) {
    mismatches += got.cell_parts[c] < 0 || got.cell_parts[c] >= ranks;
    owned += got.cell_parts[c] == rank;
  }
  const int smaller = sum_over_ranks(part.n_cells() < mesh.n_cells() ? 1 : 0);
  mismatches = sum_over_ranks(mismatches);
  owned = sum_over_ranks(owned);
  if (first)
    fmt::print("{} mismatches {} owned {} cells {} smaller {}\n", name, mismatches, owned, mesh.n_cells(), smaller);
}

}  // namespace

int main(int argc, char** argv) {
  const PetscSession session({argv[0]});
  open_failure_channel();
  try {
    const mesh::Mesh square = mesh::make_paper_square_mesh(12);
    // Degrees 1 to 4 from left to right: edges of the minimum rule's lower degree between them.
    std::vector<int> degrees(square.n_cells());
    for (int c = 0; c < square.n_cells(); ++c)
      degrees[c] = 1 + std::min(3, static_cast<int>(2.0 * (square.vertex(square.cell(c)[0])(0) + 1.0)));
    if (argc == 2 && std::string(argv[1]) == "bad") {
      degrees[7] = 0;
      check("bad", square, degrees);
      return 0;
    }
    check("square", square, degrees);
    const mesh::Mesh triangles = mesh::split_into_triangles(square);
    std::vector<int> triangle_degrees(triangles.n_cells());
    for (int c = 0; c < triangles.n_cells(); ++c)
      triangle_degrees[c] = 1 + std::min(4, static_cast<int>(2.5 * (triangles.vertex(triangles.cell(c)[0])(1) + 1.0)));
    check("triangles", triangles, triangle_degrees);
    return 0;
  } catch (const std::exception& error) {
    return testing::end_helper_on_failure(error);
  }
}
