// bisect_cells, bisect_solid_cells: recursive coordinate bisection on cell centroids; partition_interface: the edges
// and vertices shared between parts; split_cells_on_first_rank: the shorter cut of bisection and
// PT-Scotch.
#include "mesh/cell_partition.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "core/rank_agreement.hpp"
#include "mesh/graph_partition.hpp"

namespace hpcontact::mesh {

namespace {

// Assigns parts [first_part, first_part + parts) to cells[begin, end); planar or solid centroids.
template <class Centroid>
void bisect(const std::vector<Centroid>& centroids, const std::vector<int>& weight, std::vector<int>& cells, int begin,
            int end, int first_part, int parts, std::vector<int>& part_of_cell) {
  if (parts == 1 || end - begin <= 1) {
    for (int k = begin; k < end; ++k) part_of_cell[cells[k]] = first_part;
    return;
  }
  Centroid low = centroids[cells[begin]], high = low;
  for (int k = begin; k < end; ++k) low = low.cwiseMin(centroids[cells[k]]), high = high.cwiseMax(centroids[cells[k]]);
  int axis = 0;  // the longest side, the first on a tie
  for (int a = 1; a < static_cast<int>(low.size()); ++a)
    if ((high - low)(a) > (high - low)(axis)) axis = a;
  std::sort(cells.begin() + begin, cells.begin() + end, [&](int a, int b) {
    const double xa = centroids[a](axis), xb = centroids[b](axis);
    return xa < xb || (xa == xb && a < b);
  });
  // The left side takes the run of cells whose weight comes nearest its parts' share, the shorter
  // run on a tie (integer arithmetic: the same split on every process).
  const int left_parts = parts / 2;
  long long total = 0, left = 0;
  for (int k = begin; k < end; ++k) total += weight[cells[k]];
  const long long share = total * left_parts;  // the left side's weight, times parts
  int middle = begin;
  while (middle < end && (left + weight[cells[middle]]) * parts <= share) left += weight[cells[middle++]];
  if (middle < end && (left + weight[cells[middle]]) * parts - share < share - left * parts) ++middle;
  // Every part gets a cell while there are enough (a heavy cell must not leave a part empty).
  if (end - begin >= parts) middle = std::clamp(middle, begin + left_parts, end - (parts - left_parts));
  bisect(centroids, weight, cells, begin, middle, first_part, left_parts, part_of_cell);
  bisect(centroids, weight, cells, middle, end, first_part + left_parts, parts - left_parts, part_of_cell);
}

template <class Centroid>
std::vector<int> bisect_centroids(const std::vector<Centroid>& centroids, int parts,
                                  const std::vector<int>& cell_weights) {
  HPC_VERIFY(parts >= 1, "a partition needs at least one part");
  HPC_VERIFY(cell_weights.size() == centroids.size(), "one weight per cell");
  const int n = static_cast<int>(centroids.size());
  std::vector<int> cells(n);
  for (int c = 0; c < n; ++c) {
    HPC_VERIFY(cell_weights[c] > 0, "cell weights must be positive");
    cells[c] = c;
  }
  std::vector<int> part_of_cell(n, 0);
  bisect(centroids, cell_weights, cells, 0, n, 0, parts, part_of_cell);
  return part_of_cell;
}

}  // namespace

std::vector<int> bisect_cells(const Mesh& mesh, int parts, const std::vector<int>& cell_weights) {
  std::vector<Point> centroids(mesh.n_cells());
  for (int c = 0; c < mesh.n_cells(); ++c) {
    Point sum = Point::Zero();
    for (int v : mesh.cell(c)) sum += mesh.vertex(v);
    centroids[c] = sum / mesh.cell_size(c);
  }
  return bisect_centroids(centroids, parts, cell_weights);
}

std::vector<int> bisect_solid_cells(const SolidMesh& mesh, int parts, const std::vector<int>& cell_weights) {
  std::vector<SolidPoint> centroids(mesh.n_cells());
  for (int c = 0; c < mesh.n_cells(); ++c) {
    SolidPoint sum = SolidPoint::Zero();
    for (int v : mesh.cell_vertices(c)) sum += mesh.vertex(v);
    centroids[c] = sum / mesh.n_cell_vertices();
  }
  return bisect_centroids(centroids, parts, cell_weights);
}

PartitionInterface partition_interface(const Mesh& mesh, const std::vector<int>& part_of_cell) {
  PartitionInterface interface;
  // A vertex is shared if two of its cells lie in different parts: remember one part per vertex.
  std::vector<int> part_of_vertex(mesh.n_vertices(), -1);
  std::vector<char> shared(mesh.n_vertices(), 0);
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (int v : mesh.cell(c)) {
      if (part_of_vertex[v] < 0) part_of_vertex[v] = part_of_cell[c];
      if (part_of_vertex[v] != part_of_cell[c]) shared[v] = 1;
    }
  for (int v = 0; v < mesh.n_vertices(); ++v) interface.vertices += shared[v];
  for (int e = 0; e < mesh.n_edges(); ++e) {
    const auto& cells = mesh.edge_cells(e);
    if (cells[1] >= 0 && part_of_cell[cells[0]] != part_of_cell[cells[1]]) ++interface.edges;
  }
  return interface;
}

std::vector<int> split_cells_on_first_rank(const Mesh* mesh, const std::vector<int>& cell_weights, MPI_Comm ranks) {
  std::vector<int> graph = partition_cells_by_graph(mesh, cell_weights, ranks);  // collective: every rank calls it
  // The first rank bisects and compares alone; a failure there (memory) ends every rank alike.
  const bool first = rank_and_size(ranks).first == 0;
  run_on_all_ranks_agreeing(
      [&] {
        if (!first) return;
        std::vector<int> bisection = bisect_cells(*mesh, rank_and_size(ranks).second, cell_weights);
        if (partition_interface(*mesh, bisection).edges <= partition_interface(*mesh, graph).edges)
          graph = std::move(bisection);
      },
      ranks);
  return graph;
}

std::vector<int> split_cells_over_ranks(const Mesh& mesh, const std::vector<int>& cell_weights, MPI_Comm ranks) {
  std::vector<int> parts = split_cells_on_first_rank(&mesh, cell_weights, ranks);
  parts.resize(mesh.n_cells());
  HPC_VERIFY(MPI_Bcast(parts.data(), mesh.n_cells(), MPI_INT, 0, ranks) == MPI_SUCCESS, "broadcast of the parts");
  return parts;
}

}  // namespace hpcontact::mesh
