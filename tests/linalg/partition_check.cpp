// Helper of distributed_factor_test, run under mpirun: partitions test meshes over the ranks by
// recursive coordinate bisection, by PT-Scotch on the dual graph (twice) and by the toolkit's
// choice of the two, each cell weighted by its unknowns at a degree per cell (uniform, or graded
// from 1 to 8 across the square "mixed_degrees"), and rank 0 prints per mesh and method the cut (edges
// and vertices shared between parts), the largest part's weight over the mean, the smallest part's cell count,
// whether every rank holds the same partition, whether a second call gave another one, and a hash
// of the parts (to compare two runs).
//
//   partition_check MESH_DIR     (MESH_DIR holds annulus_order2.msh)
#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <string>

#include "assembly/cell_system.hpp"
#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "mesh/cell_partition.hpp"
#include "mesh/gmsh_reader.hpp"
#include "mesh/graph_partition.hpp"
#include "mesh/point_grading.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "mesh/refine.hpp"
#include "space/h1_space.hpp"

using namespace hpcontact;

namespace {

// FNV-1a over the parts, in cell order: equal partitions in two processes print equal hashes (the
// number stays below 2^53, so the test reads it back exactly).
std::uint64_t parts_hash(const std::vector<int>& part_of_cell) {
  std::uint64_t hash = 1469598103934665603ull;
  for (int part : part_of_cell) hash = (hash ^ static_cast<std::uint64_t>(part)) * 1099511628211ull;
  return hash >> 12;
}

void report(const std::string& name, const std::string& method, const mesh::Mesh& mesh,
            const std::vector<int>& cell_weights, const std::vector<int>& part_of_cell, bool repeat_differs) {
  const int ranks = mpi_rank_and_size().second;
  std::vector<double> weight(ranks, 0.0);
  std::vector<int> cells(ranks, 0);
  int outside = 0;
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const int part = part_of_cell[c];
    if (part < 0 || part >= ranks) {
      ++outside;
      continue;
    }
    weight[part] += cell_weights[c], ++cells[part];
  }
  double total = 0.0;
  for (double w : weight) total += w;
  // Every rank must hold the same partition: compare with rank 0's.
  std::vector<int> first(part_of_cell);
  MPI_Bcast(first.data(), static_cast<int>(first.size()), MPI_INT, 0, MPI_COMM_WORLD);
  int differs = first != part_of_cell, any_differs = 0;
  MPI_Allreduce(&differs, &any_differs, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  const auto cut = mesh::partition_interface(mesh, part_of_cell);
  if (mpi_rank_and_size().first == 0)
    fmt::print(
        "{} {} cut_edges {} cut_vertices {} imbalance {:.4f} smallest_part {} outside {} ranks_differ {} "
        "repeat_differs {} parts_hash {}\n",
        name, method, cut.edges, cut.vertices, *std::max_element(weight.begin(), weight.end()) / (total / ranks),
        *std::min_element(cells.begin(), cells.end()), outside, any_differs, repeat_differs ? 1 : 0,
        parts_hash(part_of_cell));
}

// Each cell's unknowns in S^p(T_h) with `degree_of(cell)`, as the factorizations weigh it.
std::vector<int> unknowns_per_cell(const mesh::Mesh& mesh, const std::function<int(int)>& degree_of) {
  std::vector<int> degrees(mesh.n_cells());
  for (int c = 0; c < mesh.n_cells(); ++c) degrees[c] = degree_of(c);
  const space::H1Space space(mesh, degrees);
  return assembly::cell_work_weights(assembly::ScalarCellSystem(space, 1.0, 0.0));
}

// PT-Scotch's parts, computed from the first rank's mesh and sent to every rank.
std::vector<int> graph_parts_on_every_rank(const mesh::Mesh& mesh, const std::vector<int>& weights) {
  std::vector<int> parts = mesh::partition_cells_by_graph(&mesh, weights, MPI_COMM_WORLD);
  parts.resize(mesh.n_cells());
  MPI_Bcast(parts.data(), mesh.n_cells(), MPI_INT, 0, MPI_COMM_WORLD);
  return parts;
}

void compare(
    const std::string& name, const mesh::Mesh& mesh, const std::function<int(int)>& degree_of = [](int) { return 2; }) {
  const std::vector<int> weights = unknowns_per_cell(mesh, degree_of);
  report(name, "bisection", mesh, weights, mesh::bisect_cells(mesh, mpi_rank_and_size().second, weights), false);
  // Twice: a partition must be a function of the graph (K and A_G of one run share it).
  const std::vector<int> parts = graph_parts_on_every_rank(mesh, weights);
  report(name, "graph", mesh, weights, parts, graph_parts_on_every_rank(mesh, weights) != parts);
  report(name, "chosen", mesh, weights, mesh::split_cells_over_ranks(mesh, weights, MPI_COMM_WORLD), false);
}

}  // namespace

int main(int argc, char** argv) {
  const PetscSession session({argv[0]});
  try {
    if (argc != 2) throw_bad_input("partition_check", "arguments", std::to_string(argc - 1), "MESH_DIR");
    const mesh::Mesh square = mesh::make_paper_square_mesh(64);
    compare("square", square);
    // Degrees 1 to 8 from left to right: cells of equal size, work rising 20-fold across.
    compare("mixed_degrees", square, [&](int c) {
      return 1 + std::min(7, static_cast<int>(4.0 * (square.vertex(square.cell(c)[0])(0) + 1.0)));
    });
    // Graded towards two points of the bottom edge: small cells crowd where bisection cuts.
    const auto x = mesh::graded_nodes(-1.0, 1.0, 32, {-0.4, 0.3}, 0.3, 8, "partition_check");
    const auto y = mesh::graded_nodes(-1.0, 1.0, 32, {-1.0}, 0.3, 8, "partition_check");
    compare("graded", mesh::make_tensor_mesh(x, y, "partition_check"));
    compare("triangles", mesh::split_into_triangles(mesh::make_paper_square_mesh(48)));
    mesh::Mesh annulus = mesh::read_gmsh_mesh(std::string(argv[1]) + "/annulus_order2.msh");
    for (int k = 0; k < 3; ++k) annulus = mesh::refine_uniformly(annulus);
    compare("annulus", annulus);
    return 0;
  } catch (const std::exception& error) {
    if (mpi_rank_and_size().first == 0) fmt::print("error: {}\n", error.what());
    return 3;
  }
}
