// Helper of test_07_distributed_factor, run under mpirun: partitions test meshes over the ranks by
// recursive coordinate bisection (the baseline) and by PT-Scotch on the dual graph, and rank 0 prints, per mesh and
// method, the cut (edges and vertices shared between parts), the largest part's weight over the mean, the smallest
// part's cell count, and whether every rank holds the same partition.
//
//   partition_check MESH_DIR     (MESH_DIR holds annulus_order2.msh)
#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <string>

#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "mesh/gmsh_reader.hpp"
#include "mesh/graph_partition.hpp"
#include "mesh/point_grading.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "mesh/refine.hpp"

using namespace hpcontact;

namespace {

// Assigns parts [first_part, first_part + parts) to cells[begin, end).
void bisect(const std::vector<mesh::Point>& centroids, std::vector<int>& cells, int begin, int end, int first_part,
            int parts, std::vector<int>& part_of_cell) {
  if (parts == 1 || end - begin <= 1) {
    for (int k = begin; k < end; ++k) part_of_cell[cells[k]] = first_part;
    return;
  }
  mesh::Point low = centroids[cells[begin]], high = low;
  for (int k = begin; k < end; ++k) low = low.cwiseMin(centroids[cells[k]]), high = high.cwiseMax(centroids[cells[k]]);
  const int axis = (high - low)(0) >= (high - low)(1) ? 0 : 1;
  const int left_parts = parts / 2;
  const int middle = begin + static_cast<int>(static_cast<long long>(end - begin) * left_parts / parts);
  std::nth_element(cells.begin() + begin, cells.begin() + middle, cells.begin() + end, [&](int a, int b) {
    const double xa = centroids[a](axis), xb = centroids[b](axis);
    return xa < xb || (xa == xb && a < b);
  });
  bisect(centroids, cells, begin, middle, first_part, left_parts, part_of_cell);
  bisect(centroids, cells, middle, end, first_part + left_parts, parts - left_parts, part_of_cell);
}

// The baseline: recursive coordinate bisection of the cell centroids (the partition the toolkit used
// before PT-Scotch), each split at the median along the longer side of the bounding box.
std::vector<int> bisect_cells(const mesh::Mesh& mesh, int parts) {
  HPC_VERIFY(parts >= 1, "a partition needs at least one part");
  std::vector<mesh::Point> centroids(mesh.n_cells());
  std::vector<int> cells(mesh.n_cells());
  for (int c = 0; c < mesh.n_cells(); ++c) {
    mesh::Point sum = mesh::Point::Zero();
    for (int v : mesh.cell(c)) sum += mesh.vertex(v);
    centroids[c] = sum / mesh.cell_size(c);
    cells[c] = c;
  }
  std::vector<int> part_of_cell(mesh.n_cells(), 0);
  bisect(centroids, cells, 0, mesh.n_cells(), 0, parts, part_of_cell);
  return part_of_cell;
}

void report(const std::string& name, const std::string& method, const mesh::Mesh& mesh,
            const std::vector<int>& part_of_cell, bool repeat_differs) {
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
    weight[part] += mesh.cell_size(c), ++cells[part];
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
        "repeat_differs {}\n",
        name, method, cut.edges, cut.vertices, *std::max_element(weight.begin(), weight.end()) / (total / ranks),
        *std::min_element(cells.begin(), cells.end()), outside, any_differs, repeat_differs ? 1 : 0);
}

void compare(const std::string& name, const mesh::Mesh& mesh) {
  report(name, "bisection", mesh, bisect_cells(mesh, mpi_rank_and_size().second), false);
  // Twice: a partition must be a function of the graph (K and A_G of one run share it).
  const std::vector<int> parts = mesh::partition_cells_by_graph(mesh);
  report(name, "graph", mesh, parts, mesh::partition_cells_by_graph(mesh) != parts);
}

}  // namespace

int main(int argc, char** argv) {
  const PetscSession session({argv[0]});
  try {
    if (argc != 2) throw_bad_input("partition_check", "arguments", std::to_string(argc - 1), "MESH_DIR");
    compare("square", mesh::make_paper_square_mesh(64));
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
